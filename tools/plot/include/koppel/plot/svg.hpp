// The one SVG writer of koppel's pictures: elements with escaped attributes and numbers in a
// fixed, short format. Coordinates are SVG user units (pixels, y down); the callers map data or
// world coordinates (y up) to them. No layout here: see figure.hpp and scheme.hpp.
#pragma once

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace koppel::plot {

// One attribute; values are escaped when written.
struct Attr {
  std::string name, value;
};
using Attrs = std::vector<Attr>;

// A number as SVG text: at most `decimals` decimals, trailing zeros dropped, never "-0", never
// NaN or infinity (a bug upstream: throws std::logic_error).
std::string Num(double value, int decimals = 2);

// Text with &, <, >, " and ' escaped for XML, and every character XML 1.0 forbids (a control
// character but tab, line feed and carriage return; U+FFFE, U+FFFF; a byte that is not UTF-8)
// written as U+FFFD, so that the file stays well-formed whatever a name holds (the file reader
// refuses such names; the API and the Python module may pass one). C1 and DEL, which XML allows
// but no picture shows, become U+FFFD too (koppel/core/printable_text.hpp).
std::string EscapeXml(const std::string& text);

class Svg {
 public:
  Svg(double width, double height);

  double width() const { return width_; }
  double height() const { return height_; }

  // <g ...>; every OpenGroup needs its CloseGroup.
  void OpenGroup(const Attrs& attrs);
  void CloseGroup();
  void Line(Eigen::Vector2d from, Eigen::Vector2d to, const Attrs& attrs);
  void Rect(double x, double y, double w, double h, const Attrs& attrs);
  void Circle(Eigen::Vector2d centre, double radius, const Attrs& attrs);
  void Polygon(const std::vector<Eigen::Vector2d>& corners, const Attrs& attrs);
  // One <path>: each run is a subpath (M ... L ...), so gaps between runs stay gaps.
  void Path(const std::vector<std::vector<Eigen::Vector2d>>& runs, const Attrs& attrs);
  // A raw path description (arcs, arrow heads), d as given.
  void PathData(const std::string& d, const Attrs& attrs);
  void Text(Eigen::Vector2d at, const std::string& text, const Attrs& attrs);
  // <defs> content (patterns, markers), written once before the drawing.
  void Defs(const std::string& raw_xml);

  // The document; throws std::logic_error when groups are unbalanced.
  std::string Finish(const Attrs& root_attrs = {}) const;

 private:
  void Element(const char* tag, const Attrs& geometry, const Attrs& attrs, const std::string* text = nullptr);
  double width_, height_;
  std::string defs_, body_;
  int depth_ = 0;
};

}  // namespace koppel::plot
