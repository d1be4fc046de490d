// koppel synth fit: least-squares fitting of any mechanism file to targets (fit_problem.hpp).
#include "commands.hpp"
#include "common.hpp"

#include "koppel/catalog/fit_problem.hpp"
#include "koppel/catalog/mechanism_writer.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"

#include <fmt/core.h>

#include <iostream>

namespace koppel::cli {
namespace {

struct Args {
  std::string problem, yaml, out, format = "csv";
  bool quiet = false;
};

void Run(const Args& args) {
  CheckFormat(args.format);
  FitProblem problem;
  try {
    problem = ReadFitProblem(args.problem);
  } catch (const InputError& e) {
    for (const Diagnostic& d : e.diagnostics()) std::cerr << d.ToString() << "\n";
    throw Exit{kExitBadInput};
  }
  NoteInputFile(args.problem), NoteInputFile(problem.mechanism_path);  // -o/--yaml never replace them
  problem.options.quiet = args.quiet;
  const FitReport r = Fit(problem.builder, problem.parameters, problem.targets, problem.options);
  if (!r.ok) {
    Complain(args.problem + ": " + r.message);
    throw Exit{kExitFailed};
  }
  Mechanism fitted;
  std::string error;
  problem.builder(r.values, &fitted, &error);
  const bool angle = fitted.InputIsAngle();
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
  for (size_t i = 0; i < problem.targets.size(); ++i) {
    s.Add(fmt::format("target{}_{}_residual", i + 1, problem.targets[i].name), r.target_residuals[i], "length or rad");
    if (problem.targets[i].input_free) s.Add(fmt::format("target{}_input", i + 1), angle ? RadToDeg(r.fitted_inputs[i]) : r.fitted_inputs[i], angle ? "deg" : "length");
  }
  s.Add("cost", r.cost, "1");
  s.Add("start", r.start_index + 1, "1");
  s.Add("full_rotation", crank ? 1 : 0, "bool");
  s.Add("assembles_over_required_range", r.assembles_over_range ? 1 : 0, "bool");
  for (int o = 0; o < static_cast<int>(fitted.outputs.size()); ++o) {
    if (fitted.outputs[o].kind != OutputKind::kTransmissionAngle || !crank) continue;
    int column = 0;
    for (int k = 0; k < o; ++k) column += fitted.outputs[k].Components();
    s.Add("mu_min_" + fitted.outputs[o].name, RadToDeg(sweep.outputs.col(column).minCoeff()), "deg");
  }
  if (!args.yaml.empty()) {
    // the fitted mechanism: the original file's structure with the fitted parameter values
    Overrides fitted_values;
    for (size_t j = 0; j < r.values.size(); ++j) fitted_values.emplace_back(problem.parameters[j].name, fmt::format("{:.17g}", r.values[j]));
    const MechanismFile fitted_file = ReadMechanismFile(problem.mechanism_path, fitted_values);
    const auto& values = fitted_file.parameters.Values();
    WriteOutput(args.yaml, WriteMechanismYaml(fitted, "Fitted by koppel synth fit from " + args.problem + "; cost " + fmt::format("{:.3g}", r.cost),
                                              problem.base.sweep, values));
  }
  WriteOutput(args.out, args.format == "json" ? JsonText(s.ToJson()) : s.ToCsv());
  if (!args.quiet) std::cerr << fmt::format("koppel synth fit: cost {:.3g} after {} iterations (start {})\n", r.cost, r.iterations, r.start_index + 1);
}

}  // namespace

void AddFitSubcommand(CLI::App& synth) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = synth.add_subcommand(
      "fit",
      "Least-squares fit of any mechanism file to targets with Ceres: precision points of a point output (inputs\n"
      "prescribed or free), values of a scalar output (function generation), dead centres at given inputs, and a\n"
      "point on a straight line over an input range. The problem file names the\n"
      "mechanism, the free parameters with bounds and starts, and the targets (see catalog/include/koppel/catalog/\n"
      "fit_problem.hpp or README). Gradients through the solver by the implicit-function theorem. Prints per target\n"
      "its residual, the fitted parameters, whether the drive turns fully, and mu_min for transmission outputs.\n"
      "Example: koppel synth fit problem.yaml -o fitted.yaml");
  cmd->add_option("problem", args->problem, "Fit problem YAML file")->required();
  cmd->add_option("-o,--yaml", args->yaml, "Write the fitted mechanism as a YAML file");
  cmd->add_option("--output-file", args->out, "Write the report to this file instead of stdout");
  cmd->add_option("--format", args->format, "csv (default) or json");
  cmd->add_flag("--quiet", args->quiet, "No progress on stderr");
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
