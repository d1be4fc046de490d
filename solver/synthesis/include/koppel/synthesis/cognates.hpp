// Cognates (Ersatzgetriebe, Satz von Roberts–Chebyshev): the two other four-bars whose coupler
// point traces the same coupler curve as a given four-bar A0 A B B0 with coupler point K.
//
// With the coupler point written K = A + r (B - A) (r complex: |r| = AK/AB, arg r = angle BAK),
// the third frame pivot is C0 = A0 + r (B0 - A0): triangle A0 B0 C0 is similar to A B K.
//   cognate 1 (pivots A0, C0): crank A0 A1 = r (B - A), coupler A1 K = A - A0 with
//     A1 C1 = r (A - A0), rocker C0 C1 = r (B - B0); its coupler turns with the original crank.
//   cognate 2 (pivots C0, B0): crank C0 C2 = (1 - r)(A - A0) turns with the original crank,
//     coupler B2 K = B - B0 with B2 C2 = (1 - r)(B - B0), rocker B0 B2 = (r - 1)(B - A).
// Each cognate is built at the original's assembled pose, with an assembly hint there, so it
// starts on the branch that traces the same curve. Cognate 2 is driven at C0 with its input
// equal to the original's crank angle; cognate 1 at A0 (its input follows the original coupler).
#pragma once

#include "koppel/core/expected.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/synthesis/design_status.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>

namespace koppel {

struct FourBarJoints {
  int frame = -1, crank = -1, coupler = -1, rocker = -1;
  int a0 = -1, a = -1, b = -1, b0 = -1;  // joints
};

// Recognises a four-bar of R joints driven at a frame joint; an error saying what is not otherwise.
Expected<FourBarJoints> IdentifyFourBar(const Mechanism& m);

struct Cognates {
  DesignStatus status = DesignStatus::kNotRun;  // kInvalidRequest: not a four-bar or not a coupler point
  std::string message;
  Mechanism first;   // pivots A0, C0
  Mechanism second;  // pivots C0, B0
  double frame_first = 0, crank_first = 0, coupler_first = 0, rocker_first = 0;  // A0C0, A0A1, A1C1, C0C1
  double k_first = 0, l_first = 0;                                                // A1K, C1K
  double frame_second = 0, crank_second = 0, coupler_second = 0, rocker_second = 0;  // C0B0, C0C2, C2B2, B0B2
  double k_second = 0, l_second = 0;                                                  // B2K, C2K
  // the input range of cognate 1 (its crank follows the original coupler, so for a crank-rocker
  // original it is a rocker): [min, max] over one turn of the original, radians
  double first_input_min = 0, first_input_max = 0;
  bool ok() const { return status == DesignStatus::kOk; }
  std::string Brief() const;
};

// `point` is the coupler point (on the coupler link). Assembles the original at its hint.
Cognates RobertsCognates(const Mechanism& m, const PointRef& point);

// A four-bar in one pose: the joints in loop order (crank pivot, crank-coupler, coupler-rocker,
// rocker pivot) and the coupler point K, global.
struct FourBarPose {
  Eigen::Vector2d a0 = Eigen::Vector2d::Zero(), a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero(),
                  b0 = Eigen::Vector2d::Zero(), k = Eigen::Vector2d::Zero();
};

// The two cognates in the same pose (the formulas above): {A0 A1 C1 C0, C0 C2 B2 B0}, each with
// the original's K. nullopt where they degenerate (K on A or B, or A on B).
std::optional<std::array<FourBarPose, 2>> CognatePoses(const FourBarPose& original);

}  // namespace koppel
