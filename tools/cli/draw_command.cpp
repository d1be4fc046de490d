// koppel draw: the kinematic scheme at one input, optionally with both dead-centre poses
// (seed 000 "Bild 3") and a traced coupler curve.
#include "commands.hpp"
#include "common.hpp"
#include "sweep_report.hpp"

#include "koppel/analysis/coupler_curve.hpp"
#include "koppel/analysis/dead_centres.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/plot/sampled_run.hpp"
#include "koppel/plot/scheme.hpp"

#include <fmt/format.h>

namespace koppel::cli {
namespace draw_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, at, trace, output, from, to, step, at_branch_point;
  std::vector<std::string> sets;
  bool deadcentres = false;
  std::string out;
};

// --deadcentres: the dead-centre poses of --output drawn over the scheme, named in the caption;
// what cannot be drawn goes to `problems`.
void AddDeadCentres(const Args& args, const Mechanism& m, const plot::SampledRun& run, const SweepOptions& range,
                    plot::SchemeScene& scene, std::vector<std::string>& problems) {
  const bool angle = m.InputIsAngle();
  auto in = [&](double v) { return angle ? DegToRad(v) : v; };
  auto shown = [&](double v) { return angle ? RadToDeg(v) : v; };
  const std::string input_name = m.drive.input_name == "phi" ? "φ" : m.drive.input_name, unit = angle ? "°" : "";
  const int output = ResolveScalarOutput(m, args.output, "--output", args.file);
  SweepOptions search = range;
  search.step = in(1.0) < std::abs(range.step) ? in(1.0) : range.step;  // the search resolution of `deadcentres`
  const DeadCentreReport dead = FindDeadCentres(m, output, 0, search);
  if (!dead.sweep.complete()) problems.push_back("dead centres: " + dead.sweep.message);
  int unnamed = 0;
  std::string list;
  for (const DeadCentre& d : dead.points) {
    plot::OverlayPose overlay;
    overlay.suffix = d.kind == DeadCentreKind::kExtended ? "a" : d.kind == DeadCentreKind::kFolded ? "i" : std::to_string(++unnamed);
    const Expected<Eigen::VectorXd> dead_pose = plot::PoseAt(m, run, d.input);
    if (!dead_pose) {
      problems.push_back("dead centre at " + fmt::format("{:g}", shown(d.input)) + ": " + dead_pose.error());
      continue;
    }
    overlay.q = *dead_pose;
    list += fmt::format("{}{}_{} = {:.2f}{}", list.empty() ? "" : ", ", input_name, overlay.suffix, shown(d.input), unit);
    scene.overlays.push_back(std::move(overlay));
  }
  if (dead.points.empty()) problems.push_back("no dead centre of '" + m.outputs[output].name + "' found");
  if (!list.empty()) scene.caption += "; dead centres of " + m.outputs[output].name + ": " + list;
}

void Run(const Args& args) {
  const MechanismFile file = LoadMechanism(args.file, args.sets);
  const Mechanism& m = file.mechanism;
  const bool angle = m.InputIsAngle();
  auto in = [&](double v) { return angle ? DegToRad(v) : v; };
  auto shown = [&](double v) { return angle ? RadToDeg(v) : v; };
  SweepOptions range;
  range.from = in(args.from.empty() ? file.sweep.from : ParseNumberFlag("--from", args.from));
  range.to = in(args.to.empty() ? file.sweep.to : ParseNumberFlag("--to", args.to));
  range.step = in(args.step.empty() ? file.sweep.step : ParseNumberFlag("--step", args.step));
  range.order = 0;
  range.continuation.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  if (range.step == 0 || SampleCount(range.from, range.to, range.step) > 20001) {
    Complain("--step must not be 0 (and give at most 20000 samples)");
    throw Exit{kExitBadInput};
  }
  // one sweep for the view, the guides' lengths, the trace and the poses' starting points
  const Mechanism traced = args.trace.empty() ? m : WithPointOutput(m, ResolvePoint(m, args.trace, "--trace"));
  const plot::SampledRun run = plot::SampleMechanism(traced, range);
  if (run.size() == 0) {
    Complain(args.file + ": " + run.message);
    throw Exit{kExitFailed};
  }
  std::vector<std::string> problems;
  if (!run.complete) problems.push_back(run.message);
  const std::string input_name = m.drive.input_name == "phi" ? "φ" : m.drive.input_name, unit = angle ? "°" : "";
  plot::SchemeScene scene;
  const double at = args.at.empty() ? m.hint.input : in(ParseNumberFlag("--at", args.at));
  const Expected<Eigen::VectorXd> pose = plot::PoseAt(m, run, at);
  if (!pose) {
    Complain(args.file + ": cannot reach " + input_name + " = " + fmt::format("{:g}", shown(at)) + ": " + pose.error());
    throw Exit{kExitFailed};
  }
  scene.q = *pose;
  scene.caption = fmt::format("{}: {} = {:.2f}{}", m.name, input_name, shown(at), unit);
  for (int i = 0; i < run.size(); ++i) scene.extent.push_back(run.poses.row(i).transpose());
  if (!args.trace.empty()) {
    for (const plot::Stretch& s : run.stretches) {
      scene.trace.emplace_back();
      for (int i = s.begin; i < s.end; ++i) scene.trace.back().emplace_back(run.outputs(i, 0), run.outputs(i, 1));
    }
    scene.trace_name = args.trace;
  }
  if (args.deadcentres) AddDeadCentres(args, m, run, range, scene, problems);
  WriteOutput(args.out, plot::DrawScheme(m, scene));
  if (!problems.empty()) {
    for (const std::string& p : problems) Complain(args.file + ": " + p);
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
