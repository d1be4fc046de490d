// koppel plot: the documents' figures as SVG — transfer functions (--transfer), the transmission
// angle (--mu), the coupler curve and its straight-line stretch (--curve, --straight) — and the
// design charts of `koppel synth chart` (a .csv file).
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"
#include "sweep_report.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/input_file.hpp"
#include "koppel/plot/forces_plot.hpp"
#include "koppel/plot/plots.hpp"

#include <cmath>


namespace koppel::cli {
namespace plot_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, transfer, curve, from, to, step, at, qg = "0.005", at_branch_point;
  std::vector<std::string> sets;
  int order = 2;
  bool mu = false, straight = false;
  bool forces = false;                 // --forces [--speed RPM] [--joint J ...]: forces_plot.hpp
  std::string speed;
  std::vector<std::string> joints;
  // --tolerance OUTPUT --tol NAME=T ... [--clearance JOINT=c ...] [--samples N --seed S --distribution D]
  std::string tolerance, distribution = "uniform";
  std::vector<std::string> tols, clearances;
  std::string samples = "0", seed = "1";
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

void RunForcesPlot(const Args& args, const Model& model, const SweepOptions& range) {
  const Mechanism& m = model.mechanism();
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
  Finish(args, plot::ForcesPlot(m, model.loads(), options));
}

// --from/--to/--step, the file's sweep for what is not given (Model::Span).
SweepSpan SpanOf(const Args& args, const Model& model) {
  return model.Span(OptionalNumberFlag("--from", args.from), OptionalNumberFlag("--to", args.to), OptionalNumberFlag("--step", args.step));
}

// The band of koppel tolerance over the range (Model::Tolerances), drawn by plot::TolerancePlot.
void RunTolerancePlot(const Args& args, const Model& model) {
  ToleranceRequest request;
  request.output = args.tolerance;
  const SweepSpan span = SpanOf(args, model);
  const double from = span.from, to = span.to, step = span.step;
  CheckSampleCount(from, to, step, "--from/--to/--step");
  const long n = static_cast<long>(std::floor(std::abs(to - from) / std::abs(step) + 1e-9)) + 1;
  for (long i = 0; i < n; ++i) request.inputs.push_back(from + i * (to >= from ? std::abs(step) : -std::abs(step)));
  for (const std::string& t : args.tols) request.tolerances.push_back(NamedNumber("--tol", t));
  for (const std::string& c : args.clearances) request.clearances.push_back(NamedNumber("--clearance", c));
  request.samples = ParseCountFlag("--samples", args.samples, 0, kMaxToleranceSamples);
  CheckCount(static_cast<double>(request.samples) * static_cast<double>(n), "--samples and --from/--to/--step", kToleranceValues);
  request.seed = static_cast<std::uint64_t>(ParseCountFlag("--seed", args.seed, 0, kMaxSeed));
  request.distribution = args.distribution;
  const ToleranceResult r = Checked([&] { return model.Tolerances(request); });
  plot::ToleranceBand band;
  band.mechanism = model.name();
  band.output = r.output;
  band.output_unit = r.unit;
  band.input_label = model.input_name() == "phi" ? "φ [deg]" : model.input_name() + " [" + r.input_unit + "]";
  band.input_degrees = model.input_is_angle();
  band.names = r.parameters;
  for (const std::string& j : r.joints) band.names.push_back("clearance " + j);
  band.shares.resize(band.names.size());
  for (const ToleranceRowReport& row : r.rows) {
    band.inputs.push_back(row.input);
    band.ok.push_back(row.ok);
    band.nominal.push_back(row.nominal);
    band.worst_case.push_back(row.worst_case + row.clearance_worst_case);
    if (r.samples > 0) {
      band.mc_min.push_back(row.mc_samples > 0 ? row.mc_min : row.nominal);
      band.mc_max.push_back(row.mc_samples > 0 ? row.mc_max : row.nominal);
    }
    for (size_t j = 0; j < band.names.size(); ++j) band.shares[j].push_back(row.ok ? row.share[j] : 0.0);
  }
  plot::PlotResult picture = plot::TolerancePlot(band);
  if (picture.status == plot::PlotStatus::kComplete && r.status != AnalysisStatus::kComplete) {
    picture.status = plot::PlotStatus::kPartial;
    picture.message = r.message;
  }
  Finish(args, picture);
}

// --from/--to/--step (else the file's sweep) and --at-branch-point, as the plot's range.
SweepOptions RangeOf(const Args& args, const Model& model) {
  auto in = [&](double v) { return model.input_is_angle() ? DegToRad(v) : v; };
  const SweepSpan span = SpanOf(args, model);
  SweepOptions range;
  range.from = in(span.from);
  range.to = in(span.to);
  range.step = in(span.step);
  range.continuation.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  return range;
}

// The transmission angle over the range: the file's first transmission-angle output.
void RunMuPlot(const Args& args, const Mechanism& m, const SweepOptions& range) {
  plot::MuPlotOptions options;
  for (int o = 0; o < static_cast<int>(m.outputs.size()) && options.output < 0; ++o)
    if (m.outputs[o].kind == OutputKind::kTransmissionAngle) options.output = o;
  options.range = range;
  std::string why;
  if (!options.IsValid(m, &why)) {
    Complain(args.file + ": " + why);
    throw Exit{kExitBadInput};
  }
  Finish(args, plot::MuPlot(m, options));
}

void Run(const Args& args) {
  const bool csv = args.file.size() > 4 && args.file.substr(args.file.size() - 4) == ".csv";
  const int kinds = !args.transfer.empty() + args.mu + !args.curve.empty() + args.forces + !args.tolerance.empty();
  if (csv) {
    if (kinds != 0) {
      Complain("a design chart (.csv) takes no --transfer, --mu or --curve");
      throw Exit{kExitBadInput};
    }
    RunChart(args);
    return;
  }
  if (kinds != 1) {
    Complain("say what to plot: exactly one of --transfer OUTPUT, --mu, --curve POINT, --forces, --tolerance OUTPUT (or give a chart .csv)");
    throw Exit{kExitBadInput};
  }
  const Model model = LoadModel(args.file, args.sets);
  const Mechanism& m = model.mechanism();
  const SweepOptions range = RangeOf(args, model);
  std::string why;
  if (!args.transfer.empty()) {
    plot::TransferPlotOptions options;
    options.output = m.FindOutput(args.transfer);
    if (options.output < 0) options.output = ResolveScalarOutput(m, args.transfer, "--transfer", args.file);  // exits 2 with the candidates
    options.order = args.order;
    options.range = range;
    options.length_unit = model.length_unit();
    if (!options.IsValid(m, &why)) {
      Complain(why);
      throw Exit{kExitBadInput};
    }
    Finish(args, plot::TransferPlot(m, options));
  } else if (args.forces) {
    RunForcesPlot(args, model, range);
  } else if (!args.tolerance.empty()) {
    RunTolerancePlot(args, model);
  } else if (args.mu) {
    RunMuPlot(args, m, range);
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
}  // namespace plot_command

void AddPlotCommand(CLI::App& app) {
  using namespace plot_command;
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
      "  --tolerance OUTPUT --tol NAME=T ... [--clearance JOINT=c ...] [--samples N]  the output over the input\n"
      "                                 in its linear worst-case band (koppel tolerance), the Monte Carlo min and\n"
      "                                 max dashed, and each tolerance's share of the variance below\n"
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
  cmd->add_option("--tolerance", args->tolerance, "Plot the tolerance band of this output (s, or K_x / K_y)");
  cmd->add_option("--tol", args->tols, "With --tolerance: a parameter's tolerance NAME=T (repeatable)");
  cmd->add_option("--clearance", args->clearances, "With --tolerance: a revolute joint's play JOINT=c (repeatable)");
  cmd->add_option("--samples", args->samples, "With --tolerance: Monte Carlo samples per input (default 0)");
  cmd->add_option("--seed", args->seed, "With --tolerance: Monte Carlo seed (default 1)");
  cmd->add_option("--distribution", args->distribution, "With --tolerance: uniform (default) or normal (T = 3 sigma)");
  cmd->add_option("--from", args->from, "First input (default: the file's sweep)");
  cmd->add_option("--to", args->to, "Last input (default: the file's sweep)");
  cmd->add_option("--step", args->step, "Input step (default: the file's sweep)");
  AddBranchPointOption(cmd, args->at_branch_point);
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write the SVG to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
