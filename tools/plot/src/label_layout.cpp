#include "koppel/plot/label_layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace koppel::plot {
namespace {

// DejaVu Sans: capitals and digits advance 0.60..0.77 em, lower case 0.28..0.98 (m, w); 0.7 em a
// character over-covers every label of a point name with a suffix. Ink from 0.8 em above the
// baseline (capitals, subscript-free) to 0.28 em below (the underscore of a suffix).
constexpr double kEmPerCharacter = 0.7, kAscent = 0.8, kDescent = 0.28, kSpare = 1;
// The glyphs' likely extent, for ending a leader at the text rather than at the kept space:
// DejaVu Sans' mean advance and cap height.
constexpr double kInkEmPerCharacter = 0.58, kInkAscent = 0.72;
// The gap between a point and its label's box, per ring, px: the first is the usual offset of a
// point label; the next rings step out by about a line height.
constexpr std::array<double, 6> kRingGaps = {7, 17, 29, 43, 59, 77};

int Characters(const std::string& utf8) {
  // count code points: every byte that does not continue a multi-byte sequence
  return static_cast<int>(std::count_if(utf8.begin(), utf8.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

// The baseline start of a text whose glyphs (`ink` px wide) sit `gap` px from the anchor in
// direction `place` (0..3 the diagonals NE, NW, SE, SW; 4..7 E, W, N, S).
Eigen::Vector2d Baseline(const Eigen::Vector2d& anchor, int place, double gap, double ink, double size) {
  const double ascent = kAscent * size, descent = kDescent * size;
  switch (place) {
    case 0: return anchor + Eigen::Vector2d(gap, -gap);
    case 1: return anchor + Eigen::Vector2d(-gap - ink, -gap);
    case 2: return anchor + Eigen::Vector2d(gap, gap + ascent);
    case 3: return anchor + Eigen::Vector2d(-gap - ink, gap + ascent);
    case 4: return anchor + Eigen::Vector2d(gap + 2, 0.5 * (ascent - descent));
    case 5: return anchor + Eigen::Vector2d(-gap - 2 - ink, 0.5 * (ascent - descent));
    case 6: return anchor + Eigen::Vector2d(-0.5 * ink, -gap - 2 - descent);
    default: return anchor + Eigen::Vector2d(-0.5 * ink, gap + 2 + ascent);
  }
}

// The generous extent of a text placed at `place`: it grows away from the anchor, so that the
// glyphs keep their gap to the point whatever their true width.
LabelBox KeptBox(const std::string& text, double size, const Eigen::Vector2d& at, int place) {
  LabelBox box = TextBox(text, size, at);
  const double ink = kInkEmPerCharacter * size * Characters(text), spare = box.right - box.left - ink;
  const double shift = place == 1 || place == 3 || place == 5 ? spare : place >= 6 ? 0.5 * spare : 0.0;
  box.left -= shift;
  box.right -= shift;
  return box;
}

struct Cost {
  double covered = 0;  // px² of labels and symbols covered, and outside the area
  int crossings = 0;   // lines through the box
  bool operator<(const Cost& o) const { return covered < o.covered || (covered == o.covered && crossings < o.crossings); }
};

Cost CostOf(const LabelBox& box, const std::vector<LabelBox>& taken, const LabelScene& scene) {
  Cost cost;
  for (const LabelBox& t : taken) cost.covered += t.OverlapArea(box);
  for (const LabelBox& s : scene.symbols) cost.covered += s.OverlapArea(box);
  const double area = (box.right - box.left) * (box.bottom - box.top);
  cost.covered += area - scene.area.OverlapArea(box);
  for (const auto& [from, to] : scene.lines) cost.crossings += box.Crosses(from, to) ? 1 : 0;
  return cost;
}

}  // namespace

bool LabelBox::Overlaps(const LabelBox& o) const { return left < o.right && o.left < right && top < o.bottom && o.top < bottom; }

double LabelBox::OverlapArea(const LabelBox& o) const {
  const double w = std::min(right, o.right) - std::max(left, o.left), h = std::min(bottom, o.bottom) - std::max(top, o.top);
  return w > 0 && h > 0 ? w * h : 0.0;
}

bool LabelBox::Contains(const LabelBox& inner) const {
  return inner.left >= left && inner.right <= right && inner.top >= top && inner.bottom <= bottom;
}

Eigen::Vector2d LabelBox::Nearest(const Eigen::Vector2d& p) const {
  return {std::clamp(p.x(), left, right), std::clamp(p.y(), top, bottom)};
}

bool LabelBox::Crosses(const Eigen::Vector2d& from, const Eigen::Vector2d& to) const {
  // Liang–Barsky: clip the segment's parameter range against the four sides
  double t0 = 0, t1 = 1;
  const Eigen::Vector2d d = to - from;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {from.x() - left, right - from.x(), from.y() - top, bottom - from.y()};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  return true;
}

LabelBox TextBox(const std::string& text, double font_size, const Eigen::Vector2d& at) {
  const double width = kEmPerCharacter * font_size * Characters(text);
  return {at.x() - kSpare, at.y() - kAscent * font_size - kSpare, at.x() + width + kSpare, at.y() + kDescent * font_size + kSpare};
}

std::vector<PlacedLabel> PlaceLabels(const std::vector<LabelRequest>& labels, const LabelScene& scene) {
  std::vector<PlacedLabel> placed;
  std::vector<LabelBox> taken;
  const int rings = std::clamp(scene.rings, 1, static_cast<int>(kRingGaps.size()));
  for (const LabelRequest& label : labels) {
    const double ink_width = kInkEmPerCharacter * label.font_size * Characters(label.text);
    // the first place that covers nothing and crosses no line; else the first that covers
    // nothing; else the one that covers least
    PlacedLabel best;
    Cost best_cost{std::numeric_limits<double>::infinity(), 0};
    bool settled = false;
    for (int ring = 0; ring < rings && !settled; ++ring) {
      for (int place = 0; place < 8 && !settled; ++place) {
        const Eigen::Vector2d at = Baseline(label.anchor, place, kRingGaps[ring], ink_width, label.font_size);
        const LabelBox box = KeptBox(label.text, label.font_size, at, place);
        const Cost cost = CostOf(box, taken, scene);
        const bool free = cost.covered == 0;
        if (free && cost.crossings == 0) settled = true;
        // a free place beats any covering one; among free places the first with fewest crossings
        if (cost < best_cost || settled) {
          best_cost = cost;
          const LabelBox ink{at.x(), at.y() - kInkAscent * label.font_size, at.x() + ink_width, at.y()};
          best = {at, box, ink, ring > 0};
        }
      }
    }
    taken.push_back(best.box);
    placed.push_back(best);
  }
  return placed;
}

}  // namespace koppel::plot
