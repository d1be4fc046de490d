#include "koppel/plot/svg.hpp"

#include "koppel/core/printable_text.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace koppel::plot {

std::string Num(double value, int decimals) {
  if (!std::isfinite(value)) throw std::logic_error("koppel::plot::Num: non-finite coordinate");
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  std::string s = buffer;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

std::string EscapeXml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : PrintableText(text, Replacement::kReplacementCharacter, "\t\n\r")) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

Svg::Svg(double width, double height) : width_(width), height_(height) {}

void Svg::Element(const char* tag, const Attrs& geometry, const Attrs& attrs, const std::string* text) {
  body_.append(depth_ + 1, ' ').append("<").append(tag);
  for (const Attrs* list : {&geometry, &attrs})
    for (const Attr& a : *list) body_.append(" ").append(a.name).append("=\"").append(EscapeXml(a.value)).append("\"");
  if (text)
    body_.append(">").append(EscapeXml(*text)).append("</").append(tag).append(">\n");
  else
    body_.append("/>\n");
}

void Svg::OpenGroup(const Attrs& attrs) {
  body_ += std::string(depth_ + 1, ' ') + "<g";
  for (const Attr& a : attrs) body_.append(" ").append(a.name).append("=\"").append(EscapeXml(a.value)).append("\"");
  body_ += ">\n";
  ++depth_;
}

void Svg::CloseGroup() {
  if (depth_ == 0) throw std::logic_error("koppel::plot::Svg: CloseGroup without OpenGroup");
  --depth_;
  body_ += std::string(depth_ + 1, ' ') + "</g>\n";
}

void Svg::Line(Eigen::Vector2d from, Eigen::Vector2d to, const Attrs& attrs) {
  Element("line", {{"x1", Num(from.x())}, {"y1", Num(from.y())}, {"x2", Num(to.x())}, {"y2", Num(to.y())}}, attrs);
}

void Svg::Rect(double x, double y, double w, double h, const Attrs& attrs) {
  Element("rect", {{"x", Num(x)}, {"y", Num(y)}, {"width", Num(w)}, {"height", Num(h)}}, attrs);
}

void Svg::Circle(Eigen::Vector2d centre, double radius, const Attrs& attrs) {
  Element("circle", {{"cx", Num(centre.x())}, {"cy", Num(centre.y())}, {"r", Num(radius)}}, attrs);
}

void Svg::Polygon(const std::vector<Eigen::Vector2d>& corners, const Attrs& attrs) {
  std::string points;
  for (const auto& p : corners) points.append(points.empty() ? "" : " ").append(Num(p.x())).append(",").append(Num(p.y()));
  Element("polygon", {{"points", points}}, attrs);
}

void Svg::Path(const std::vector<std::vector<Eigen::Vector2d>>& runs, const Attrs& attrs) {
  std::string d;
  for (const auto& run : runs) {
    for (size_t i = 0; i < run.size(); ++i)
      d.append(d.empty() ? "" : " ").append(i == 0 ? "M" : "L").append(Num(run[i].x())).append(",").append(Num(run[i].y()));
  }
  Element("path", {{"d", d}}, attrs);
}

void Svg::PathData(const std::string& d, const Attrs& attrs) { Element("path", {{"d", d}}, attrs); }

void Svg::Text(Eigen::Vector2d at, const std::string& text, const Attrs& attrs) {
  Element("text", {{"x", Num(at.x())}, {"y", Num(at.y())}}, attrs, &text);
}

void Svg::Defs(const std::string& raw_xml) { defs_ += raw_xml; }

std::string Svg::Finish(const Attrs& root_attrs) const {
  if (depth_ != 0) throw std::logic_error("koppel::plot::Svg: unclosed group");
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + Num(width_) + "\" height=\"" + Num(height_) +
                    "\" viewBox=\"0 0 " + Num(width_) + " " + Num(height_) + "\"";
  for (const Attr& a : root_attrs) out += " " + a.name + "=\"" + EscapeXml(a.value) + "\"";
  out += ">\n";
  if (!defs_.empty()) out += " <defs>" + defs_ + "</defs>\n";
  return out + body_ + "</svg>\n";
}

}  // namespace koppel::plot
