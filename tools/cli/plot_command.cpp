// koppel plot: the documents' figures as SVG — transfer functions (--transfer), the transmission
// angle (--mu), the coupler curve and its straight-line stretch (--curve, --straight) — and the
// design charts of `koppel synth chart` (a .csv file).
#include "commands.hpp"
#include "common.hpp"
#include "sweep_report.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/input_file.hpp"
#include "koppel/plot/forces_plot.hpp"
#include "koppel/plot/plots.hpp"


namespace koppel::cli {
namespace {

struct Args {
  std::string file, transfer, curve, from, to, step, at, qg = "0.005", at_branch_point;
  std::vector<std::string> sets;
  int order = 2;
  bool mu = false, straight = false;
  bool forces = false;                 // --forces [--speed RPM] [--joint J ...]: forces_plot.hpp
  std::string speed;
  std::vector<std::string> joints;
  std::string out;
};

// Writes the picture (also a partial one: what was computed is shown), then exits as the
// result says.
void Finish(const Args& args, const plot::PlotResult& r) {
  if (r.status == plot::PlotStatus::kFailed) {
    Complain(args.file + ": " + r.message);
    throw Exit{kExitFailed};
  }
  WriteOutput(args.out, r.svg);
  if (r.status == plot::PlotStatus::kPartial) {
    Complain(args.file + ": " + r.message + " (the picture shows what was computed)");
    throw Exit{kExitFailed};
  }
}

void RunChart(const Args& args) {
  const plot::PlotResult r = plot::ChartPlot(io::ReadInputFile(args.file), args.file);
  if (r.status == plot::PlotStatus::kFailed) {
    Complain(r.message);
    throw Exit{kExitBadInput};
  }
  WriteOutput(args.out, r.svg);
}

void RunForcesPlot(const Args& args, const MechanismFile& file, const SweepOptions& range) {
  const Mechanism& m = file.mechanism;
  plot::ForcesPlotOptions options;
  options.forces.sweep = range;
  if (!args.speed.empty()) options.forces.speed = ParseNumberFlag("--speed", args.speed) * (m.InputIsAngle() ? kPi / 30 : 1.0);
  for (const std::string& name : args.joints) {
    options.joints.push_back(m.FindJoint(name));
    if (options.joints.back() < 0) {
      Complain("--joint: no joint '" + name + "'");
      throw Exit{kExitBadInput};
    }
  }
  std::string why;
  if (!options.IsValid(m, &why)) {
    Complain(why);
    throw Exit{kExitBadInput};
  }
  Finish(args, plot::ForcesPlot(m, file.loads, options));
}

void Run(const Args& args) {
  const bool csv = args.file.size() > 4 && args.file.substr(args.file.size() - 4) == ".csv";
  const int kinds = !args.transfer.empty() + args.mu + !args.curve.empty() + args.forces;
  if (csv) {
    if (kinds != 0) {
      Complain("a design chart (.csv) takes no --transfer, --mu or --curve");
      throw Exit{kExitBadInput};
    }
    RunChart(args);
    return;
  }
  if (kinds != 1) {
    Complain("say what to plot: exactly one of --transfer OUTPUT, --mu, --curve POINT, --forces (or give a chart .csv)");
    throw Exit{kExitBadInput};
  }
  const MechanismFile file = LoadMechanism(args.file, args.sets);
  const Mechanism& m = file.mechanism;
  auto in = [&](double v) { return m.InputIsAngle() ? DegToRad(v) : v; };
  SweepOptions range;
  range.from = in(args.from.empty() ? file.sweep.from : ParseNumberFlag("--from", args.from));
  range.to = in(args.to.empty() ? file.sweep.to : ParseNumberFlag("--to", args.to));
  range.step = in(args.step.empty() ? file.sweep.step : ParseNumberFlag("--step", args.step));
  range.continuation.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  std::string why;
  if (!args.transfer.empty()) {
    plot::TransferPlotOptions options;
    options.output = m.FindOutput(args.transfer);
    if (options.output < 0) options.output = ResolveScalarOutput(m, args.transfer, "--transfer", args.file);  // exits 2 with the candidates
    options.order = args.order;
    options.range = range;
    if (!options.IsValid(m, &why)) {
      Complain(why);
      throw Exit{kExitBadInput};
    }
    Finish(args, plot::TransferPlot(m, options));
  } else if (args.forces) {
    RunForcesPlot(args, file, range);
  } else if (args.mu) {
    plot::MuPlotOptions options;
    for (int o = 0; o < static_cast<int>(m.outputs.size()) && options.output < 0; ++o)
      if (m.outputs[o].kind == OutputKind::kTransmissionAngle) options.output = o;
    options.range = range;
    if (!options.IsValid(m, &why)) {
      Complain(args.file + ": " + why);
      throw Exit{kExitBadInput};
    }
    Finish(args, plot::MuPlot(m, options));
  } else {
    plot::CurvePlotOptions options;
    options.point = ResolvePoint(m, args.curve, "--curve");
    options.range = range;
    options.straight = args.straight;
    options.qg = ParseNumberFlag("--qg", args.qg);
    if (!args.at.empty()) options.reference = DegToRad(ParseNumberFlag("--at", args.at));
    if (!options.IsValid(m, &why)) {
      Complain(why);
      throw Exit{kExitBadInput};
    }
    Finish(args, plot::CurvePlot(m, options));
  }
}

}  // namespace

void AddPlotCommand(CLI::App& app) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "plot",
      "The documents' figures as SVG, drawn from the solver's numbers of this run:\n"
      "  --transfer OUTPUT [--order N]  the output and its transfer functions up to order N (default 2), one panel\n"
      "                                 each over the input, dead centres marked (phi_a extended, phi_i folded)\n"
      "  --mu                           the transmission angle over the input, mu_min marked\n"
      "  --curve POINT [--straight]     the coupler curve to scale; --straight adds the stretch K_A..K_E with\n"
      "                                 Q_G <= --qg through K_I (--at), the tangent g and a panel with the band\n"
      "  --forces [--speed RPM] [--joint J ...]  the drive torque over the input (koppel forces) and each joint's\n"
      "                                 reaction as a polar diagram (the force on its second link, frame axes)\n"
      "  CHART.csv                      a design chart written by `koppel synth chart`\n"
      "Where the solver stops (a dead centre of the drive, the end of the assemblable range) the curves end and the\n"
      "rest is shaded: the picture is written and the exit code is 1.\n"
      "Example: koppel plot catalog/entries/slider-crank-offset.yaml --transfer s -o transfer.svg");
  cmd->add_option("file", args->file, "Mechanism YAML file, or a design chart CSV")->required();
  cmd->add_option("--transfer", args->transfer, "Plot this output and its transfer functions");
  cmd->add_option("--order", args->order, "Highest order for --transfer (default 2)");
  cmd->add_flag("--mu", args->mu, "Plot the transmission angle (the file's first transmission output)");
  cmd->add_option("--curve", args->curve, "Plot the coupler curve of this point (K, link.point)");
  cmd->add_flag("--straight", args->straight, "With --curve: the straight-line stretch and its band");
  cmd->add_option("--qg", args->qg, "With --straight: allowed Q_G = delta_y/L (default 0.005)");
  cmd->add_option("--at", args->at, "With --straight: input of the reference point K_I [deg] (default: least curvature)");
  cmd->add_flag("--forces", args->forces, "Plot the drive torque and, with --joint, polar diagrams of joint forces");
  cmd->add_option("--speed", args->speed, "With --forces: constant drive speed [rpm] (kinetostatics)");
  cmd->add_option("--joint", args->joints, "With --forces: a joint whose reaction is drawn as a polar diagram (repeatable)");
  cmd->add_option("--from", args->from, "First input (default: the file's sweep)");
  cmd->add_option("--to", args->to, "Last input (default: the file's sweep)");
  cmd->add_option("--step", args->step, "Input step (default: the file's sweep)");
  AddBranchPointOption(cmd, args->at_branch_point);
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write the SVG to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
