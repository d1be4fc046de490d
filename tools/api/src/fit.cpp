// koppel synth fit's report: the fit of a problem file and what the fitted mechanism does.
#include "koppel/api/fit.hpp"

#include "koppel/catalog/fit_problem.hpp"
#include "koppel/catalog/document_edit.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"

#include <fmt/core.h>

namespace koppel {

namespace {

// A value in the unit a user reads: degrees for angles, lengths in the file's unit.
double FitShown(FitUnit unit, double v) { return unit == FitUnit::kAngle ? RadToDeg(v) : v; }
// A whole turn of the drive from its assembly input (an R drive only), outputs of order 0.
SweepResult FitTurn(const Mechanism& fitted) {
  if (!fitted.InputIsAngle()) return {};
  SweepOptions turn;
  turn.from = fitted.hint.input;
  turn.to = fitted.hint.input + 2 * kPi;
  turn.step = DegToRad(1);
  turn.order = 0;
  return Sweep(fitted, turn);
}

// What the fitted mechanism does: whether it turns fully, the range it reaches when it does not
// assemble over `require`, and mu_min over the turn for every transmission angle output.
void AddBehaviour(const FitProblem& problem, const FitReport& r, const Mechanism& fitted, std::vector<FitQuantity>& rows) {
  const FitUnit input_unit = fitted.InputIsAngle() ? FitUnit::kAngle : FitUnit::kLength;
  const SweepResult sweep = FitTurn(fitted);
  const bool crank = fitted.InputIsAngle() && sweep.complete();
  rows.push_back({"full_rotation", crank ? 1.0 : 0.0, "bool"});
  rows.push_back({"assembles_over_required_range", r.assembles_over_range ? 1.0 : 0.0, "bool"});
  if (!r.assembles_over_range) {
    rows.push_back({"drivable_from", FitShown(input_unit, r.drivable_from), FitUnitName(problem, input_unit)});
    rows.push_back({"drivable_to", FitShown(input_unit, r.drivable_to), FitUnitName(problem, input_unit)});
  }
  int column = 0;
  for (const Output& o : fitted.outputs) {
    if (o.kind == OutputKind::kTransmissionAngle && crank) rows.push_back({"mu_min_" + o.name, RadToDeg(sweep.outputs.col(column).minCoeff()), "deg"});
    column += o.Components();
  }
}

std::vector<FitQuantity> ReportRows(const FitProblem& problem, const FitReport& r, const Mechanism& fitted) {
  const FitUnit input_unit = fitted.InputIsAngle() ? FitUnit::kAngle : FitUnit::kLength;
  std::vector<FitQuantity> rows;
  for (size_t j = 0; j < r.values.size(); ++j) rows.push_back({problem.parameters[j].name, r.values[j], FitParameterUnitName(problem, problem.parameters[j].name)});
  for (size_t i = 0; i < r.targets.size(); ++i) {
    const FitTargetResult& t = r.targets[i];
    const std::string key = fmt::format("target{}_{}", i + 1, t.name);
    rows.push_back({key + "_residual", FitShown(t.unit, t.residual), FitUnitName(problem, t.unit)});
    rows.push_back({key + "_tolerance", FitShown(t.unit, t.tolerance), FitUnitName(problem, t.unit)});
    rows.push_back({key + "_met", t.met ? 1.0 : 0.0, "bool"});
    if (problem.targets[i].input_free)
      rows.push_back({fmt::format("target{}_input", i + 1), FitShown(input_unit, t.input), FitUnitName(problem, input_unit)});
  }
  rows.push_back({"cost", r.cost, "1"});
  rows.push_back({"start", r.best_start + 1.0, "1"});
  rows.push_back({"starts", static_cast<double>(r.starts.size()), "1"});
  rows.push_back({"starts_at_best", static_cast<double>(r.starts_at_best), "1"});
  AddBehaviour(problem, r, fitted, rows);
  return rows;
}

// The user's mechanism file with the fitted values written in place of the free parameters'
// formulas, every other byte as it was (units, masses, loads, comments, the other formulas), and
// one comment line on top saying where the values came from.
std::string FittedYaml(const FitRequest& request, const FitProblem& problem, const FitReport& r) {
  DocumentChanges changes;
  for (size_t j = 0; j < r.values.size(); ++j) changes.parameters.emplace_back(problem.parameters[j].name, NumberText(r.values[j]));
  return fmt::format("# Fitted by koppel synth fit from {}; cost {:.3g}{}\n", request.problem, r.cost,
                     r.ok() ? "" : " (" + std::string(ToString(r.status)) + ")") +
         EditMechanismText(problem.mechanism_text, problem.mechanism_path, changes);
}

}  // namespace

FitOutcome FitMechanism(const FitRequest& request) {
  FitProblem problem = ReadFitProblem(request.problem);  // InputError: its diagnostics
  FitOutcome outcome;
  if (request.threads) problem.options.threads = *request.threads;
  problem.options.space = request.space;
  if (std::string why; !problem.options.IsValid(&why)) {
    outcome.bad_input = true;
    outcome.message = why;
    return outcome;
  }
  const FitReport r = Fit(problem.builder, problem.parameters, problem.targets, problem.options);
  for (const FitStart& s : r.starts) outcome.starts.push_back(s.brief);
  outcome.status = ToString(r.status);
  outcome.ok = r.ok();
  outcome.bad_input = r.status == FitStatus::kInvalidOptions;
  outcome.message = r.message;
  outcome.cost = r.cost;
  outcome.iterations = r.iterations;
  outcome.best_start = r.best_start + 1;
  outcome.starts_at_best = r.starts_at_best;
  if (r.values.empty()) return outcome;
  const Expected<Mechanism> built = problem.builder(r.values);
  if (!built) {
    outcome.ok = false;
    outcome.message = "the fitted values do not build the mechanism: " + built.error();
    return outcome;
  }
  outcome.fitted = true;
  outcome.report = ReportRows(problem, r, *built);
  if (request.yaml) outcome.yaml = FittedYaml(request, problem, r);
  return outcome;
}

}  // namespace koppel
