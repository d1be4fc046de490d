#include "koppel/synthesis/function_synthesis.hpp"

#include "koppel/analysis/extremes.hpp"

#include "bar_linkages.hpp"

#include "koppel/analysis/extremes.hpp"
#include "koppel/analysis/sampled_maximum.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"
#include "koppel/synthesis/fit.hpp"
#include "koppel/synthesis/four_bar_design.hpp"

#include <Eigen/Dense>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

namespace koppel {
namespace {

// Links shorter than this (relative to the frame, or the output range for a slider-crank) make
// no mechanism: the precision points are then (nearly) degenerate.
constexpr double kShortestLink = 1e-9;

// The unknowns of the linear equation: four-bar (a, b, c), slider-crank (a, b, e).
struct Dimensions {
  double a = 0, b = 0, third = 0;
};

// Four-bar with signed crank a and rocker c (body x axes along A0 -> A for a > 0; the link angles
// are phi and psi either way); B assembled at phi on `branch`.
std::optional<Mechanism> FourBarAt(const Dimensions& dim, double d, double phi, int branch) {
  const Eigen::Vector2d a0(0, 0), b0(d, 0), a = dim.a * Eigen::Vector2d(std::cos(phi), std::sin(phi));
  const std::optional<Eigen::Vector2d> b = FourBarJointB(a, b0, dim.b, dim.third, branch);
  if (!b) return std::nullopt;
  Mechanism m = BarFourBar("function-generator", a0, b0, dim.a, dim.b, dim.third);
  HintInput(m, phi);
  HintPoint(m, "crank", "A", a);
  HintPoint(m, "coupler", "A", a);
  HintPoint(m, "coupler", "B", *b);
  HintPoint(m, "rocker", "B", *b);
  return m;
}

// Slider-crank: slide along y = e, B = (s, e); B at phi on `branch` (+1: s > a cos phi).
std::optional<Mechanism> SliderCrankAt(const Dimensions& dim, double phi, int branch) {
  const double e = dim.third;
  const Eigen::Vector2d a = dim.a * Eigen::Vector2d(std::cos(phi), std::sin(phi));
  const double h2 = dim.b * dim.b - std::pow(e - a.y(), 2);
  if (!(h2 >= 0)) return std::nullopt;
  const Eigen::Vector2d b(a.x() + branch * std::sqrt(h2), e);
  Mechanism m = BarSliderCrank("function-generator", {0, 0}, {0, e}, {dim.a, 0}, std::abs(dim.b));
  HintInput(m, phi);
  HintPoint(m, "crank", "A", a);
  HintPoint(m, "coupler", "A", a);
  HintPoint(m, "coupler", "B", b);
  HintPoint(m, "slider", "B", b);
  return m;
}

// The linear equations through the precision points (least squares for more than three); an
// error for a degenerate solution.
Expected<Dimensions> SolveLinear(const FunctionRequest& r, const std::vector<double>& phi, const std::vector<double>& out) {
  using Result = Expected<Dimensions>;
  Dimensions dim;
  const int n = static_cast<int>(phi.size());
  Eigen::MatrixXd m(n, 3);
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) {
    if (r.type == FunctionGenerator::kFourBar) {
      m.row(i) << std::cos(phi[i]), std::cos(out[i]), 1;
      rhs[i] = std::cos(phi[i] - out[i]);
    } else {
      m.row(i) << out[i] * std::cos(phi[i]), std::sin(phi[i]), -1;
      rhs[i] = out[i] * out[i];
    }
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m);
  if (qr.rank() < 3) {
    return Result::Error("the precision points make the linear equations singular");
  }
  const Eigen::Vector3d k = qr.solve(rhs);
  if (r.type == FunctionGenerator::kFourBar) {
    const double d = r.frame;
    // R1 = -d/c, R2 = d/a, R3 = (a^2 - b^2 + c^2 + d^2) / (2ac)
    dim.third = -d / k[0];
    dim.a = d / k[1];
    const double b2 = dim.a * dim.a + dim.third * dim.third + d * d - 2 * dim.a * dim.third * k[2];
    if (!(std::isfinite(dim.a) && std::isfinite(dim.third) && b2 > std::pow(kShortestLink * d, 2))) {
      return Result::Error("Freudenstein's equation gives no real coupler length for these precision points");
    }
    dim.b = std::sqrt(b2);
  } else {
    dim.a = k[0] / 2;
    dim.third = k[1] / k[0];
    const double b2 = dim.a * dim.a + dim.third * dim.third - k[2];
    if (!(std::isfinite(dim.a) && std::isfinite(dim.third) && b2 > 0)) {
      return Result::Error("the slider-crank's equation gives no real coupler length for these precision points");
    }
    dim.b = std::sqrt(b2);
  }
  return dim;
}

}  // namespace

const char* ToString(FunctionStatus status) {
  switch (status) {
    case FunctionStatus::kNotRun: return "not run";
    case FunctionStatus::kOk: return "ok";
    case FunctionStatus::kNotDrivable: return "not drivable over the input range";
    case FunctionStatus::kNoMechanism: return "no mechanism";
    case FunctionStatus::kMissesPoints: return "misses the precision points";
    case FunctionStatus::kInvalidRequest: return "invalid request";
  }
  return "?";
}

std::string FunctionDesign::Brief() const {
  std::string text = ToString(status);
  if (!message.empty()) text += ": " + message;
  return text;
}

std::vector<double> ChebyshevPoints(double from, double to, int n) {
  std::vector<double> x;
  for (int i = 1; i <= n; ++i) x.push_back(0.5 * (from + to) - 0.5 * (to - from) * std::cos((2 * i - 1) * kPi / (2 * n)));
  return x;
}

bool FunctionRequest::IsValid(std::string* why) const {
  std::string problem;
  const bool finite = std::isfinite(x_from) && std::isfinite(x_to) && std::isfinite(input_from) && std::isfinite(input_to) &&
                      std::isfinite(output_from) && std::isfinite(output_to) && std::isfinite(frame);
  if (!function) problem = "no function";
  else if (!finite) problem = "the ranges must be finite";
  else if (x_from == x_to) problem = "the x range is empty";
  else if (input_from == input_to) problem = "the input range is empty";
  else if (output_from == output_to) problem = "the output range is empty";
  else if (!(frame > 0)) problem = "the frame length must be positive";
  else if (at.empty() && (points < 3 || points > 1000)) problem = "points must be between 3 and 1000";
  else if (!at.empty() && (at.size() < 3 || at.size() > 1000)) problem = "at: needs between 3 and 1000 precision points";
  else if (error_samples < 2 || error_samples > 1'000'000) problem = "error_samples must be between 2 and 1000000";
  if (problem.empty()) {
    for (double x : at) {
      if (!(std::isfinite(x) && x >= std::min(x_from, x_to) && x <= std::max(x_from, x_to))) problem = fmt::format("precision point x = {} lies outside the x range", x);
    }
  }
  if (why) *why = problem;
  return problem.empty();
}

namespace {

// The request's linear maps: x to the input, f(x) to the output.
class FunctionMap {
 public:
  explicit FunctionMap(const FunctionRequest& r) : r_(r) {}
  // f at both ends of the x range; false when it is undefined there or equal at both ends
  bool Prepare() { return r_.function(r_.x_from, &y_from_) && r_.function(r_.x_to, &y_to_) && y_from_ != y_to_; }
  double Input(double x) const { return r_.input_from + (x - r_.x_from) / (r_.x_to - r_.x_from) * (r_.input_to - r_.input_from); }
  double X(double input) const { return r_.x_from + (input - r_.input_from) / (r_.input_to - r_.input_from) * (r_.x_to - r_.x_from); }
  // the output that f(x) maps to; nullopt where f has no finite value
  std::optional<double> Output(double x) const {
    double y = 0;
    if (!r_.function(x, &y)) return std::nullopt;
    const double out = r_.output_from + (y - y_from_) / (y_to_ - y_from_) * (r_.output_to - r_.output_from);
    return std::isfinite(out) ? std::optional<double>(out) : std::nullopt;
  }

 private:
  const FunctionRequest& r_;
  double y_from_ = 0, y_to_ = 0;
};

FunctionDesign Refused(FunctionDesign& design, FunctionStatus status, std::string message) {
  design.status = status;
  design.message = std::move(message);
  return design;
}

using Build = std::function<std::optional<Mechanism>(const Dimensions&)>;
using UsableDimensions = std::function<bool(const Dimensions&)>;

// More precision points than unknowns: the least-squares design polished on the true output
// through the solver, kept when the fit assembles over the whole input range.
void PolishByFit(const FunctionRequest& r, const std::vector<double>& phi, const std::vector<double>& out, const Build& build,
                 const UsableDimensions& usable, Dimensions& dim, FunctionDesign& design) {
  const MechanismBuilder builder = [&](const std::vector<double>& v) -> Expected<Mechanism> {
    const std::optional<Mechanism> built = build({v[0], v[1], v[2]});
    if (!built) return Expected<Mechanism>::Error("does not close at the first precision point");
    return *built;
  };
  const std::vector<FitParameter> parameters = {{"a", dim.a}, {"b", dim.b}, {"third", dim.third}};
  std::vector<FitTarget> targets;
  for (size_t i = 0; i < phi.size(); ++i) {
    FitTarget t;
    t.name = fmt::format("x = {}", design.precision_x[i]);
    t.output = 0;
    t.input = phi[i];
    t.value = out[i];
    targets.push_back(t);
  }
  FitOptions options;
  options.starts = 1;
  options.threads = 1;
  options.require_from = std::min(r.input_from, r.input_to);
  options.require_to = std::max(r.input_from, r.input_to);
  const FitReport fit = Fit(builder, parameters, targets, options);
  design.polish_report = fit.Brief();
  if (fit.values.empty() || !fit.assembles_over_range) return;
  const Dimensions polished{fit.values[0], fit.values[1], fit.values[2]};
  if (usable(polished) && build(polished)) {
    dim = polished;
    design.polished = true;
  }
}

// The largest |structural error| over the sampled range, refined between the samples (the
// largest sample is not the maximum): the mechanism is solved at inputs between two samples by
// continuation from the nearer one. `design.error_curve` holds the samples of `s`, in its order.
// False when it cannot be solved there.
bool RefineErrorMaximum(const FunctionRequest& r, const FunctionMap& map, const SweepResult& s, FunctionDesign& design) {
  const bool four_bar = r.type == FunctionGenerator::kFourBar;
  std::vector<double> errors;
  for (const StructuralErrorSample& e : design.error_curve) errors.push_back(std::abs(e.error));
  PositionSolver solver(design.mechanism);
  std::vector<double> output(solver.OutputWidth(0));
  const double step = s.inputs.size() > 1 ? std::abs(s.inputs[1] - s.inputs[0]) : 1.0;
  const auto evaluate = [&](double input) -> std::optional<double> {
    const auto nearest = std::min_element(s.inputs.begin(), s.inputs.end(), [&](double a, double b) { return std::abs(a - input) < std::abs(b - input); });
    const Eigen::Index k = nearest - s.inputs.begin();
    Continuation path(solver);
    if (!path.Start(s.inputs[k], s.poses.row(k).transpose()).ok() || !path.AdvanceTo(input, step).ok()) return std::nullopt;
    path.OutputDerivatives(0, output.data());
    const std::optional<double> wanted = map.Output(map.X(input));
    if (!wanted) return std::nullopt;
    return std::abs(four_bar ? AngleDifference(output[0], *wanted) : output[0] - *wanted);
  };
  const SampledMaximum maximum = RefineSampledMaximum(s.inputs, errors, evaluate);
  if (!maximum.ok) return false;
  design.error_max = maximum.value;
  design.error_max_x = map.X(maximum.input);
  return true;
}

// The least transmission angle over the input range (the design's transmission output), refined
// between the samples (extremes.hpp): a generator that runs through a mu of 15 deg jams in
// practice however small its error. Left unknown (mu_known false) when the search fails.
void MeasureTransmission(const FunctionRequest& r, FunctionDesign& design) {
  const Mechanism& m = design.mechanism;
  for (int o = 0; o < static_cast<int>(m.outputs.size()); ++o) {
    if (m.outputs[o].kind != OutputKind::kTransmissionAngle) continue;
    SweepOptions range;
    range.from = r.input_from;
    range.to = r.input_to;
    range.step = (r.input_to - r.input_from) / std::max(2, r.error_samples - 1);
    range.order = 2;
    const OutputExtremes mu = FindOutputExtremes(m, o, 0, range);
    if (mu.status != AnalysisStatus::kComplete) return;
    design.mu_min = mu.minimum.value;
    design.mu_known = true;
    return;
  }
}

// The structural error over the whole input range and at the precision points, by the solver;
// the design's status says whether the mechanism runs through the range.
FunctionDesign MeasureError(const FunctionRequest& r, const FunctionMap& map, const std::vector<double>& phi,
                            const std::vector<double>& out, FunctionDesign& design) {
  const bool four_bar = r.type == FunctionGenerator::kFourBar;
  auto difference = [&](double generated, double wanted) { return four_bar ? AngleDifference(generated, wanted) : generated - wanted; };
  SweepOptions sweep;
  sweep.from = r.input_from;
  sweep.to = r.input_to;
  sweep.step = (r.input_to - r.input_from) / (r.error_samples - 1);
  sweep.order = 0;
  const SweepResult s = Sweep(design.mechanism, sweep);
  for (size_t i = 0; i < s.inputs.size(); ++i) {
    StructuralErrorSample e;
    e.input = s.inputs[i];
    e.x = map.X(e.input);
    const std::optional<double> wanted = map.Output(e.x);
    if (!wanted) return Refused(design, FunctionStatus::kInvalidRequest, fmt::format("f is not defined at x = {} inside the x range", e.x));
    e.desired = *wanted;
    e.generated = s.outputs(static_cast<Eigen::Index>(i), 0);
    e.error = difference(e.generated, e.desired);
    design.error_curve.push_back(e);
  }
  if (!s.inputs.empty() && !RefineErrorMaximum(r, map, s, design))
    return Refused(design, FunctionStatus::kNotDrivable, "the structural error cannot be evaluated between its samples");
  std::sort(design.error_curve.begin(), design.error_curve.end(), [&](const auto& u, const auto& v) { return (u.x < v.x) == (r.x_from < r.x_to); });
  for (size_t i = 0; i < phi.size(); ++i) {
    SweepOptions at;
    at.from = at.to = phi[i];
    at.order = 0;
    const SweepResult p = Sweep(design.mechanism, at);
    if (!p.complete()) continue;  // reported through the error curve's status below
    design.error_at_precision = std::max(design.error_at_precision, std::abs(difference(p.outputs(0, 0), out[i])));
  }
  // three points are solved exactly: a solver's mechanism that misses one runs on another
  // assembly branch than the equations assumed, and its error curve is not the design's
  const double exact = 1e-6 * std::max(1.0, std::abs(r.output_to - r.output_from));
  if (phi.size() == 3 && !(design.error_at_precision <= exact))
    return Refused(design, FunctionStatus::kMissesPoints,
                   fmt::format("the mechanism misses a precision point by {:.3g}{}: the precision points lie on different assembly "
                               "branches (a branch defect: turning the crank through the input range does not carry the linkage "
                               "from one to the other). Try other input or output ranges",
                               four_bar ? RadToDeg(design.error_at_precision) : design.error_at_precision, four_bar ? " deg" : ""));
  if (!s.complete())
    return Refused(design, FunctionStatus::kNotDrivable, "the mechanism does not run through the whole input range on its branch: " + s.message);
  MeasureTransmission(r, design);
  design.status = FunctionStatus::kOk;
  return design;
}

}  // namespace

FunctionDesign SynthesiseFunction(const FunctionRequest& r) {
  FunctionDesign design;
  if (std::string why; !r.IsValid(&why)) return Refused(design, FunctionStatus::kInvalidRequest, why);
  const bool four_bar = r.type == FunctionGenerator::kFourBar;
  FunctionMap map(r);
  if (!map.Prepare()) return Refused(design, FunctionStatus::kInvalidRequest, "f must be defined at both ends of the x range and differ there");
  design.precision_x = r.at.empty() ? ChebyshevPoints(r.x_from, r.x_to, r.points) : r.at;
  std::vector<double> phi, out;
  for (double x : design.precision_x) {
    const std::optional<double> o = map.Output(x);
    if (!o) return Refused(design, FunctionStatus::kInvalidRequest, fmt::format("f is not defined at the precision point x = {}", x));
    phi.push_back(map.Input(x));
    out.push_back(*o);
  }
  const Expected<Dimensions> solved = SolveLinear(r, phi, out);
  if (!solved) return Refused(design, FunctionStatus::kNoMechanism, solved.error());
  Dimensions dim = *solved;
  // the assembly branch the first precision point puts B on, kept while polishing
  int branch = 1;
  if (four_bar) {
    const Eigen::Vector2d a = dim.a * Eigen::Vector2d(std::cos(phi[0]), std::sin(phi[0]));
    const Eigen::Vector2d b = Eigen::Vector2d(r.frame, 0) + dim.third * Eigen::Vector2d(std::cos(out[0]), std::sin(out[0]));
    branch = FourBarBranch(a, b, {r.frame, 0}) >= 0 ? 1 : -1;
  } else {
    branch = out[0] >= dim.a * std::cos(phi[0]) ? 1 : -1;
  }
  const Build build = [&](const Dimensions& d) { return four_bar ? FourBarAt(d, r.frame, phi[0], branch) : SliderCrankAt(d, phi[0], branch); };
  const double size = four_bar ? r.frame : std::abs(r.output_to - r.output_from);
  const UsableDimensions usable = [&](const Dimensions& d) {
    return std::min({std::abs(d.a), std::abs(d.b), four_bar ? std::abs(d.third) : 1e300}) > kShortestLink * size;
  };
  if (!usable(dim) || !build(dim))
    return Refused(design, FunctionStatus::kNoMechanism,
                   "the precision points give a degenerate mechanism (a link of zero length, or it does not close at the first point)");
  if (phi.size() > 3) PolishByFit(r, phi, out, build, usable, dim, design);
  design.mechanism = *build(dim);
  design.output = 0;
  design.crank = std::abs(dim.a);
  design.coupler = std::abs(dim.b);
  if (four_bar) {
    design.rocker = std::abs(dim.third);
    design.frame = r.frame;
  } else {
    design.offset = dim.third;
  }
  return MeasureError(r, map, phi, out, design);
}

}  // namespace koppel
