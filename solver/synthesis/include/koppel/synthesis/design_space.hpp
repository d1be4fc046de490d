// The design space an engineer states for a four-bar synthesis: how long the links may be, how
// far apart their lengths, where the frame pivots may stand, and whether the input must turn
// fully. A design outside it cannot be built where it is wanted and is never returned.
// (Read from a design file by koppel/catalog/design_space_file.hpp.) Lengths and places in the
// points' unit.
#pragma once

#include <Eigen/Core>

#include <optional>
#include <string>
#include <utility>

namespace koppel {

struct FourBarSizes {
  Eigen::Vector2d a0 = Eigen::Vector2d::Zero(), b0 = Eigen::Vector2d::Zero();  // frame pivots
  double crank = 0, coupler = 0, rocker = 0;                                    // A0A, AB, B0B (the frame is |A0B0|)
};

enum class InputTurn { kAny, kCrank };  // kCrank: the input at A0 turns fully (Grashof, crank or frame shortest)

struct DesignSpace {
  std::optional<std::pair<double, double>> lengths;  // every link, the frame too: [min, max]
  std::optional<double> ratio;                       // longest / shortest link at most this (>= 1)
  std::optional<std::pair<double, double>> pivots_x, pivots_y;  // both frame pivots inside the box
  InputTurn input = InputTurn::kAny;

  bool Empty() const { return !lengths && !ratio && !pivots_x && !pivots_y && input == InputTurn::kAny; }
  // Empty *why and true when the space can hold a design (no empty interval, ratio >= 1, finite).
  bool IsValid(std::string* why) const;
  // The first constraint `sizes` breaks, in words with its figures ("lengths: the coupler is
  // 511, beyond 80"); empty when it lies inside the space.
  std::string Violation(const FourBarSizes& sizes) const;
};

}  // namespace koppel
