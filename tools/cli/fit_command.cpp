// koppel synth fit: least-squares fitting of any mechanism file to targets (fit_problem.hpp).
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"

#include "koppel/api/fit.hpp"
#include "koppel/api/design_file.hpp"

#include <fmt/core.h>

#include <iostream>

namespace koppel::cli {
namespace fit_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string problem, yaml, out, format = "csv", threads, design;
  bool quiet = false;
};

void Run(const Args& args) {
  CheckFormat(args.format);
  FitRequest request;
  request.problem = args.problem;
  if (!args.threads.empty()) request.threads = static_cast<int>(ParseCountFlag("--threads", args.threads, 0, kMaxThreads));
  request.yaml = !args.yaml.empty();
  if (!args.design.empty()) request.space = Checked([&] { return ReadDesignFile(args.design); });  // file:line, exit 2
  const FitOutcome r = Checked([&] { return FitMechanism(request); });  // a problem file that does not read: exit 2
  if (!args.quiet) {
    for (size_t i = 0; i < r.starts.size(); ++i) std::cerr << fmt::format("koppel synth fit: start {}: {}\n", i + 1, r.starts[i]);
  }
  if (!r.fitted) {
    Complain(args.problem + ": " + r.message);
    throw Exit{r.bad_input ? kExitBadInput : kExitFailed};
  }
  Summary s;
  for (const FitQuantity& q : r.report) s.Add(q.quantity, q.value, q.unit);
  if (!args.yaml.empty()) WriteOutput(args.yaml, r.yaml);
  WriteOutput(args.out, args.format == "json" ? JsonText(s.ToJson()) : s.ToCsv());
  if (!args.quiet)
    std::cerr << fmt::format("koppel synth fit: cost {:.3g} after {} iterations (start {}; {} of {} starts reached it)\n", r.cost,
                             r.iterations, r.best_start, r.starts_at_best, r.starts.size());
  if (!r.ok) {
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
      "mechanism, the free parameters with bounds and starts, and the targets (see docs/synthesis.md,\n"
      "'Least-squares fitting'). Gradients through the solver by the implicit-function theorem. Angle targets are\n"
      "compared wrapped to (-180, 180] deg. Several starts (16 unless the file says `starts:`) run on every core.\n"
      "Prints the fitted parameters, per target its residual and tolerance (length or deg), how many starts reached\n"
      "the best cost, whether the drive turns fully (or, when it does not assemble over `require`, the range it reaches)\n"
      "and mu_min for transmission outputs. Exit 1, naming the targets missed and by how much, when a target ends above\n"
      "its tolerance (`tolerance:`, default 1e-6 in the target's unit) or the design does not assemble over `require`.\n"
      "Example: koppel synth fit tests/data/fit-mzc-every-target.yaml -o fitted.yaml");
  cmd->add_option("problem", args->problem, "Fit problem YAML file")->required();
  OutputFile(cmd->add_option("-o,--yaml", args->yaml, "Write the mechanism file with the fitted values in place of the free parameters' (the rest as written)"));
  OutputFile(cmd->add_option("--output-file", args->out, "Write the report to this file instead of stdout"));
  cmd->add_option("--format", args->format, "csv (default) or json");
  cmd->add_flag("--quiet", args->quiet, "Do not print each start's Ceres report on stderr");
  cmd->add_option("--threads", args->threads, "Threads for the starts (default: one per core)");
  cmd->add_option("--design", args->design, "The design space: a YAML file (lengths and ratio: the distance between every two\n"
                                             "joints of a link; pivots: every frame joint; input: crank; mu_min: every transmission\n"
                                             "output over `require:`, else a whole turn). The best start inside it is the result;\n"
                                             "exit 1 naming the constraint when every start's design lies outside");
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
