// Coupler curves (Koppelkurven) of any point of any link, with arc length and curvature, and
// the straight-line analysis of seed 003 (Geradführung): the tolerance band of a stretch
// measured against the tangent g at a reference point K_I, Q_G = Δy/L, and for a given Q_G the
// longest stretch that contains K_I.
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/position.hpp"
#include "koppel/solver/sweep.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace koppel {

struct CouplerCurve {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // partial: the curve of the drivable part only
  std::string message;
  SweepEvents sweep;                         // singular points and gaps of the trace
  std::vector<double> inputs;
  std::vector<std::uint8_t> singular;        // per sample: the pose is singular (see SweepResult)
  std::vector<Eigen::Vector2d> points;       // global position
  std::vector<Eigen::Vector2d> d1, d2;       // d/dinput, d2/dinput2
  std::vector<double> arc_length;            // from the first sample, along the curve
  std::vector<double> curvature;             // signed, 1/length; 0 where the point stands still
  std::string Brief() const;
};

// The mechanism with one output only: `point` (name "curve").
Mechanism WithPointOutput(const Mechanism& mechanism, const PointRef& point);

// Traces `point` over the sweep. Arc length integrates |dK/dinput| over each interval by
// 3-point Gauss on the cubic Hermite interpolant of the exact positions and derivatives.
CouplerCurve TraceCurve(const Mechanism& mechanism, const PointRef& point, const SweepOptions& range);

// A stretch is reported in seed 003's convention, whatever reference the search started from:
// the inputs of an R drive (radians) with reference (phi_I) and phi_a in [0, 2 pi) and phi_e =
// phi_a + phi_g > phi_a. A stretch that runs through input 0 is the one case with phi_e >= 2 pi
// (then phi_I may read less than phi_a: phi_I + 2 pi lies in the stretch). Seed 003's example:
// phi_I = 180 deg, phi_A = 98.3 deg, phi_G = 163.3 deg, so phi_E = 261.6 deg.
struct StraightStretch {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // kComplete: a stretch was measured
  std::string message;
  double reference = 0;                // phi_I: input of K_I, in [0, 2 pi)
  Eigen::Vector2d reference_point = Eigen::Vector2d::Zero();
  Eigen::Vector2d tangent = Eigen::Vector2d::UnitX();  // unit direction of g
  double phi_a = 0, phi_e = 0;         // start (in [0, 2 pi)) and end (phi_a + phi_g) of the stretch
  double phi_g = 0;                    // phi_e - phi_a: the input swept along the stretch, > 0
  double length = 0;                   // L: extent of the stretch along g
  double band = 0;                     // Δy: width of the band parallel to g that holds the stretch
  double qg = 0;                       // band / length
  bool ok() const { return status == AnalysisStatus::kComplete; }
  std::string Brief() const;
};

// A stretch [from, to] of inputs: from < to <= from + 2 pi. *why says what is wrong.
bool StretchIsValid(double from, double to, std::string* why);

// Band of a given stretch [from, to] against the tangent at `reference`: from < to <= from + 2 pi
// (a stretch through input 0 is written with to beyond 2 pi, or from below 0), moved by whole
// turns to lie around `reference`. kFailed (with StretchIsValid's reason) when the stretch is not
// one.
StraightStretch StretchBand(const Mechanism& mechanism, const PointRef& point, double reference, double from, double to,
                            double resolution, const ContinuationOptions& continuation = {});

// The longest stretch around `reference` (default: the input of least |curvature| over the
// range) with Q_G <= qg, searched over [reference - half_range, reference + half_range] at
// `resolution` (inputs in radians for R drives). Q_G is not monotonic in the end point, so every
// end point is tried, not only the first crossing.
StraightStretch LongestStraightStretch(const Mechanism& mechanism, const PointRef& point, double qg,
                                       std::optional<double> reference, double half_range, double resolution,
                                       const ContinuationOptions& continuation = {});

// The input of least |curvature| on a traced curve (the best reference point for straight-line
// guidance); -1 index when the curve is empty.
int FlattestSample(const CouplerCurve& curve);

}  // namespace koppel
