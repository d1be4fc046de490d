// The syntheses of `koppel synth` as functions returning a Design (synthesis.hpp).
#include "koppel/api/synthesis.hpp"

#include "design_units.hpp"
#include "display.hpp"
#include "model_impl.hpp"

#include "koppel/catalog/fit_problem.hpp"
#include "koppel/catalog/length_units.hpp"
#include "koppel/catalog/mechanism_writer.hpp"
#include "koppel/catalog/synthesis_spec.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/synthesis/cognates.hpp"
#include "koppel/synthesis/deadcentre_synthesis.hpp"
#include "koppel/synthesis/function_synthesis.hpp"
#include "koppel/synthesis/mzc_synthesis.hpp"
#include "koppel/solver/sweep.hpp"

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

// A design from no file in the unit the user names: its file says the unit, its length
// figures carry its name.
void InUnits(const std::optional<Loads>& units, Design& design, const Mechanism& m, const std::string& comment,
             const SweepDefaults& sweep = {0, 360, 1}) {
  design.yaml = WriteMechanismYaml(m, comment, sweep, {}, UnitsFor(units));
  LabelLengths(units, design.figures);
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

namespace {

std::string CrankRockerComment(const CrankRockerRequest& r, const CrankRockerDesign& d, bool clockwise) {
  const double turn = clockwise ? -1 : 1;
  return fmt::format("Crank-rocker from dead-centre synthesis (koppel synth): phi0 = {:.10g} deg, psi0 = {:.10g} deg, beta = {:.10g} deg,\n"
                     "rocker sense {}. Input phi: crank angle against A0B0, counter-clockwise; the crank runs {}.\n"
                     "From the folded dead centre (phi = {:.10g} deg) to the extended one (phi = {:.10g} deg) the crank turns\n"
                     "by phi0 and the rocker by psi0, {}.",
                     RadToDeg(r.phi0), RadToDeg(r.psi0), RadToDeg(d.beta), ToString(r.rocker_sense), clockwise ? "clockwise" : "counter-clockwise",
                     RadToDeg(turn * d.phi_i), RadToDeg(turn * d.phi_a), r.rocker_sense == RockerSense::kSame ? "both the same way" : "in opposite senses");
}

Figures CrankRockerFigures(const CrankRockerRequest& r, const CrankRockerDesign& d, bool clockwise) {
  const double turn = clockwise ? -1 : 1;  // the CLI's --sense cw: the mirror image
  Figures f;
  f.Angle("phi0", r.phi0);
  f.Angle("psi0", r.psi0);
  f.Add("rocker_sense", r.rocker_sense == RockerSense::kSame ? 1 : -1, "same=1");
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
  f.Add("sense", turn, "ccw=1");
  return f;
}

}  // namespace

Design SynthesiseCrankRocker(const CrankRockerSpec& spec) {
  Require(!(spec.beta && spec.lambda), "beta/lambda", "give beta or lambda, not both");
  const std::optional<Loads> units = UnitsOf(spec.units);
  CrankRockerRequest request;
  request.phi0 = DegToRad(spec.phi0);
  request.psi0 = DegToRad(spec.psi0);
  request.rocker_sense = spec.same_sense ? RockerSense::kSame : RockerSense::kOpposite;
  request.frame_length = spec.frame;
  std::string why;
  Require(request.IsValid(&why), "phi0/psi0/frame", why);
  if (const std::string why = spec.space.Unsupported("synth deadcentre", false, false); !why.empty()) BadInput("design space", "design", why);
  CrankRockerDesign d = spec.beta     ? CrankRockerFromBeta(request, DegToRad(*spec.beta))
                        : spec.lambda ? CrankRockerFromLambda(request, *spec.lambda)
                                      : BestCrankRockerInSpace(request, spec.space);
  if (d.status == DesignStatus::kInvalidRequest) BadInput("synthesis request", "beta/lambda/design", d.message);
  if (d.ok() && (spec.beta || spec.lambda))  // the design asked for, against the space
    if (const std::string v = spec.space.Violation({{0, 0}, {d.l4, 0}, d.l1, d.l2, d.l3, std::nullopt, d.mu_min}); !v.empty()) {
      d.status = DesignStatus::kNoDesign;
      d.message = "outside the design space: " + v;
    }
  if (!d.ok()) return Finished(d, Figures{}, Mechanism{});
  const Mechanism m = spec.clockwise ? MirrorMechanism(CrankRockerMechanism(d)) : CrankRockerMechanism(d);
  Design design = Finished(d, CrankRockerFigures(request, d, spec.clockwise), m);
  InUnits(units, design, m, CrankRockerComment(request, d, spec.clockwise));
  return design;
}

Design SynthesiseSliderCrank(const SliderCrankSpec& spec) {
  Require(!(spec.offset && spec.beta), "offset/beta", "give the offset or beta, not both");
  const std::optional<Loads> units = UnitsOf(spec.units);
  SliderCrankRequest request;
  request.phi0 = DegToRad(spec.phi0);
  request.stroke = spec.stroke;
  std::string why;
  Require(request.IsValid(&why), "phi0/stroke", why);
  const SliderCrankDesign d = spec.offset ? SliderCrankFromOffset(request, *spec.offset)
                              : spec.beta ? SliderCrankFromBeta(request, DegToRad(*spec.beta))
                                          : BestSliderCrank(request);
  if (d.status == DesignStatus::kInvalidRequest) BadInput("synthesis request", "offset/beta", d.message);
  if (!d.ok()) return Finished(d, Figures{}, Mechanism{});
  Figures f;
  f.Angle("phi0", request.phi0);
  f.Add("stroke", request.stroke, "length");
  f.Add("e", d.e, "length");
  f.Add("l1", d.l1, "length");
  f.Add("l2", d.l2, "length");
  f.Add("e_s0", d.e / request.stroke, "1");
  f.Angle("beta", d.beta);
  f.Angle("mu_min", d.mu_min);
  f.Angle("mu_min_at", d.mu_min_at);
  f.Add("offset_max", d.offset_max, "length");
  f.Angle("beta_max", d.beta_max);
  f.Angle("reanalysed_phi0", d.reanalysed_phi0);
  f.Add("reanalysed_stroke", d.reanalysed_stroke, "length");
  const Mechanism m = SliderCrankMechanism(d);
  Design design = Finished(d, f, m);
  InUnits(units, design, m,
          fmt::format("Slider-crank from dead-centre synthesis (koppel synth): phi0 = {:.10g} deg, stroke = {:.10g}, e = {:.10g}.\n"
                      "Conventions of seed 000: A0 = (0, -e), phi from -y counter-clockwise, s from the foot point.",
                      RadToDeg(request.phi0), request.stroke, d.e));
  return design;
}

namespace {

// The double rocker's cognate whose crank turns with its coupler, about K (point 2 of link 2,
// MzcMechanism): the crank-rocker (seed 003).
Cognates MzcCognates(const Mechanism& double_rocker) { return RobertsCognates(double_rocker, {2, 2}); }

void AddCrankRocker(const Cognates& c, Figures& f) {
  f.Add("crank_rocker_l1", c.crank_first, "length");
  f.Add("crank_rocker_l2", c.coupler_first, "length");
  f.Add("crank_rocker_l3", c.rocker_first, "length");
  f.Add("crank_rocker_l4", c.frame_first, "length");
  f.Add("crank_rocker_AK", c.k_first, "length");
}

}  // namespace

Design SynthesiseMzc(const MzcSpec& spec) {
  const std::optional<Loads> units = UnitsOf(spec.units);
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
  if (const Cognates c = MzcCognates(m); c.ok()) AddCrankRocker(c, f);
  Design design = Finished(d, f, m);
  // the double rocker's own input range, a hundredth of a degree inside its limit positions
  const InputRange range = DrivableRange(m, kPi, DegToRad(1));
  const double lo = RadToDeg(range.low) + 0.01, hi = RadToDeg(range.high) - 0.01;
  InUnits(units, design, m,
          fmt::format("Meyer zur Capellen straight-line linkage (koppel synth mzc): lambda = {}, D = {}.\n"
                      "Assembled in the crossed symmetric position; K is the inflection pole there.",
                      d.lambda, d.D),
          {lo, hi, (hi - lo) / 200});
  return design;
}

Design MzcCrankRocker(const Design& double_rocker, const std::string& unit_name) {
  if (!double_rocker.ok() || !double_rocker.model) BadInput("design", "double rocker", "no Meyer zur Capellen design: " + double_rocker.message);
  const std::optional<Loads> units = UnitsOf(unit_name);
  const Cognates c = MzcCognates(double_rocker.model->mechanism());
  Figures f;
  if (c.ok()) {
    f.Add("l1", c.crank_first, "length");
    f.Add("l2", c.coupler_first, "length");
    f.Add("l3", c.rocker_first, "length");
    f.Add("l4", c.frame_first, "length");
    f.Add("AK", c.k_first, "length");
  }
  Design design = Finished(c, f, c.first);
  if (design.ok()) InUnits(units, design, c.first, "Crank-rocker cognate of a Meyer zur Capellen linkage (koppel synth mzc).");
  return design;
}

namespace {

// The mechanism file's comment: what was asked (by `by`: the command or the API call), what was
// designed and its structural error.
std::string FunctionComment(const FunctionRequest& r, const FunctionDesign& d, const std::string& by, const std::string& formula) {
  const bool four_bar = r.type == FunctionGenerator::kFourBar;
  const auto out_unit = [&](double v) { return four_bar ? RadToDeg(v) : v; };
  std::string points;
  for (double x : d.precision_x) points += fmt::format("{}{:.6g}", points.empty() ? "" : ", ", x);
  return fmt::format(
      "Function generator ({}): y = {} for x in [{:.6g}, {:.6g}]; the crank angle phi [deg] maps x\n"
      "from {:.6g} to {:.6g}, the output {} maps y from {:.6g} to {:.6g}. Precision points x = {}{}.\n"
      "Structural error: at most {:.6g} {} over the range, {:.3g} at the precision points.",
      by, formula, r.x_from, r.x_to, RadToDeg(r.input_from), RadToDeg(r.input_to), four_bar ? "psi [deg]" : "s", out_unit(r.output_from),
      out_unit(r.output_to), points, d.polished ? " (least squares, polished through the mechanism)" : "", out_unit(d.error_max),
      four_bar ? "deg" : "length", out_unit(d.error_at_precision));
}

// A function design in the API's units. A design that was made but fails its check keeps its
// lengths; one that misses a precision point was re-analysed on another assembly branch, so its
// error (figures and curve) would belong to a different mechanism and is left out.
Design ShownFunction(const FunctionRequest& r, const FunctionDesign& d, const std::string& by, const std::string& formula,
                     const std::optional<Loads>& units, const DesignSpace& space) {
  Design design;
  design.status = d.ok() ? DesignStatus::kOk : DesignStatus::kNoDesign;
  design.message = d.ok() ? d.message : d.Brief();
  if (d.status == FunctionStatus::kNoMechanism) return design;
  const bool four_bar = r.type == FunctionGenerator::kFourBar;
  const auto shown = [&](double v) { return four_bar ? RadToDeg(v) : v; };
  const std::string unit = four_bar ? "deg" : "length";  // relabelled below with --units
  Figures f;
  f.Add("crank", d.crank, "length");
  f.Add("coupler", d.coupler, "length");
  if (four_bar) {
    f.Add("rocker", d.rocker, "length");
    f.Add("frame", d.frame, "length");
  } else {
    f.Add("offset", d.offset, "length");
  }
  if (d.status != FunctionStatus::kMissesPoints) {
    f.Add("error_max", shown(d.error_max), unit);
    f.Add("error_at_precision", shown(d.error_at_precision), unit);
    if (d.mu_known) f.Add("mu_min", RadToDeg(d.mu_min), "deg");
    design.curve.columns = {"x", "crank", "desired", "generated", "error"};
    for (const StructuralErrorSample& e : d.error_curve)
      design.curve.rows.push_back({e.x, RadToDeg(e.input), shown(e.desired), shown(e.generated), shown(e.error)});
  }
  design.figures = std::move(f.list);
  LabelLengths(units, design.figures);
  if (!d.ok()) return design;
  // the design space: a four-bar's pivots A0 (0, 0) and B0 (frame, 0), its links and mu_min
  if (!space.Empty()) {
    std::string violation = "the design space is for four-bars; a slider-crank generator is not checked against it";
    if (four_bar && space.mu_min && !d.mu_known) violation = "mu_min: the generator's transmission angle over the input range is not known";
    else if (four_bar)
      violation = space.Violation({Eigen::Vector2d(0, 0), Eigen::Vector2d(d.frame, 0), d.crank, d.coupler, d.rocker, std::nullopt,
                                   d.mu_known ? std::optional<double>(d.mu_min) : std::nullopt});
    if (!violation.empty()) {
      design.status = DesignStatus::kNoDesign;
      design.message = "outside the design space: " + violation;
      return design;
    }
  }
  design.model = Model::FromMechanism(d.mechanism);
  const double from = RadToDeg(r.input_from), to = RadToDeg(r.input_to);
  design.yaml = WriteMechanismYaml(d.mechanism, FunctionComment(r, d, by, formula), {from, to, (to - from) / 360}, {}, UnitsFor(units));
  return design;
}

}  // namespace

Design SynthesiseFunction(const FunctionSpec& spec) {
  if (const std::string why = spec.space.Unsupported("synth function", false, false); !why.empty()) BadInput("design space", "design", why);
  const std::optional<Loads> units = UnitsOf(spec.units);
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
  return ShownFunction(request, d, "koppel::SynthesiseFunction", "f(x)", units, spec.space);
}

Design SynthesiseFunctionFile(const std::string& path, const std::string& unit_name, const DesignSpace& space) {
  if (const std::string why = space.Unsupported("synth function", false, false); !why.empty()) BadInput("design space", "design", why);
  const std::optional<Loads> units = UnitsOf(unit_name);
  const FunctionSpecFile spec = ReadFunctionSpec(path);
  const FunctionDesign d = koppel::SynthesiseFunction(spec.request);
  if (d.status == FunctionStatus::kInvalidRequest) BadInput(path, "function request", d.message);
  return ShownFunction(spec.request, d, "koppel synth function " + path, spec.formula, units, space);
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
    f.Add(problem.parameters[j].name, r.values[j], FitParameterUnitName(problem, problem.parameters[j].name));
    fitted.emplace_back(problem.parameters[j].name, fmt::format("{:.17g}", r.values[j]));
  }
  design.model = Model::Load(problem.mechanism_path, fitted);
  const bool angle_input = design.model->input_is_angle();
  for (size_t i = 0; i < r.targets.size(); ++i) {
    const FitTargetResult& t = r.targets[i];
    const bool angle = t.unit == FitUnit::kAngle;
    f.Add(fmt::format("target{}_{}_residual", i + 1, t.name), angle ? RadToDeg(t.residual) : t.residual, FitUnitName(problem, t.unit));
    if (problem.targets[i].input_free)
      f.Add(fmt::format("target{}_input", i + 1), angle_input ? RadToDeg(t.input) : t.input,
            FitUnitName(problem, angle_input ? FitUnit::kAngle : FitUnit::kLength));
  }
  f.Add("cost", r.cost, "1");
  f.Add("starts_at_best", r.starts_at_best, "1");
  design.figures = std::move(f.list);
  return design;
}

namespace {

// Cognate 1 is driven by a link that follows the original coupler: its own input range over a
// turn of the original, a hundredth of a degree inside the dead centres at its ends. A coupler
// that only translates (a parallelogram) leaves that crank standing while K moves: then the
// sweep is its one pose, and `note` says why.
SweepDefaults FirstCognateSweep(const Cognates& c, std::string* note) {
  double lo = RadToDeg(c.first_input_min) + 0.01, hi = RadToDeg(c.first_input_max) - 0.01;
  if (!(hi > lo)) {
    *note = "cognate 1's crank follows the original coupler, which does not turn here: cognate 1 cannot be driven by its crank "
            "(its file's sweep is its one pose)";
    lo = hi = RadToDeg(0.5 * (c.first_input_min + c.first_input_max));
  }
  return {lo, hi, hi > lo ? (hi - lo) / 180 : 1.0};
}

}  // namespace

Designs FindCognates(const Model& original, const std::string& point) {
  const Expected<PointRef> k = FindPointByText(original.mechanism(), point);
  if (!k) BadInput(original.path(), "point", k.error());
  const Cognates c = RobertsCognates(original.mechanism(), *k);
  if (c.status == DesignStatus::kInvalidRequest) BadInput(original.path(), "mechanism", c.message);
  Designs out;
  out.status = c.status;
  out.message = c.message;
  if (!c.ok()) return out;
  const std::string unit = original.length_unit();
  Figures first, second;
  first.Add("A0C0", c.frame_first, unit);
  first.Add("A0A1", c.crank_first, unit);
  first.Add("A1C1", c.coupler_first, unit);
  first.Add("C0C1", c.rocker_first, unit);
  first.Add("A1K", c.k_first, unit);
  first.Add("C1K", c.l_first, unit);
  first.Angle("input_min", c.first_input_min);
  first.Angle("input_max", c.first_input_max);
  second.Add("C0B0", c.frame_second, unit);
  second.Add("C0C2", c.crank_second, unit);
  second.Add("C2B2", c.coupler_second, unit);
  second.Add("B0B2", c.rocker_second, unit);
  second.Add("B2K", c.k_second, unit);
  second.Add("C2K", c.l_second, unit);
  out.designs.push_back(Finished(c, first, c.first));
  out.designs.push_back(Finished(c, second, c.second));
  const std::string note = "Roberts–Chebyshev cognate of " + original.path() + " (koppel cognates): traces the same curve of K.\n";
  std::string why;
  // the cognates' links are not the original's: of its loads only the length unit carries over
  const Loads& given = ModelAccess::File(original).loads;
  Loads units;
  units.metres_per_unit = given.metres_per_unit;
  units.length_unit_given = given.length_unit_given;
  units.length_unit_name = given.length_unit_name;
  out.designs[0].yaml = WriteMechanismYaml(c.first, note + "Pivots A0 and C0; its crank A0A1 turns with the original coupler.",
                                           FirstCognateSweep(c, &why), {}, &units);
  if (!why.empty()) out.notes.push_back(why);
  out.designs[1].yaml = WriteMechanismYaml(c.second, note + "Pivots C0 and B0; its crank C0C2 turns with the original crank: same input.",
                                           ModelAccess::File(original).sweep, {}, &units);
  return out;
}

}  // namespace koppel
