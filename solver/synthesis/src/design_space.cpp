#include "koppel/synthesis/design_space.hpp"

#include "koppel/core/angles.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace koppel {
namespace {

bool FiniteInterval(const std::optional<std::pair<double, double>>& range) {
  return !range || (std::isfinite(range->first) && std::isfinite(range->second) && range->first <= range->second);
}

}  // namespace

bool DesignSpace::IsValid(std::string* why) const {
  std::string problem;
  if (!FiniteInterval(lengths)) problem = "lengths: [min, max] must be finite with min <= max";
  else if (lengths && lengths->second <= 0) problem = "lengths: the largest length must be positive";
  else if (ratio && !(std::isfinite(*ratio) && *ratio >= 1)) problem = "ratio: the longest link over the shortest is at least 1";
  else if (!FiniteInterval(pivots_x) || !FiniteInterval(pivots_y)) problem = "pivots: each of x and y must be [min, max], finite, min <= max";
  else if (a0 && !a0->allFinite()) problem = "A0: [x, y] must be finite";
  else if (frame_angle && !std::isfinite(*frame_angle)) problem = "frame_angle must be finite";
  else if (!FiniteInterval(coupler_point)) problem = "coupler_point: [min, max] must be finite with min <= max";
  else if (mu_min && !(*mu_min >= 0 && *mu_min < kPi / 2)) problem = "mu_min: a transmission angle from 0 to below 90 deg";
  else if (a0 && pivots_x && (a0->x() < pivots_x->first || a0->x() > pivots_x->second)) problem = "A0 lies outside pivots.x";
  else if (a0 && pivots_y && (a0->y() < pivots_y->first || a0->y() > pivots_y->second)) problem = "A0 lies outside pivots.y";
  if (why) *why = problem;
  return problem.empty();
}

std::string DesignSpace::Unsupported(const std::string& what, bool with_coupler_point, bool fixed_frame) const {
  if (coupler_point && !with_coupler_point) return "coupler_point: " + what + " designs no coupler point";
  if ((a0 || frame_angle) && !fixed_frame)
    return std::string(a0 ? "A0" : "frame_angle") + ": " + what + " places its frame itself (synth path's global search holds it fixed)";
  return "";
}

std::string DesignSpace::Violation(const FourBarSizes& s) const {
  const double frame = (s.b0 - s.a0).norm();
  const std::array<std::pair<const char*, double>, 4> links = {{{"crank", s.crank}, {"coupler", s.coupler}, {"rocker", s.rocker}, {"frame", frame}}};
  if (lengths) {
    for (const auto& [name, length] : links) {
      if (length < lengths->first) return fmt::format("lengths: the {} is {:.6g}, below {:.6g}", name, length, lengths->first);
      if (length > lengths->second) return fmt::format("lengths: the {} is {:.6g}, beyond {:.6g}", name, length, lengths->second);
    }
  }
  const auto [shortest, longest] = std::minmax_element(links.begin(), links.end(), [](const auto& x, const auto& y) { return x.second < y.second; });
  if (ratio && longest->second > *ratio * shortest->second)
    return fmt::format("ratio: the {} ({:.6g}) is {:.4g} times the {} ({:.6g}), more than {:.6g}", longest->first, longest->second,
                       longest->second / shortest->second, shortest->first, shortest->second, *ratio);
  for (const auto& [name, p] : {std::pair<const char*, Eigen::Vector2d>{"A0", s.a0}, {"B0", s.b0}}) {
    if (pivots_x && (p.x() < pivots_x->first || p.x() > pivots_x->second))
      return fmt::format("pivots: {} at x = {:.6g}, outside [{:.6g}, {:.6g}]", name, p.x(), pivots_x->first, pivots_x->second);
    if (pivots_y && (p.y() < pivots_y->first || p.y() > pivots_y->second))
      return fmt::format("pivots: {} at y = {:.6g}, outside [{:.6g}, {:.6g}]", name, p.y(), pivots_y->first, pivots_y->second);
  }
  const double size = std::max(longest->second, 1e-300);
  if (a0 && (s.a0 - *a0).norm() > kFixedTolerance * size)
    return fmt::format("A0: at ({:.6g}, {:.6g}), not at the fixed ({:.6g}, {:.6g})", s.a0.x(), s.a0.y(), a0->x(), a0->y());
  if (frame_angle) {
    const Eigen::Vector2d along = s.b0 - s.a0;
    const double off = std::abs(std::remainder(std::atan2(along.y(), along.x()) - *frame_angle, 2 * kPi));
    if (off * frame > kFixedTolerance * size)
      return fmt::format("frame_angle: the frame line A0 -> B0 is at {:.6g} deg, not at the fixed {:.6g} deg", RadToDeg(std::atan2(along.y(), along.x())),
                         RadToDeg(*frame_angle));
  }
  if (coupler_point && s.coupler_point)
    for (const auto& [name, v] : {std::pair<const char*, double>{"along A -> B", s.coupler_point->x()}, {"left of A -> B", s.coupler_point->y()}})
      if (v < coupler_point->first || v > coupler_point->second)
        return fmt::format("coupler_point: K lies {:.6g} {}, outside [{:.6g}, {:.6g}]", v, name, coupler_point->first, coupler_point->second);
  // the solver's least transmission angle of a design the search held at the bound: its roundoff
  if (mu_min && s.mu_min && *s.mu_min < *mu_min - kFixedTolerance)
    return fmt::format("mu_min: the smallest transmission angle is {:.4g} deg, below {:.4g} deg", RadToDeg(*s.mu_min), RadToDeg(*mu_min));
  if (input == InputTurn::kCrank) {
    // Grashof: shortest + longest <= the other two; the input turns fully when the crank or the
    // frame is the shortest (crank-rocker, double crank)
    const double sum = s.crank + s.coupler + s.rocker + frame;
    const bool grashof = shortest->second + longest->second <= sum - shortest->second - longest->second;
    const bool input_turns = grashof && (shortest->first == std::string("crank") || shortest->first == std::string("frame"));
    if (!input_turns) return "input: crank, but the input does not turn fully (not Grashof with the crank or the frame shortest)";
  }
  return "";
}

}  // namespace koppel
