// A designed four-bar A0 A B B0 as a Mechanism, from its joints' global positions in one pose:
// the form every synthesis of this library (motion, function and path generation) hands to the
// solver for its re-analysis and writes as a mechanism file.
//
// Links: frame (A0, B0; the global frame), crank (body x along A0 -> A), coupler (body frame =
// the moving plane: origin `plane_origin`, x axis at `plane_angle` in this pose; points A, B and
// P = the plane's origin), rocker (body x along B0 -> B). Driven at A0; the input reads `input`
// in this pose (the crank's angle against +x by default). Outputs: "P" (point), "theta" (the
// coupler's angle = the plane's angle), "psi" (the rocker's angle, reading `psi` in this pose;
// by default its angle against +x), "mu" (transmission angle at B). The assembly hint is this
// pose. Lengths in the caller's unit, angles in radians.
#pragma once

#include "koppel/core/mechanism.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>

namespace koppel {

struct FourBarGeometry {
  Eigen::Vector2d a0 = Eigen::Vector2d::Zero(), a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero(), b0 = Eigen::Vector2d::Zero();
  Eigen::Vector2d plane_origin = Eigen::Vector2d::Zero();
  double plane_angle = 0;
  std::optional<double> input;  // default: the angle of A0 -> A
  std::optional<double> psi;    // default: the angle of B0 -> B
};

// Precondition: no link of zero length (A0 != A, A != B, B != B0, A0 != B0).
Mechanism DesignedFourBar(const FourBarGeometry& geometry, const std::string& name);

// The smallest transmission angle (output "mu") of a DesignedFourBar while its input is driven
// from `from` to `to` [rad] on the assembly's branch, found by the solver (extremes.hpp, 1 deg
// search, refined); nullopt where that stretch cannot be driven through.
std::optional<double> TransmissionMinimum(const Mechanism& designed, double from, double to);

// Where B sits for crank angle `phi` (A = A0 + a (cos phi, sin phi)) on the assembly branch
// `branch` (+1: B left of the line A -> B0, -1: right), rocker c about B0, coupler b. nullopt
// where the links do not close.
std::optional<Eigen::Vector2d> FourBarJointB(const Eigen::Vector2d& a, const Eigen::Vector2d& b0, double b, double c, int branch);

// +1 when B lies left of A -> B0, -1 right, 0 on the line (a limit position of the crank drive):
// the assembly branch, constant while the crank is driven between its limit positions.
int FourBarBranch(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& b0);

}  // namespace koppel
