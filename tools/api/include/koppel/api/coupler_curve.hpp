// Coupler curves (Koppelkurven) and straight-line guidance (Geradführung, seed 003) of a point,
// as `koppel curve` reports them, in the API's units (model.hpp): inputs and angles in degrees
// for an R drive, positions in the file's length unit, global frame; derivatives by the input in
// radians (R drive) or length (P drive). The theory: koppel/analysis/coupler_curve.hpp.
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/api/instant_geometry.hpp"  // Point2
#include "koppel/api/model.hpp"
#include "koppel/core/mechanism.hpp"        // PointRef

#include <optional>
#include <string>
#include <vector>

namespace koppel {

struct CouplerCurveRequest {
  PointRef point;
  std::optional<double> from, to, step;  // [deg | length]; unset: the file's sweep (Model::Span)
  AtBranchPoint at_branch_point = AtBranchPoint::kContinue;
  // false with the reason when the range cannot be swept (a zero step, ends not finite, ...)
  bool IsValid(const Model& model, std::string* why) const;
};

// The curve over the sweep, one entry per computed sample in sweep order.
struct CouplerCurveTable {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // partial: the curve of the drivable part only
  std::string message;
  std::string point;                  // "link.point"
  std::vector<double> inputs;         // [deg | length]
  std::vector<Point2> points;         // the position [length unit]
  std::vector<Point2> d1;             // d position / d input [length/rad | 1]
  std::vector<double> arc_length;     // from the first sample, along the curve [length unit]
  std::vector<double> curvature;      // signed [1/length unit]; 0 where the point stands still
  std::vector<bool> singular;         // the pose is singular (as `koppel analyze` flags it)
  SweepRecord sweep;                  // what the trace met
  bool complete() const { return status == AnalysisStatus::kComplete; }
};

// The coupler curve of request.point. InputError when !request.IsValid(model).
CouplerCurveTable TraceCouplerCurve(const Model& model, const CouplerCurveRequest& request);

// Straight-line guidance of an R drive's point: with `stretch` the band of that stretch [deg]
// about `at`, else the longest stretch through `at` with Q_G <= qg, searched at `resolution`
// over one turn about `at` (unset: the input of least curvature).
struct StraightLineRequest {
  PointRef point;
  std::optional<double> at;                  // phi_I [deg]; needed with a stretch
  std::optional<double> stretch_a, stretch_e;  // A:E [deg], both or neither
  double qg = 0.005;
  double resolution = 0.02;                  // [deg]
  AtBranchPoint at_branch_point = AtBranchPoint::kContinue;
  // false with the reason: a P drive, a resolution or qg not positive, a stretch without `at` or
  // that is not one (StraightStretchIsValid)
  bool IsValid(const Model& model, std::string* why) const;
};

// A stretch A..E [deg]: finite, A < E <= A + 360 (a stretch through 0 ends beyond 360: 300:420).
bool StraightStretchIsValid(double a, double e, std::string* why);

// Seed 003's convention whatever `at` was: phi_I and phi_A in [0, 360), phi_E = phi_A + phi_G
// (beyond 360 only for a stretch through 0).
struct StraightLine {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // complete: a stretch was measured
  std::string message;
  double reference = 0;        // phi_I [deg]: the input of K_I
  Point2 reference_point;      // K_I [length unit]
  double tangent_angle = 0;    // the direction of the tangent g at K_I [deg], in (-180, 180]
  double phi_a = 0, phi_e = 0, phi_g = 0;  // [deg]
  double length = 0;           // L: the stretch's extent along g [length unit]
  double band = 0;             // delta_y: the width of the band parallel to g that holds it [length unit]
  double qg = 0;               // Q_G = delta_y / L
  bool ok() const { return status == AnalysisStatus::kComplete; }
};

// InputError when !request.IsValid(model).
StraightLine FindStraightLine(const Model& model, const StraightLineRequest& request);

}  // namespace koppel
