#include "koppel/synthesis/mechanism_space.hpp"

#include "koppel/analysis/extremes.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace koppel {
namespace {

// Below this share of the mechanism's largest distance two joints of a link stand at one place
// (a compound joint): no link length lies between them.
constexpr double kOnePlace = 1e-9;

// Each R joint of `link` with its place in the link's body frame.
std::vector<std::pair<std::string, Eigen::Vector2d>> RevolutesOn(const Mechanism& m, int link) {
  std::vector<std::pair<std::string, Eigen::Vector2d>> on;
  for (const Joint& j : m.joints) {
    if (j.type != JointType::kRevolute || (j.link_a != link && j.link_b != link)) continue;
    const PointRef p = JointPointOn(j, link);
    if (p.point >= 0) on.emplace_back(j.name, m.links[link].points[p.point].local);
  }
  return on;
}

// The smallest transmission angle over from..to of every transmission-angle output [rad]; empty
// with `why` when one could not be found.
std::optional<double> SmallestTransmission(const Mechanism& m, double from, double to, std::string* why) {
  SweepOptions stretch;
  stretch.from = from;
  stretch.to = to;
  stretch.step = m.InputIsAngle() ? DegToRad(1) : (to - from) / 360;
  std::optional<double> smallest;
  for (size_t o = 0; o < m.outputs.size(); ++o) {
    if (m.outputs[o].kind != OutputKind::kTransmissionAngle) continue;
    const OutputExtremes mu = FindOutputExtremes(m, static_cast<int>(o), 0, stretch);
    if (!mu.sweep.complete() || mu.status != AnalysisStatus::kComplete) {
      *why = fmt::format("mu_min: {}'s smallest value over the worked stretch is not known ({})", m.outputs[o].name, mu.Brief());
      return std::nullopt;
    }
    smallest = std::min(smallest.value_or(mu.minimum.value), mu.minimum.value);
  }
  return smallest;
}

std::string LengthViolation(const DesignSpace& space, const MechanismSizes& sizes) {
  if (sizes.lengths.empty()) return "";
  if (space.lengths) {
    for (const auto& [name, length] : sizes.lengths) {
      if (length < space.lengths->first) return fmt::format("lengths: {} is {:.6g}, below {:.6g}", name, length, space.lengths->first);
      if (length > space.lengths->second) return fmt::format("lengths: {} is {:.6g}, beyond {:.6g}", name, length, space.lengths->second);
    }
  }
  const auto [shortest, longest] =
      std::minmax_element(sizes.lengths.begin(), sizes.lengths.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  if (space.ratio && longest->second > *space.ratio * shortest->second)
    return fmt::format("ratio: {} ({:.6g}) is {:.4g} times {} ({:.6g}), more than {:.6g}", longest->first, longest->second,
                       longest->second / shortest->second, shortest->first, shortest->second, *space.ratio);
  return "";
}

std::string PivotViolation(const DesignSpace& space, const MechanismSizes& sizes) {
  for (const auto& [name, p] : sizes.pivots) {
    if (space.pivots_x && (p.x() < space.pivots_x->first || p.x() > space.pivots_x->second))
      return fmt::format("pivots: {} at x = {:.6g}, outside [{:.6g}, {:.6g}]", name, p.x(), space.pivots_x->first, space.pivots_x->second);
    if (space.pivots_y && (p.y() < space.pivots_y->first || p.y() > space.pivots_y->second))
      return fmt::format("pivots: {} at y = {:.6g}, outside [{:.6g}, {:.6g}]", name, p.y(), space.pivots_y->first, space.pivots_y->second);
  }
  return "";
}

}  // namespace

MechanismSizes SizesOf(const Mechanism& m) {
  MechanismSizes sizes;
  double largest = 0;
  std::vector<std::pair<std::string, double>> all;
  for (int l = 0; l < static_cast<int>(m.links.size()); ++l) {
    const auto on = RevolutesOn(m, l);
    for (size_t i = 0; i < on.size(); ++i)
      for (size_t k = i + 1; k < on.size(); ++k) {
        const double d = (on[i].second - on[k].second).norm();
        largest = std::max(largest, d);
        all.emplace_back(fmt::format("{} {}-{}", m.links[l].name, on[i].first, on[k].first), d);
      }
    if (m.links[l].is_frame) sizes.pivots = on;
  }
  for (const auto& [name, d] : all)
    if (d > kOnePlace * largest) sizes.lengths.emplace_back(name, d);
  return sizes;
}

std::string UncheckableSpace(const DesignSpace& space, const Mechanism& m) {
  if (const std::string why = space.Unsupported("synth fit", false, false); !why.empty()) return why;
  if (space.mu_min && std::none_of(m.outputs.begin(), m.outputs.end(), [](const Output& o) { return o.kind == OutputKind::kTransmissionAngle; }))
    return "mu_min: the mechanism file has no transmission-angle output (outputs: {mu: {transmission: {coupler: ..., joint: ...}}})";
  if (space.input == InputTurn::kCrank && !m.InputIsAngle()) return "input: crank, but the drive is a slide (a P joint), which cannot turn";
  return "";
}

std::string MechanismViolation(const DesignSpace& space, const Mechanism& m, double from, double to) {
  const MechanismSizes sizes = SizesOf(m);
  if (std::string v = LengthViolation(space, sizes); !v.empty()) return v;
  if (std::string v = PivotViolation(space, sizes); !v.empty()) return v;
  if (space.input == InputTurn::kCrank) {
    SweepOptions turn;
    turn.from = m.hint.input;
    turn.to = m.hint.input + 2 * kPi;
    turn.order = 0;
    if (const SweepResult sweep = Sweep(m, turn); !sweep.complete())
      return "input: crank, but the drive does not turn a whole turn (" + sweep.Brief() + ")";
  }
  if (space.mu_min) {
    std::string why;
    const std::optional<double> mu = SmallestTransmission(m, from, to, &why);
    if (!mu) return why;
    if (*mu < *space.mu_min - DesignSpace::kFixedTolerance)
      return fmt::format("mu_min: the smallest transmission angle is {:.4g} deg, below {:.4g} deg", RadToDeg(*mu), RadToDeg(*space.mu_min));
  }
  return "";
}

}  // namespace koppel
