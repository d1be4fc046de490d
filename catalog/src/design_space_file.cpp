#include "koppel/catalog/design_space_file.hpp"

#include "koppel/catalog/mechanism_file.hpp"  // InputError
#include "input_file.hpp"
#include "koppel/core/angles.hpp"
#include "yaml_reader.hpp"

#include <cmath>

namespace koppel {
namespace {

// [min, max], finite, min <= max; reported at the node otherwise.
std::optional<std::pair<double, double>> Interval(YamlReader& r, const YAML::Node& node, const std::string& path) {
  if (!node.IsSequence() || node.size() != 2) {
    r.Error(node, path, "expected [min, max]");
    return std::nullopt;
  }
  const auto lo = r.Number(node[0], Index(path, 0)), hi = r.Number(node[1], Index(path, 1));
  if (!lo || !hi) return std::nullopt;
  if (!std::isfinite(*lo) || !std::isfinite(*hi)) {
    r.Error(node, path, "expected finite numbers");
    return std::nullopt;
  }
  if (*lo > *hi) {
    r.Error(node, path, "an empty interval: min is above max");
    return std::nullopt;
  }
  return std::make_pair(*lo, *hi);
}

}  // namespace

DesignSpace ReadDesignSpace(const std::string& path) { return ParseDesignSpaceText(ReadInputText(path), path); }

DesignSpace ParseDesignSpaceText(const std::string& text, const std::string& path) {
  const YAML::Node root = ParseYamlText(text, path);
  YamlReader r(path, nullptr);
  r.set_fallback(YAML::Mark());
  // a file of comments alone would leave the synthesis as it is: refused (--design that changes nothing)
  if (root.IsNull()) r.Error(root, "", "the design file states no constraint: give a map of lengths, ratio, pivots, input, A0, frame_angle, coupler_point or mu_min");
  if (root.IsNull() || !r.ExpectMap(root, "")) throw InputError(r.diagnostics());
  r.CheckKeys(root, "", {"lengths", "ratio", "pivots", "input", "A0", "frame_angle", "coupler_point", "mu_min"});
  DesignSpace space;
  if (const YAML::Node n = root["lengths"]; n.IsDefined()) {
    space.lengths = Interval(r, n, "lengths");
    if (space.lengths && space.lengths->second <= 0) r.Error(n, "lengths", "the largest length must be positive");
    else if (space.lengths && space.lengths->first < 0) r.Error(n, "lengths", "the smallest length cannot be negative (0 admits any)");
  }
  if (const YAML::Node n = root["ratio"]; n.IsDefined()) {
    if (const auto v = r.Number(n, "ratio")) {
      if (!(std::isfinite(*v) && *v >= 1)) r.Error(n, "ratio", "the longest link over the shortest is at least 1");
      space.ratio = *v;
    }
  }
  if (const YAML::Node n = root["pivots"]; n.IsDefined() && r.ExpectMap(n, "pivots")) {
    r.CheckKeys(n, "pivots", {"x", "y"});
    if (const YAML::Node x = n["x"]; x.IsDefined()) space.pivots_x = Interval(r, x, "pivots.x");
    if (const YAML::Node y = n["y"]; y.IsDefined()) space.pivots_y = Interval(r, y, "pivots.y");
  }
  if (const YAML::Node n = root["input"]; n.IsDefined()) {
    const std::optional<std::string> word = r.Text(n, "input");
    if (word == "crank") space.input = InputTurn::kCrank;
    else if (word == "any") space.input = InputTurn::kAny;
    else if (word) r.Error(n, "input", "expected crank or any, found '" + *word + "'");
  }
  if (const YAML::Node n = root["A0"]; n.IsDefined()) {
    if (!n.IsSequence() || n.size() != 2) {
      r.Error(n, "A0", "expected [x, y]");
    } else if (const auto x = r.Number(n[0], Index("A0", 0)), y = r.Number(n[1], Index("A0", 1)); x && y) {
      if (!std::isfinite(*x) || !std::isfinite(*y)) r.Error(n, "A0", "expected finite numbers");
      else space.a0 = Eigen::Vector2d(*x, *y);
    }
  }
  if (const YAML::Node n = root["frame_angle"]; n.IsDefined()) {
    if (const auto v = r.Number(n, "frame_angle")) {
      if (!std::isfinite(*v)) r.Error(n, "frame_angle", "expected a finite angle in degrees");
      else space.frame_angle = DegToRad(*v);
    }
  }
  if (const YAML::Node n = root["coupler_point"]; n.IsDefined()) space.coupler_point = Interval(r, n, "coupler_point");
  if (const YAML::Node n = root["mu_min"]; n.IsDefined()) {
    if (const auto v = r.Number(n, "mu_min")) {
      if (!(*v >= 0 && *v < 90)) r.Error(n, "mu_min", "expected a transmission angle from 0 to below 90 deg");
      else space.mu_min = DegToRad(*v);
    }
  }
  if (std::string why; r.diagnostics().empty() && !space.IsValid(&why)) r.Error(root, "", why);
  if (!r.diagnostics().empty()) throw InputError(r.diagnostics());
  return space;
}

}  // namespace koppel
