// koppel draw: the kinematic scheme at one input, optionally with both dead-centre poses
// (seed 000 "Bild 3") and a traced coupler curve.
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"
#include "sweep_report.hpp"

#include "koppel/plot/scheme_drawing.hpp"

namespace koppel::cli {
namespace draw_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, at, trace, output, from, to, step, at_branch_point;
  std::vector<std::string> sets;
  bool deadcentres = false;
  std::string out;
};

// Whether --output names a scalar output (the first one when empty), without a word: a pose that
// cannot be drawn is told first, and ResolveScalarOutput names the output's problem after it.
bool HasScalarOutput(const Mechanism& m, const std::string& name) {
  for (const Output& o : m.outputs)
    if (o.Components() == 1 && (name.empty() || o.name == name)) return true;
  return false;
}

plot::SchemeRequest ReadRequest(const Args& args, const Model& model) {
  const Mechanism& m = model.mechanism();
  plot::SchemeRequest request;
  if (!args.from.empty()) request.from = ParseNumberFlag("--from", args.from);
  if (!args.to.empty()) request.to = ParseNumberFlag("--to", args.to);
  if (!args.step.empty()) request.step = ParseNumberFlag("--step", args.step);
  request.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  if (std::string why; !request.IsValid(model, &why)) {
    Complain("--step must not be 0 (and give at most 20000 samples)");
    throw Exit{kExitBadInput};
  }
  if (!args.trace.empty()) {
    request.trace = ResolvePoint(m, args.trace, "--trace");
    request.trace_name = args.trace;
  }
  if (!args.at.empty()) request.at = ParseNumberFlag("--at", args.at);
  request.dead_centres = args.deadcentres && HasScalarOutput(m, args.output);
  request.output = args.output;
  return request;
}

void Run(const Args& args) {
  const Model model = LoadModel(args.file, args.sets);
  const plot::SchemeRequest request = ReadRequest(args, model);
  const plot::SchemeDrawing drawing = Checked([&] { return plot::DrawSchemeOf(model, request); });
  if (drawing.status == plot::PlotStatus::kFailed) {
    Complain(args.file + ": " + drawing.message);
    throw Exit{kExitFailed};
  }
  if (args.deadcentres && !request.dead_centres) ResolveScalarOutput(model.mechanism(), args.output, "--output", args.file);  // Exit{2}
  WriteOutput(args.out, drawing.svg);
  if (!drawing.problems.empty()) {
    for (const std::string& p : drawing.problems) Complain(args.file + ": " + p);
    throw Exit{kExitFailed};
  }
}

}  // namespace
}  // namespace draw_command

void AddDrawCommand(CLI::App& app) {
  using namespace draw_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "draw",
      "The kinematic scheme as SVG at one input: frame pivots hatched, revolute joints as circles, sliders as\n"
      "blocks on their guides, binary links as bars, ternary links as polygons, point labels, the drive arrow.\n"
      "--deadcentres overlays the poses at the dead centres of an output (A_a, B_a extended; A_i, B_i folded),\n"
      "--trace K draws the coupler curve of K over the sweep. The pose is solved from the file's assembly branch.\n"
      "Example: koppel draw catalog/entries/slider-crank-offset.yaml --at 120 --deadcentres -o scheme.svg");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--at", args->at, "Input of the pose drawn [deg for an R drive] (default: the assembly hint's input)");
  cmd->add_flag("--deadcentres", args->deadcentres, "Overlay the dead-centre poses");
  cmd->add_option("--output", args->output, "Output whose dead centres are drawn (default: the first scalar output)");
  cmd->add_option("--trace", args->trace, "Draw the coupler curve of this point (K, link.point)");
  cmd->add_option("--from", args->from, "First input of the sweep (default: the file's sweep)");
  cmd->add_option("--to", args->to, "Last input of the sweep (default: the file's sweep)");
  cmd->add_option("--step", args->step, "Input step of the sweep (default: the file's sweep)");
  AddBranchPointOption(cmd, args->at_branch_point);
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write the SVG to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
