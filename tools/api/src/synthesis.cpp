// The syntheses of `koppel synth` as functions returning a Design (synthesis.hpp).
#include "koppel/api/synthesis.hpp"

#include "display.hpp"

#include "koppel/catalog/fit_problem.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/synthesis/cognates.hpp"
#include "koppel/synthesis/deadcentre_synthesis.hpp"
#include "koppel/synthesis/function_synthesis.hpp"
#include "koppel/synthesis/motion_dyads.hpp"
#include "koppel/synthesis/motion_synthesis.hpp"
#include "koppel/synthesis/mzc_synthesis.hpp"

#include <fmt/core.h>

#include <cmath>

namespace koppel {

using api_detail::BadInput;

namespace {

void Require(bool valid, const std::string& field, const std::string& why) {
  if (!valid) BadInput("synthesis request", field, why);
}

struct Figures {
  std::vector<DesignFigure> list;
  void Add(const std::string& name, double value, const std::string& unit) { list.push_back({name, value, unit}); }
  void Angle(const std::string& name, double radians) { Add(name, RadToDeg(radians), "deg"); }
};

template <class Result>
Design Finished(const Result& result, Figures figures, const Mechanism& mechanism) {
  Design d;
  d.status = result.status;
  d.message = result.message;
  if (d.ok()) {
    d.figures = std::move(figures.list);
    d.model = Model::FromMechanism(mechanism);
  }
  return d;
}

}  // namespace

double Design::Get(const std::string& name) const {
  for (const DesignFigure& f : figures) {
    if (f.name == name) return f.value;
  }
  BadInput("design", "figure", ok() ? "no figure '" + name + "'" : "no design: " + message);
}

std::string Design::Brief() const {
  std::string s = ToString(status);
  const char* separator = ": ";
  for (const DesignFigure& f : figures) {
    s += separator + f.name + " = " + std::to_string(f.value);
    separator = ", ";
  }
  return s + (message.empty() ? "" : "; " + message);
}

Design SynthesiseCrankRocker(const CrankRockerSpec& spec) {
  Require(!(spec.beta && spec.lambda), "beta/lambda", "give beta or lambda, not both");
  CrankRockerRequest request;
  request.phi0 = DegToRad(spec.phi0);
  request.psi0 = DegToRad(spec.psi0);
  request.rocker_sense = spec.same_sense ? RockerSense::kSame : RockerSense::kOpposite;
  request.frame_length = spec.frame;
  std::string why;
  Require(request.IsValid(&why), "phi0/psi0/frame", why);
  const CrankRockerDesign d = spec.beta     ? CrankRockerFromBeta(request, DegToRad(*spec.beta))
                              : spec.lambda ? CrankRockerFromLambda(request, *spec.lambda)
                                            : BestCrankRocker(request);
  if (d.status == DesignStatus::kInvalidRequest) BadInput("synthesis request", "beta/lambda", d.message);
  Figures f;
  if (d.ok()) {
    const double turn = spec.clockwise ? -1 : 1;  // the CLI's --sense cw: the mirror image
    f.Angle("beta", d.beta);
    f.Add("lambda", d.lambda, "1");
    f.Add("l1", d.l1, "length");
    f.Add("l2", d.l2, "length");
    f.Add("l3", d.l3, "length");
    f.Add("l4", d.l4, "length");
    f.Angle("mu_min", d.mu_min);
    f.Angle("mu_min_at", turn * d.mu_min_at);
    f.Angle("phi_a", turn * d.phi_a);
    f.Angle("phi_i", turn * d.phi_i);
    f.Angle("beta_L", d.beta_l);
    f.Angle("beta_E", d.beta_e);
    f.Angle("reanalysed_phi0", d.reanalysed_phi0);
    f.Angle("reanalysed_psi0", std::abs(d.reanalysed_psi));
  }
  if (!d.ok()) return Finished(d, f, Mechanism{});
  return Finished(d, f, spec.clockwise ? MirrorMechanism(CrankRockerMechanism(d)) : CrankRockerMechanism(d));
}

Design SynthesiseSliderCrank(const SliderCrankSpec& spec) {
  Require(!(spec.offset && spec.beta), "offset/beta", "give the offset or beta, not both");
  SliderCrankRequest request;
  request.phi0 = DegToRad(spec.phi0);
  request.stroke = spec.stroke;
  std::string why;
  Require(request.IsValid(&why), "phi0/stroke", why);
  const SliderCrankDesign d = spec.offset ? SliderCrankFromOffset(request, *spec.offset)
                              : spec.beta ? SliderCrankFromBeta(request, DegToRad(*spec.beta))
                                          : BestSliderCrank(request);
  if (d.status == DesignStatus::kInvalidRequest) BadInput("synthesis request", "offset/beta", d.message);
  Figures f;
  if (d.ok()) {
    f.Add("e", d.e, "length");
    f.Add("l1", d.l1, "length");
    f.Add("l2", d.l2, "length");
    f.Angle("beta", d.beta);
    f.Angle("mu_min", d.mu_min);
    f.Angle("mu_min_at", d.mu_min_at);
    f.Add("offset_max", d.offset_max, "length");
    f.Angle("beta_max", d.beta_max);
    f.Angle("reanalysed_phi0", d.reanalysed_phi0);
    f.Add("reanalysed_stroke", d.reanalysed_stroke, "length");
    return Finished(d, f, SliderCrankMechanism(d));
  }
  return Finished(d, f, Mechanism{});
}

Design SynthesiseMzc(const MzcSpec& spec) {
  Require(spec.lambda.has_value() != spec.kappa.has_value(), "lambda/kappa", "give lambda or kappa (one of them)");
  double lambda = spec.lambda.value_or(0);
  if (spec.kappa) {
    const Expected<double> from_kappa = LambdaFromKappa(DegToRad(*spec.kappa));
    Require(static_cast<bool>(from_kappa), "kappa", from_kappa ? "" : from_kappa.error());
    lambda = *from_kappa;
  }
  const MzcDesign d = MzcFromLambda(lambda, spec.diameter);
  if (d.status == DesignStatus::kInvalidRequest) BadInput("synthesis request", "lambda/D", d.message);
  Figures f;
  if (!d.ok()) return Finished(d, f, Mechanism{});
  const Mechanism m = MzcMechanism(d);
  f.Add("lambda", d.lambda, "1");
  f.Add("D", d.D, "length");
  f.Angle("phi0", d.phi0);
  f.Angle("kappa", d.kappa);
  f.Add("l1", d.l1, "length");
  f.Add("l2", d.l2, "length");
  f.Add("l3", d.l3, "length");
  f.Add("l4", d.l4, "length");
  f.Add("k", d.k, "length");
  // point 2 of link 2: K on the coupler (MzcMechanism), as `koppel synth mzc` counts it
  f.Add("contact_points", TangentContactOrder(m, {2, 2}, m.hint.input, 1e-9), "1");
  return Finished(d, f, m);
}

Design SynthesiseFunction(const FunctionSpec& spec) {
  Require(spec.type == "four-bar" || spec.type == "slider-crank", "type", "expected four-bar or slider-crank, found '" + spec.type + "'");
  Require(static_cast<bool>(spec.f), "f", "no function given");
  FunctionRequest request;
  request.type = spec.type == "four-bar" ? FunctionGenerator::kFourBar : FunctionGenerator::kSliderCrank;
  request.function = [&spec](double x, double* y) {
    *y = spec.f(x);
    return std::isfinite(*y);
  };
  request.x_from = spec.x_from;
  request.x_to = spec.x_to;
  request.input_from = DegToRad(spec.input_from);
  request.input_to = DegToRad(spec.input_to);
  const bool angle_out = request.type == FunctionGenerator::kFourBar;
  request.output_from = angle_out ? DegToRad(spec.output_from) : spec.output_from;
  request.output_to = angle_out ? DegToRad(spec.output_to) : spec.output_to;
  request.points = spec.points;
  request.at = spec.at;
  request.frame = spec.frame;
  std::string why;
  Require(request.IsValid(&why), "function request", why);
  const FunctionDesign d = koppel::SynthesiseFunction(request);
  if (d.status == FunctionStatus::kInvalidRequest) BadInput("synthesis request", "function request", d.message);
  Design design;
  design.status = d.ok() ? DesignStatus::kOk : DesignStatus::kNoDesign;
  design.message = d.ok() ? d.message : std::string(ToString(d.status)) + ": " + d.message;
  if (!d.ok()) return design;
  Figures f;
  const auto shown = [&](double v) { return angle_out ? RadToDeg(v) : v; };
  const std::string unit = angle_out ? "deg" : "length";
  if (angle_out) {
    f.Add("crank", d.crank, "length");
    f.Add("coupler", d.coupler, "length");
    f.Add("rocker", d.rocker, "length");
    f.Add("frame", d.frame, "length");
  } else {
    f.Add("crank", d.crank, "length");
    f.Add("coupler", d.coupler, "length");
    f.Add("offset", d.offset, "length");
  }
  f.Add("error_max", shown(d.error_max), unit);
  f.Add("error_at_precision", shown(d.error_at_precision), unit);
  design.figures = std::move(f.list);
  design.model = Model::FromMechanism(d.mechanism);
  return design;
}

Design SynthesiseFit(const FitSpec& spec) {
  Require(spec.threads >= 0, "threads", "must be 0 (the file's or one per core) or more");
  FitProblem problem = ReadFitProblem(spec.problem);
  if (spec.threads > 0) problem.options.threads = spec.threads;
  std::string why;
  if (!problem.options.IsValid(&why)) BadInput(spec.problem, "options", why);
  const FitReport r = Fit(problem.builder, problem.parameters, problem.targets, problem.options);
  if (r.status == FitStatus::kInvalidOptions) BadInput(spec.problem, "parameters/targets", r.message);
  Design design;
  design.status = r.ok() ? DesignStatus::kOk : DesignStatus::kNoDesign;
  design.message = r.ok() ? r.message : std::string(ToString(r.status)) + ": " + r.message;
  if (!r.ok()) return design;
  Figures f;
  ParameterValues fitted;
  for (size_t j = 0; j < r.values.size(); ++j) {
    f.Add(problem.parameters[j].name, r.values[j], "parameter");
    fitted.emplace_back(problem.parameters[j].name, fmt::format("{:.17g}", r.values[j]));
  }
  design.model = Model::Load(problem.mechanism_path, fitted);
  const bool angle_input = design.model->input_is_angle();
  for (size_t i = 0; i < r.targets.size(); ++i) {
    const FitTargetResult& t = r.targets[i];
    const bool angle = t.unit == FitUnit::kAngle;
    f.Add(fmt::format("target{}_{}_residual", i + 1, t.name), angle ? RadToDeg(t.residual) : t.residual, angle ? "deg" : "length");
    if (problem.targets[i].input_free)
      f.Add(fmt::format("target{}_input", i + 1), angle_input ? RadToDeg(t.input) : t.input, angle_input ? "deg" : "length");
  }
  f.Add("cost", r.cost, "1");
  f.Add("starts_at_best", r.starts_at_best, "1");
  design.figures = std::move(f.list);
  return design;
}

namespace {

Design MotionDesign(const MotionFourBar& f) {
  Figures figures;
  const auto point = [&](const std::string& name, const Eigen::Vector2d& p) {
    figures.Add(name + "_x", p.x(), "length");
    figures.Add(name + "_y", p.y(), "length");
  };
  point("A0", f.crank.centre);
  point("A", f.crank.circle);
  point("B", f.rocker.circle);
  point("B0", f.rocker.centre);
  figures.Angle("mu_min", f.mu_min);
  figures.Add("branch_defect", f.branch_defect ? 1 : 0, "bool");
  figures.Add("order_defect", f.order_defect ? 1 : 0, "bool");
  figures.Add("crank_turns_fully", f.crank_turns_fully ? 1 : 0, "bool");
  figures.Add("pose_error", f.pose_error, "length");
  for (size_t i = 0; i < f.pose_inputs.size(); ++i) figures.Angle(fmt::format("pose{}_input", i + 1), f.pose_inputs[i]);
  Design d;
  d.status = DesignStatus::kOk;
  d.message = ToString(f.grashof);
  d.figures = std::move(figures.list);
  d.model = Model::FromMechanism(f.mechanism);
  return d;
}

}  // namespace

Designs SynthesiseMotion(const MotionSpec& spec) {
  Require(spec.threads >= 0, "threads", "must be 0 (one per core) or more");
  std::vector<Pose> poses;
  for (const MotionPose& p : spec.poses) {
    Require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.angle), "poses", "a pose is not finite");
    poses.push_back({Eigen::Vector2d(p.x, p.y), DegToRad(p.angle)});
  }
  DyadRequest request;
  for (const auto& [x, y] : spec.circle_points) request.circle_points.emplace_back(x, y);
  request.crank_turn = DegToRad(spec.crank_turn);
  request.curve_samples = spec.curve_samples;
  const DyadChoice dyads = DyadsForPoses(poses, request);
  if (dyads.status == BurmesterStatus::kInvalidRequest) BadInput("synthesis request", "poses/circle_points", dyads.message);
  Designs out;
  if (!dyads.ok() || dyads.dyads.empty()) {
    out.status = DesignStatus::kNoDesign;
    out.message = dyads.message.empty() ? "no dyad meets the poses" : dyads.message;
    return out;
  }
  // every ordered pair is a four-bar to re-analyse: the CLI's bound on the work
  MotionOptions options;
  const std::uint64_t four_bars = MotionFourBarCount(dyads.dyads.size(), options);
  Require(four_bars <= static_cast<std::uint64_t>(kMaxMotionFourBars), "curve_samples/circle_points",
          fmt::format("{} dyads make {} four-bars, more than the limit of {} (kMaxMotionFourBars): fewer, please", dyads.dyads.size(),
                      four_bars, kMaxMotionFourBars));
  options.require_crank = spec.require_crank;
  options.threads = spec.threads;
  const MotionResult result = FourBarsFromDyads(poses, dyads.dyads, options);
  if (result.failed > 0) {
    out.status = DesignStatus::kReanalysisFailed;
    out.message = fmt::format("{} four-bar(s) failed their re-analysis{}", result.failed, result.failures.empty() ? "" : ": " + result.failures.front());
    return out;
  }
  if (result.four_bars.empty()) {
    out.status = DesignStatus::kNoDesign;
    out.message = "no four-bar meets the request";
    return out;
  }
  out.status = DesignStatus::kOk;
  for (const MotionFourBar& f : result.four_bars) out.designs.push_back(MotionDesign(f));
  return out;
}

Designs FindCognates(const Model& original, const std::string& point) {
  const Expected<PointRef> k = FindPointByText(original.mechanism(), point);
  if (!k) BadInput(original.path(), "point", k.error());
  const Cognates c = RobertsCognates(original.mechanism(), *k);
  if (c.status == DesignStatus::kInvalidRequest) BadInput(original.path(), "mechanism", c.message);
  Designs out;
  out.status = c.status;
  out.message = c.message;
  if (!c.ok()) return out;
  Figures first, second;
  first.Add("A0C0", c.frame_first, "length");
  first.Add("A0A1", c.crank_first, "length");
  first.Add("A1C1", c.coupler_first, "length");
  first.Add("C0C1", c.rocker_first, "length");
  first.Add("A1K", c.k_first, "length");
  first.Add("C1K", c.l_first, "length");
  first.Angle("input_min", c.first_input_min);
  first.Angle("input_max", c.first_input_max);
  second.Add("C0B0", c.frame_second, "length");
  second.Add("C0C2", c.crank_second, "length");
  second.Add("C2B2", c.coupler_second, "length");
  second.Add("B0B2", c.rocker_second, "length");
  second.Add("B2K", c.k_second, "length");
  second.Add("C2K", c.l_second, "length");
  out.designs.push_back(Finished(c, first, c.first));
  out.designs.push_back(Finished(c, second, c.second));
  return out;
}

}  // namespace koppel
