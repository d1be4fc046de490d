// The design space an engineer states for a four-bar synthesis: how long the links may be, how
// far apart their lengths, where the frame pivots may stand, and whether the input must turn
// fully. A design outside it cannot be built where it is wanted and is never returned.
// (Read from a design file by koppel/catalog/design_space_file.hpp.) Lengths and places in the
// points' unit, angles in radians (the file says degrees).
#pragma once

#include <Eigen/Core>

#include <optional>
#include <string>
#include <utility>

namespace koppel {

struct FourBarSizes {
  Eigen::Vector2d a0 = Eigen::Vector2d::Zero(), b0 = Eigen::Vector2d::Zero();  // frame pivots
  double crank = 0, coupler = 0, rocker = 0;                                    // A0A, AB, B0B (the frame is |A0B0|)
  // K in the coupler's frame (along A -> B, left of it); unknown (not checked) when absent
  std::optional<Eigen::Vector2d> coupler_point;
  // the smallest transmission angle over the worked stretch [rad]; unknown (not checked) when absent
  std::optional<double> mu_min;
};

enum class InputTurn { kAny, kCrank };  // kCrank: the input at A0 turns fully (Grashof, crank or frame shortest)

struct DesignSpace {
  std::optional<std::pair<double, double>> lengths;  // every link, the frame too: [min, max]
  std::optional<double> ratio;                       // longest / shortest link at most this (>= 1)
  std::optional<std::pair<double, double>> pivots_x, pivots_y;  // both frame pivots inside the box
  InputTurn input = InputTurn::kAny;
  std::optional<Eigen::Vector2d> a0;  // the crank's pivot A0 fixed here
  // the frame line A0 -> B0 fixed at this angle against +x (counter-clockwise positive)
  std::optional<double> frame_angle;
  // both coordinates of K in the coupler's frame (along A -> B, left of it) inside [min, max]
  std::optional<std::pair<double, double>> coupler_point;
  // the smallest transmission angle over the worked stretch at least this [rad]
  std::optional<double> mu_min;

  // A fixed A0 or frame angle holds to this, relative to the design's largest link (roundoff of
  // the polish, which keeps them constant, and of the joints' positions computed from them).
  static constexpr double kFixedTolerance = 1e-9;

  bool Empty() const {
    return !lengths && !ratio && !pivots_x && !pivots_y && input == InputTurn::kAny && !a0 && !frame_angle && !coupler_point && !mu_min;
  }
  // Empty *why and true when the space can hold a design (no empty interval, ratio >= 1, finite).
  bool IsValid(std::string* why) const;
  // Empty when a synthesis can keep every key given; else the first key it cannot, in words
  // ("coupler_point: synth function's generator has no coupler point"). `what` names the synthesis;
  // `coupler_point`: its designs have one; `fixed_frame`: it can hold A0 and the frame angle.
  std::string Unsupported(const std::string& what, bool coupler_point, bool fixed_frame) const;
  // The first constraint `sizes` breaks, in words with its figures ("lengths: the coupler is
  // 511, beyond 80"); empty when it lies inside the space.
  std::string Violation(const FourBarSizes& sizes) const;
};

}  // namespace koppel
