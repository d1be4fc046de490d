// Reading koppel's SVG pictures back in the tests with an XML parser (pugixml), never by string
// search: panels, axes and their px <-> data mapping from the tick marks and their labels,
// curves as subpaths of points, markers, and the transforms of the scheme's link groups.
#pragma once

#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <pugixml.hpp>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace koppel::test {

inline pugi::xml_document ParseSvg(const std::string& text) {
  pugi::xml_document doc;
  const pugi::xml_parse_result r = doc.load_string(text.c_str());
  INFO(r.description());
  REQUIRE(r);
  REQUIRE(std::string(doc.document_element().name()) == "svg");
  return doc;
}

inline bool HasClass(const pugi::xml_node& n, const std::string& cls) {
  std::istringstream in(n.attribute("class").as_string());
  std::string word;
  while (in >> word)
    if (word == cls) return true;
  return false;
}

// Every descendant element of `root` (itself excluded) with tag `tag` ("" any) and class `cls` ("" any).
inline std::vector<pugi::xml_node> Find(const pugi::xml_node& root, const std::string& tag, const std::string& cls) {
  std::vector<pugi::xml_node> out;
  struct Walker : pugi::xml_tree_walker {
    std::string tag, cls;
    std::vector<pugi::xml_node>* out;
    bool for_each(pugi::xml_node& n) override {
      if (n.type() == pugi::node_element && (tag.empty() || tag == n.name()) && (cls.empty() || HasClass(n, cls))) out->push_back(n);
      return true;
    }
  } walker;
  walker.tag = tag;
  walker.cls = cls;
  walker.out = &out;
  pugi::xml_node copy = root;
  copy.traverse(walker);
  return out;
}

// An axis of a panel: the data value at a px coordinate from two of its labelled ticks.
struct AxisMap {
  double px0 = 0, value0 = 0, px1 = 1, value1 = 1;  // two ticks
  double data_min = 0, data_max = 0;                 // the axis' range (data-min/max)
  std::vector<double> tick_values;                   // from the tick labels' text
  double ToData(double px) const { return value0 + (px - px0) * (value1 - value0) / (px1 - px0); }
  double ToPx(double v) const { return px0 + (v - value0) * (px1 - px0) / (value1 - value0); }
};

// The axis "x" or "y" of a panel: ticks (<line class="tick">) paired with their labels' text.
inline AxisMap ReadAxis(const pugi::xml_node& panel, const std::string& which) {
  AxisMap a;
  pugi::xml_node axis;
  for (const auto& g : Find(panel, "g", "axis"))
    if (HasClass(g, which)) axis = g;
  REQUIRE(axis);
  a.data_min = axis.attribute("data-min").as_double();
  a.data_max = axis.attribute("data-max").as_double();
  const auto ticks = Find(axis, "line", "tick");
  const auto labels = Find(axis, "text", "tick-label");
  REQUIRE(ticks.size() == labels.size());
  REQUIRE(ticks.size() >= 2);
  for (const auto& l : labels) a.tick_values.push_back(std::strtod(l.child_value(), nullptr));
  auto px = [&](const pugi::xml_node& t) { return which == "x" ? t.attribute("x1").as_double() : t.attribute("y1").as_double(); };
  a.px0 = px(ticks.front());
  a.value0 = a.tick_values.front();
  a.px1 = px(ticks.back());
  a.value1 = a.tick_values.back();
  return a;
}

// The points of a path's "d" (M/L only), one vector per subpath.
inline std::vector<std::vector<Eigen::Vector2d>> Subpaths(const pugi::xml_node& path) {
  std::vector<std::vector<Eigen::Vector2d>> runs;
  const std::string d = path.attribute("d").as_string();
  size_t i = 0;
  while (i < d.size()) {
    const char c = d[i];
    if (c == 'M' || c == 'L') {
      if (c == 'M') runs.emplace_back();
      char* end = nullptr;
      const double x = std::strtod(d.c_str() + i + 1, &end);
      REQUIRE(*end == ',');
      const double y = std::strtod(end + 1, &end);
      REQUIRE(!runs.empty());
      runs.back().emplace_back(x, y);
      i = static_cast<size_t>(end - d.c_str());
    } else {
      ++i;
    }
  }
  return runs;
}

// "matrix(a b c d e f)" -> the 2x3 affine map.
inline Eigen::Matrix<double, 2, 3> ParseMatrix(const std::string& transform) {
  REQUIRE(transform.rfind("matrix(", 0) == 0);
  std::istringstream in(transform.substr(7));
  double a, b, c, d, e, f;
  in >> a >> b >> c >> d >> e >> f;
  Eigen::Matrix<double, 2, 3> m;
  m << a, c, e, b, d, f;
  return m;
}

inline Eigen::Vector2d Apply(const Eigen::Matrix<double, 2, 3>& m, const Eigen::Vector2d& p) {
  return m.leftCols<2>() * p + m.col(2);
}

}  // namespace koppel::test
