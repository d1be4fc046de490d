// Function generation (Übertragungsgetriebe-Synthese): a four-bar whose rocker angle psi, or a
// slider-crank whose slider displacement s, follows y = f(x) while the crank angle phi follows x,
// both mapped linearly: phi = phi_from + (x - x_from)/(x_to - x_from) (phi_to - phi_from), and
// the output from y(x_from) .. y(x_to) onto output_from .. output_to.
//
// Four-bar A0 = (0, 0), B0 = (d, 0), A = A0 + a (cos phi, sin phi), B = B0 + c (cos psi, sin psi),
// coupler b: Freudenstein's equation (Freudenstein 1955; Sandor & Erdman, Advanced Mechanism
// Design, sec. 2.x)
//   R1 cos phi + R2 cos psi + R3 = cos(phi - psi),  R1 = -d/c, R2 = d/a, R3 = (a^2 - b^2 + c^2 + d^2)/(2 a c),
// is linear in R1..R3: exact through 3 precision points, least squares for more (then polished by
// the Ceres fit, fit.hpp, on the true output angles through the real mechanism).
// Slider-crank, slide along y = e, B = (s, e): (s - a cos phi)^2 + (e - a sin phi)^2 = b^2, i.e.
//   K1 s cos phi + K2 sin phi - K3 = s^2,  K1 = 2a, K2 = 2 a e, K3 = a^2 + e^2 - b^2.
// A negative a (or c) puts A (B) on the other side of its pivot: the link is |a| long and the
// mechanism's input (output) reads phi (psi) all the same.
//
// The structural error (generated - desired output, radians or length) is evaluated by the
// solver over the whole input range; it vanishes at the precision points of an exact design.
// Its maximum is refined between the samples of the error curve (Brent's method).
#pragma once

#include "koppel/core/mechanism.hpp"

#include <functional>
#include <string>
#include <vector>

namespace koppel {

enum class FunctionGenerator { kFourBar, kSliderCrank };

struct FunctionRequest {
  FunctionGenerator type = FunctionGenerator::kFourBar;
  // y = f(x); false where f is undefined (the request is then refused). Called from one thread.
  std::function<bool(double x, double* y)> function;
  double x_from = 0, x_to = 1;
  double input_from = 0, input_to = 1;    // crank angle [rad]
  double output_from = 0, output_to = 1;  // rocker angle [rad] or slider displacement [length]
  int points = 3;                         // Chebyshev spacing over x (when `at` is empty)
  std::vector<double> at;                 // precision points (x values), instead of `points`
  double frame = 1;                       // four-bar: A0B0
  int error_samples = 361;                // structural error curve: samples over the input range
  bool IsValid(std::string* why) const;
};

enum class FunctionStatus {
  kNotRun,
  kOk,               // designed, drivable over the whole input range, error curve complete
  kNotDrivable,      // designed, but the mechanism does not run through the whole input range
  kNoMechanism,      // the precision points give no real mechanism (a link of zero or imaginary length)
  kMissesPoints,     // exact design (3 points), but the solver's mechanism misses a precision point (another branch)
  kInvalidRequest,
};
const char* ToString(FunctionStatus status);

struct StructuralErrorSample {
  double x = 0, input = 0, desired = 0, generated = 0, error = 0;  // error = generated - desired (angles wrapped)
};

struct FunctionDesign {
  FunctionStatus status = FunctionStatus::kNotRun;
  std::string message;
  bool ok() const { return status == FunctionStatus::kOk; }
  std::string Brief() const;

  std::vector<double> precision_x;
  double crank = 0, coupler = 0, rocker = 0, frame = 0;  // four-bar link lengths (positive)
  double offset = 0;                                     // slider-crank: e
  bool polished = false;                                 // more than 3 points: the Ceres fit improved it
  std::string polish_report;                             // the fit's Brief()
  Mechanism mechanism;  // four-bar: four_bar_design.hpp (output "psi"); slider-crank: output "s"
  int output = 0;       // index of that output
  std::vector<StructuralErrorSample> error_curve;
  // max |error| over the input range: the largest sample refined between its neighbours
  // (sampled_maximum.hpp), at x = error_max_x
  double error_max = 0;
  double error_max_x = 0;
  double error_at_precision = 0;  // max |error| at the precision points (solver)
  // the least transmission angle over the input range [rad] (its output; refined), when known
  double mu_min = 0;
  bool mu_known = false;
};

FunctionDesign SynthesiseFunction(const FunctionRequest& request);

// Chebyshev spacing of n precision points over [from, to].
std::vector<double> ChebyshevPoints(double from, double to, int n);

}  // namespace koppel
