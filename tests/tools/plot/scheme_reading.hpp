// Reading koppel's kinematic scheme back (scheme.hpp) with pugixml: where the joint circles
// and the other point symbols are, the point labels with the points they name, and the check of
// issue 22 item 15 that the labels are legible. Shared by the picture's own tests and the
// command's (`koppel draw`).
#pragma once

#include "tools/plot/svg_reading.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace koppel::test {

// Where the scheme put each joint circle, in px: the circle's centre through its group's transform.
inline std::map<std::string, Eigen::Vector2d> JointCircles(const pugi::xml_document& doc) {
  std::map<std::string, Eigen::Vector2d> at;
  for (const auto& group : Find(doc, "g", "joints"))
    for (const auto& c : Find(group, "circle", "joint"))
      at[c.attribute("data-joint").as_string()] =
          Apply(ParseMatrix(group.attribute("transform").as_string()),
                      {c.attribute("cx").as_double(), c.attribute("cy").as_double()});
  return at;
}

// A label as a reader measures it: the text, the point it names (data-x, data-y) and its extent
// estimated from the font size of the scheme's style sheet (13 px; 12 px in an overlay) and the
// number of characters: 0.6 em a character (DejaVu Sans' mean advance), ink 0.75 em above the
// baseline and 0.2 em below (an underscore).
struct ReadLabel {
  std::string name, text;
  Eigen::Vector2d anchor, low, high;  // the point; the extent's corners (px)
  bool overlay = false;
  double Distance(const Eigen::Vector2d& p) const { return (p - p.cwiseMax(low).cwiseMin(high)).norm(); }
};

inline std::vector<ReadLabel> ReadLabels(const pugi::xml_document& doc) {
  std::vector<ReadLabel> labels;
  for (const char* group : {"labels", "overlay-labels"})
    for (const auto& g : Find(doc, "g", group))
      for (const auto& t : g.children("text")) {
        ReadLabel l;
        l.overlay = std::string(group) == "overlay-labels";
        l.name = t.attribute("data-point").as_string();
        l.text = t.child_value();
        l.anchor = {t.attribute("data-x").as_double(), t.attribute("data-y").as_double()};
        const double font = l.overlay ? 12 : 13, x = t.attribute("x").as_double(), y = t.attribute("y").as_double();
        size_t characters = 0;
        for (unsigned char c : l.text) characters += (c & 0xC0) != 0x80;
        l.low = {x, y - 0.75 * font};
        l.high = {x + 0.6 * font * characters, y + 0.2 * font};
        labels.push_back(l);
      }
  return labels;
}

// Where the scheme shows a point with a symbol (px): joint circles, blocks, the dots of points
// without a joint, the small circles of the overlays.
inline std::vector<Eigen::Vector2d> PointSymbols(const pugi::xml_document& doc) {
  std::vector<Eigen::Vector2d> at;
  for (const auto& [name, p] : JointCircles(doc)) at.push_back(p);
  auto centre = [](const pugi::xml_node& c) { return Eigen::Vector2d(c.attribute("cx").as_double(), c.attribute("cy").as_double()); };
  for (const auto& g : Find(doc, "g", "")) {
    const std::string transform = g.attribute("transform").as_string();
    const bool moving = !transform.empty();
    for (const auto& c : g.children("circle"))
      if (HasClass(c, "point-mark") || HasClass(g, "overlay"))
        at.push_back(moving ? Apply(ParseMatrix(transform), centre(c)) : centre(c));
    for (const auto& block : g.children("polygon")) {
      if (!HasClass(block, "block")) continue;
      std::istringstream in(block.attribute("points").as_string());
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      double x, y;
      char comma;
      for (int i = 0; i < 4 && in >> x >> comma >> y; ++i) sum += Eigen::Vector2d(x, y) / 4;
      at.push_back(Apply(ParseMatrix(transform), sum));
    }
  }
  return at;
}

// Issue 22 item 15: no label covers another, each names a point that a symbol shows, and each
// sits by its point (the nearest ring: 7 px) or has a leader line from the point to the text.
inline void CheckLabelsLegible(const pugi::xml_document& doc) {
  constexpr double kNearestRing = 12;  // 7 px up and right of the point, less the text's descent
  constexpr double kOnSymbol = 0.5;    // px: a symbol at the labelled point
  constexpr double kLeaderReach = 4;   // px: a leader ends at the text (whose extent is estimated)
  const std::vector<ReadLabel> labels = ReadLabels(doc);
  REQUIRE(!labels.empty());
  for (size_t i = 0; i < labels.size(); ++i)
    for (size_t j = i + 1; j < labels.size(); ++j) {
      const ReadLabel &a = labels[i], &b = labels[j];
      INFO(a.text << " and " << b.text);
      CHECK_FALSE((a.low.array() < b.high.array()).all() & (b.low.array() < a.high.array()).all());
    }
  const std::vector<Eigen::Vector2d> symbols = PointSymbols(doc);
  const auto leaders = Find(doc, "line", "leader");
  for (const ReadLabel& l : labels) {
    INFO(l.text << " at (" << l.anchor.transpose() << ")");
    double nearest = 1e300;
    for (const Eigen::Vector2d& s : symbols) nearest = std::min(nearest, (s - l.anchor).norm());
    CHECK(nearest < kOnSymbol);
    bool led = false;
    for (const auto& line : leaders) {
      const Eigen::Vector2d from(line.attribute("x1").as_double(), line.attribute("y1").as_double()),
          to(line.attribute("x2").as_double(), line.attribute("y2").as_double());
      led |= line.attribute("data-point").as_string() == l.name && (from - l.anchor).norm() < 7 && l.Distance(to) < kLeaderReach;
    }
    CHECK((l.Distance(l.anchor) < kNearestRing || led));
  }
}

}  // namespace koppel::test
