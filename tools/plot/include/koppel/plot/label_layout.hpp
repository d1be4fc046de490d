// Placing point labels so that none covers another label or a symbol: each label tries places
// around its point, the nearest ring first (above right, above left, below right, below left,
// then right, left, above, below), and rings farther out; a label placed beyond the nearest ring
// gets a leader line to its point (PlacedLabel::leader). Text extents are estimated from the
// font size and the number of characters (DejaVu Sans, generously: no renderer is asked). px,
// y down.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel::plot {

struct LabelBox {
  double left = 0, top = 0, right = 0, bottom = 0;
  bool Overlaps(const LabelBox& other) const;
  double OverlapArea(const LabelBox& other) const;
  bool Contains(const LabelBox& inner) const;
  // The point of the box nearest p (p itself when inside).
  Eigen::Vector2d Nearest(const Eigen::Vector2d& p) const;
  bool Crosses(const Eigen::Vector2d& from, const Eigen::Vector2d& to) const;  // the segment meets the box
};

// The box a text takes with its baseline starting at `at` (text-anchor start): every glyph's
// ink, underscores included, with a pixel to spare.
LabelBox TextBox(const std::string& text, double font_size, const Eigen::Vector2d& at);

struct LabelRequest {
  std::string text;
  Eigen::Vector2d anchor = Eigen::Vector2d::Zero();  // the labelled point, px
  double font_size = 12;
};

struct PlacedLabel {
  Eigen::Vector2d baseline = Eigen::Vector2d::Zero();  // where the text starts (text-anchor start)
  LabelBox box;          // the generous extent the layout keeps free
  LabelBox ink;          // the likely extent of the glyphs (0.58 em a character): where a leader ends
  bool leader = false;   // placed beyond the nearest ring: draw a line from the anchor to `ink`
};

struct LabelScene {
  LabelBox area;                             // labels stay inside
  std::vector<LabelBox> symbols;             // joints, pivots, marks, other text: never covered
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> lines;  // links and guides: avoided if possible
  int rings = 4;                             // 1: the nearest ring only (no leaders)
};

// Labels placed in the order given (earlier ones have the better places). A label that finds no
// free place takes the one that covers least.
std::vector<PlacedLabel> PlaceLabels(const std::vector<LabelRequest>& labels, const LabelScene& scene);

}  // namespace koppel::plot
