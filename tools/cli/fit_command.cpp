// koppel synth fit: least-squares fitting of any mechanism file to targets (fit_problem.hpp).
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"

#include "koppel/catalog/fit_problem.hpp"
#include "koppel/catalog/mechanism_writer.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"

#include <fmt/core.h>

#include <iostream>

namespace koppel::cli {
namespace fit_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string problem, yaml, out, format = "csv", threads;
  bool quiet = false;
};

// A value in the unit a user reads: degrees for angles.
double InUnit(FitUnit unit, double v) { return unit == FitUnit::kAngle ? RadToDeg(v) : v; }
const char* UnitName(FitUnit unit) { return unit == FitUnit::kAngle ? "deg" : "length"; }

// The report's quantity,value,unit rows: the fitted parameters, each target's residual against
// its tolerance, the starts, and what the fitted mechanism does over a turn of its drive.
Summary FitSummary(const FitProblem& problem, const FitReport& r, const Mechanism& fitted) {
  const bool angle = fitted.InputIsAngle();
  const FitUnit input_unit = angle ? FitUnit::kAngle : FitUnit::kLength;
  // a crank: the drive turns through a full revolution; mu_min over that turn if there is a mu output
  SweepOptions turn;
  turn.from = fitted.hint.input;
  turn.to = fitted.hint.input + 2 * kPi;
  turn.step = DegToRad(1);
  turn.order = 0;
  const SweepResult sweep = angle ? Sweep(fitted, turn) : SweepResult{};
  const bool crank = angle && sweep.complete();
  Summary s;
  for (size_t j = 0; j < r.values.size(); ++j) s.Add(problem.parameters[j].name, r.values[j], "parameter");
  for (size_t i = 0; i < r.targets.size(); ++i) {
    const FitTargetResult& t = r.targets[i];
    const std::string key = fmt::format("target{}_{}", i + 1, t.name);
    s.Add(key + "_residual", InUnit(t.unit, t.residual), UnitName(t.unit));
    s.Add(key + "_tolerance", InUnit(t.unit, t.tolerance), UnitName(t.unit));
    s.Add(key + "_met", t.met ? 1 : 0, "bool");
    if (problem.targets[i].input_free) s.Add(fmt::format("target{}_input", i + 1), InUnit(input_unit, t.input), UnitName(input_unit));
  }
  s.Add("cost", r.cost, "1");
  s.Add("start", r.best_start + 1, "1");
  s.Add("starts", static_cast<double>(r.starts.size()), "1");
  s.Add("starts_at_best", r.starts_at_best, "1");
  s.Add("full_rotation", crank ? 1 : 0, "bool");
  s.Add("assembles_over_required_range", r.assembles_over_range ? 1 : 0, "bool");
  if (!r.assembles_over_range) {
    // what the drive does reach, from the assembly position
    s.Add("drivable_from", InUnit(input_unit, r.drivable_from), UnitName(input_unit));
    s.Add("drivable_to", InUnit(input_unit, r.drivable_to), UnitName(input_unit));
  }
  for (int o = 0; o < static_cast<int>(fitted.outputs.size()); ++o) {
    if (fitted.outputs[o].kind != OutputKind::kTransmissionAngle || !crank) continue;
    int column = 0;
    for (int k = 0; k < o; ++k) column += fitted.outputs[k].Components();
    s.Add("mu_min_" + fitted.outputs[o].name, RadToDeg(sweep.outputs.col(column).minCoeff()), "deg");
  }
  return s;
}

// --yaml: the original file's structure with the fitted parameter values.
void WriteFittedFile(const Args& args, const FitProblem& problem, const FitReport& r, const Mechanism& fitted) {
  Overrides fitted_values;
  for (size_t j = 0; j < r.values.size(); ++j) fitted_values.emplace_back(problem.parameters[j].name, fmt::format("{:.17g}", r.values[j]));
  const MechanismFile fitted_file = ReadMechanismFile(problem.mechanism_path, fitted_values);
  const auto& values = fitted_file.parameters.Values();
  WriteOutput(args.yaml, WriteMechanismYaml(fitted, fmt::format("Fitted by koppel synth fit from {}; cost {:.3g}{}", args.problem, r.cost,
                                                                r.ok() ? "" : " (" + std::string(ToString(r.status)) + ")"),
                                            problem.base.sweep, values));
}

void Run(const Args& args) {
  CheckFormat(args.format);
  FitProblem problem = Checked([&] { return ReadFitProblem(args.problem); });  // bad input: its diagnostics, exit 2
  if (!args.threads.empty()) problem.options.threads = static_cast<int>(ParseNumberFlag("--threads", args.threads));
  std::string why;
  if (!problem.options.IsValid(&why)) {
    Complain(args.problem + ": " + why);
    throw Exit{kExitBadInput};
  }
  const FitReport r = Fit(problem.builder, problem.parameters, problem.targets, problem.options);
  if (!args.quiet) {
    for (const FitStart& s : r.starts) std::cerr << fmt::format("koppel synth fit: start {}: {}\n", s.index + 1, s.brief);
  }
  if (r.values.empty()) {
    Complain(args.problem + ": " + r.message);
    throw Exit{r.status == FitStatus::kInvalidOptions ? kExitBadInput : kExitFailed};
  }
  const Expected<Mechanism> built = problem.builder(r.values);
  if (!built) {
    Complain(args.problem + ": the fitted values do not build the mechanism: " + built.error());
    throw Exit{kExitFailed};
  }
  const Mechanism& fitted = *built;
  const Summary s = FitSummary(problem, r, fitted);
  if (!args.yaml.empty()) WriteFittedFile(args, problem, r, fitted);
  WriteOutput(args.out, args.format == "json" ? JsonText(s.ToJson()) : s.ToCsv());
  if (!args.quiet) std::cerr << fmt::format("koppel synth fit: cost {:.3g} after {} iterations (start {}; {} of {} starts reached it)\n", r.cost, r.iterations,
                           r.best_start + 1, r.starts_at_best, r.starts.size());
  if (!r.ok()) {
    Complain(args.problem + ": " + r.message);
    throw Exit{kExitFailed};
  }
}

}  // namespace
}  // namespace fit_command

void AddFitSubcommand(CLI::App& synth) {
  using namespace fit_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = synth.add_subcommand(
      "fit",
      "Least-squares fit of any mechanism file to targets with Ceres: precision points of a point output (inputs\n"
      "prescribed or free), values of a scalar output (function generation), dead centres at given inputs, and a\n"
      "point on a straight line over an input range. The problem file names the\n"
      "mechanism, the free parameters with bounds and starts, and the targets (see catalog/include/koppel/catalog/\n"
      "fit_problem.hpp or README). Gradients through the solver by the implicit-function theorem. Angle targets are\n"
      "compared wrapped to (-180, 180] deg. Several starts (16 unless the file says `starts:`) run on every core.\n"
      "Prints the fitted parameters, per target its residual and tolerance (length or deg), how many starts reached\n"
      "the best cost, whether the drive turns fully (or, when it does not assemble over `require`, the range it reaches)\n"
      "and mu_min for transmission outputs. Exit 1, naming the targets missed and by how much, when a target ends above\n"
      "its tolerance (`tolerance:`, default 1e-6 in the target's unit) or the design does not assemble over `require`.\n"
      "Example: koppel synth fit tests/data/fit-mzc-every-target.yaml -o fitted.yaml");
  cmd->add_option("problem", args->problem, "Fit problem YAML file")->required();
  OutputFile(cmd->add_option("-o,--yaml", args->yaml, "Write the fitted mechanism as a YAML file"));
  OutputFile(cmd->add_option("--output-file", args->out, "Write the report to this file instead of stdout"));
  cmd->add_option("--format", args->format, "csv (default) or json");
  cmd->add_flag("--quiet", args->quiet, "Do not print each start's Ceres report on stderr");
  cmd->add_option("--threads", args->threads, "Threads for the starts (default: one per core)");
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
