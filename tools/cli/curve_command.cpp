// koppel curve: the coupler curve of a point, with arc length and curvature; --straight adds
// the straight-line analysis (Geradführung) of seed 003.
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"
#include "sweep_report.hpp"

#include "koppel/api/coupler_curve.hpp"
#include "koppel/core/angles.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

namespace koppel::cli {
namespace curve_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, point, from, to, step, at, qg = "0.005", stretch, resolution = "0.02", at_branch_point;
  std::vector<std::string> sets;
  bool straight = false;
  std::string format = "csv", out;
};

// The curve of `point` over --from/--to/--step: position, tangent, arc length, curvature.
void RunTrace(const Args& args, const Model& model, const CouplerCurveRequest& base) {
  const bool angle = model.input_is_angle();
  auto in = [&](double v) { return angle ? DegToRad(v) : v; };
  CouplerCurveRequest request = base;
  if (!args.from.empty()) request.from = ParseNumberFlag("--from", args.from);
  if (!args.to.empty()) request.to = ParseNumberFlag("--to", args.to);
  if (!args.step.empty()) request.step = ParseNumberFlag("--step", args.step);
  const SweepSpan span = model.Span(request.from, request.to, request.step);
  CheckSampleCount(in(span.from), in(span.to), in(span.step), "--from/--to/--step");
  if (std::string why; !request.IsValid(model, &why)) {
    Complain("--from/--to/--step: " + why);
    throw Exit{kExitBadInput};
  }
  const CouplerCurveTable c = TraceCouplerCurve(model, request);
  Table t;
  t.columns = {model.input_name(), "x", "y", "dx", "dy", "arc", "curvature", "singular"};
  for (size_t i = 0; i < c.inputs.size(); ++i)
    t.rows.push_back({c.inputs[i], c.points[i].x, c.points[i].y, c.d1[i].x, c.d1[i].y, c.arc_length[i], c.curvature[i],
                      c.singular[i] ? 1.0 : 0.0});
  if (args.format == "json") {
    nlohmann::json j = t.ToJson();
    j["mechanism"] = model.name();
    j["point"] = c.point;
    j["complete"] = c.sweep.complete();
    j.update(SweepEventsJson(c.sweep));
    if (!c.sweep.complete()) j["message"] = c.sweep.message;
    WriteOutput(args.out, JsonText(j));
  } else {
    WriteOutput(args.out, t.ToCsv());
  }
  ReportSweep(args.file, model, c.sweep);
  if (!c.sweep.complete()) throw Exit{kExitFailed};
}

// --stretch A:E [deg]; Exit{2} unless it has that form and a reference point --at.
std::pair<double, double> ParseStretch(const Args& args) {
  const auto colon = args.stretch.find(':');
  if (colon == std::string::npos || args.at.empty()) {
    Complain("--stretch A:E needs the form A:E (degrees) and a reference point --at");
    throw Exit{kExitBadInput};
  }
  const double a = ParseNumberFlag("--stretch", args.stretch.substr(0, colon)), e = ParseNumberFlag("--stretch", args.stretch.substr(colon + 1));
  if (std::string why; !StraightStretchIsValid(a, e, &why)) {
    Complain("--stretch: " + why);
    throw Exit{kExitBadInput};
  }
  return {a, e};
}

// The flags of --straight, checked as the search's own rules, each naming its flag.
StraightLineRequest ReadStraight(const Args& args, const Model& model, const CouplerCurveRequest& base) {
  if (!model.input_is_angle()) {
    Complain("--straight needs a rotating drive (an R joint)");
    throw Exit{kExitBadInput};
  }
  StraightLineRequest request;
  request.point = base.point;
  request.at_branch_point = base.at_branch_point;
  request.resolution = ParseNumberFlag("--resolution", args.resolution);
  const double resolution = DegToRad(request.resolution);
  if (resolution <= 0) {
    Complain("--resolution must be positive");
    throw Exit{kExitBadInput};
  }
  if (!args.at.empty()) request.at = ParseNumberFlag("--at", args.at);
  const double reference = request.at ? DegToRad(*request.at) : 0.0;
  CheckSampleCount(reference - kPi, reference + kPi, resolution, "--at/--resolution", kStraightSearchSamples);
  if (!args.stretch.empty()) {
    std::tie(request.stretch_a, request.stretch_e) = ParseStretch(args);
    const double a = DegToRad(*request.stretch_a), e = DegToRad(*request.stretch_e);
    CheckSampleCount(std::min({a, e, reference}), std::max({a, e, reference}), resolution, "--stretch/--at/--resolution");
  } else {
    request.qg = ParseNumberFlag("--qg", args.qg);
    if (request.qg <= 0) {
      Complain("--qg must be positive");
      throw Exit{kExitBadInput};
    }
  }
  return request;
}

// --straight: the longest stretch within --qg (or the band of --stretch A:E) about --at.
void RunStraight(const Args& args, const Model& model, const CouplerCurveRequest& base) {
  const StraightLine s = FindStraightLine(model, ReadStraight(args, model, base));
  if (!s.ok()) {
    Complain(args.file + ": " + s.message);
    throw Exit{kExitFailed};
  }
  const std::string input = model.input_name(), length = model.length_unit();
  Summary sum;
  sum.Add(input + "_I", s.reference, "deg");
  sum.Add("K_I_x", s.reference_point.x, length);
  sum.Add("K_I_y", s.reference_point.y, length);
  sum.Add("tangent_angle", s.tangent_angle, "deg");
  sum.Add(input + "_A", s.phi_a, "deg");
  sum.Add(input + "_E", s.phi_e, "deg");
  sum.Add(input + "_G", s.phi_g, "deg");
  sum.Add("L", s.length, length);
  sum.Add("delta_y", s.band, length);
  sum.Add("Q_G", s.qg, "1");
  WriteOutput(args.out, args.format == "json" ? JsonText(sum.ToJson()) : sum.ToCsv());
}

void Run(const Args& args) {
  CheckFormat(args.format);
  const Model model = LoadModel(args.file, args.sets);
  CouplerCurveRequest request;
  request.point = ResolvePoint(model.mechanism(), args.point, "--point");
  request.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  if (args.straight) {
    RunStraight(args, model, request);
  } else {
    RunTrace(args, model, request);
  }
}

}  // namespace
}  // namespace curve_command

void AddCurveCommand(CLI::App& app) {
  using namespace curve_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "curve",
      "The coupler curve (Koppelkurve) of a point: x, y, dx/dinput, dy/dinput, arc length from the first row, and\n"
      "the signed curvature, over the sweep, and the singular flag of `analyze` (1 at a singular position). The\n"
      "sweep follows the assembly branch like `analyze`; gaps of the drivable range are named and give exit 1.\n"
      "--straight: straight-line guidance (Geradführung) as in the Meyer zur Capellen description. The tangent g at the\n"
      "reference point K_I (--at, default: the point of least curvature); Δy is the width of the band parallel to g that\n"
      "holds the stretch K_A..K_E, L its extent along g, Q_G = Δy/L. With --qg the longest stretch through K_I with\n"
      "Q_G <= qg (every end point is tried: Q_G is not monotonic); with --stretch A:E the band of that stretch.\n"
      "Prints phi_I, K_I, the tangent's angle, phi_A, phi_E, phi_G = phi_E - phi_A, L, delta_y, Q_G, in the document's\n"
      "convention whatever --at is: phi_I and phi_A in [0, 360), phi_E = phi_A + phi_G (beyond 360 only for a stretch\n"
      "through 0).\n"
      "Example: koppel curve catalog/entries/mzc-crank-rocker.yaml --point K --straight --qg 0.005 --at 180");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--point", args->point, "The point: a point output (K), link.point, or a point name")->required();
  cmd->add_option("--from", args->from, "First input (default: the file's sweep)");
  cmd->add_option("--to", args->to, "Last input (default: the file's sweep)");
  cmd->add_option("--step", args->step, "Input step (default: the file's sweep)");
  cmd->add_flag("--straight", args->straight, "Straight-line analysis instead of the curve table");
  cmd->add_option("--qg", args->qg, "Allowed Q_G = delta_y/L for --straight (default 0.005)");
  cmd->add_option("--at", args->at, "Input of the reference point K_I [deg] (default: least curvature)");
  cmd->add_option("--stretch", args->stretch, "A:E — measure this stretch [deg] instead of searching");
  cmd->add_option("--resolution", args->resolution, "Input resolution of the search [deg] (default 0.02)");
  AddBranchPointOption(cmd, args->at_branch_point);
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  cmd->add_option("--format", args->format, "csv (default) or json");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
