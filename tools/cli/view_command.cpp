// koppel view: one self-contained HTML page that animates the mechanism (see view_page.hpp).
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"
#include "sweep_report.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/plot/view_page.hpp"

namespace koppel::cli {
namespace view_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, from, to, step, at_branch_point;
  std::vector<std::string> sets;
  std::string out;
};

void Run(const Args& args) {
  const Model model = LoadModel(args.file, args.sets);
  const Mechanism& m = model.mechanism();
  auto in = [&](double v) { return m.InputIsAngle() ? DegToRad(v) : v; };
  // one frame per degree unless asked: smooth enough, and the page stays small
  std::optional<double> step = OptionalNumberFlag("--step", args.step);
  if (!step && m.InputIsAngle()) step = 1.0;
  const SweepSpan span = model.Span(OptionalNumberFlag("--from", args.from), OptionalNumberFlag("--to", args.to), step);
  plot::ViewOptions options;
  options.length_unit = model.length_unit();
  options.range.from = in(span.from);
  options.range.to = in(span.to);
  options.range.step = in(span.step);
  options.range.continuation.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  options.title = model.title().empty() ? m.name : model.title() + " (" + m.name + ")";
  std::string why;
  if (!options.IsValid(&why)) {
    Complain(why);
    throw Exit{kExitBadInput};
  }
  const plot::PlotResult r = plot::ViewPage(m, options);
  if (r.status == plot::PlotStatus::kFailed) {
    Complain(args.file + ": " + r.message);
    throw Exit{kExitFailed};
  }
  WriteOutput(args.out, r.svg);
  if (r.status == plot::PlotStatus::kPartial) {
    Complain(args.file + ": " + r.message + " (the page shows what was computed)");
    throw Exit{kExitFailed};
  }
}

}  // namespace
}  // namespace view_command

void AddViewCommand(CLI::App& app) {
  using namespace view_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "view",
      "One self-contained HTML page (opens offline, no server): the mechanism animated over the sweep (looping over a\n"
      "full turn, back and forth over a limited range), a slider for the input, play/pause and speed, the coupler\n"
      "curves of the point outputs, every scalar output with its transfer functions and the transmission angle as\n"
      "charts (uPlot) with a cursor at the current input, and the numbers there.\n"
      "Example: koppel view catalog/entries/mzc-crank-rocker.yaml -o mech.html");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--from", args->from, "First input (default: the file's sweep)");
  cmd->add_option("--to", args->to, "Last input (default: the file's sweep)");
  cmd->add_option("--step", args->step, "Input step between frames (default 1 deg for an R drive, else the file's step)");
  AddBranchPointOption(cmd, args->at_branch_point);
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write the page to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
