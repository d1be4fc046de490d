// koppel curve: the coupler curve of a point, with arc length and curvature; --straight adds
// the straight-line analysis (Geradführung) of seed 003.
#include "commands.hpp"
#include "common.hpp"
#include "sweep_report.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/analysis/coupler_curve.hpp"

#include <algorithm>

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
void RunTrace(const Args& args, const MechanismFile& file, const PointRef& point, const ContinuationOptions& continuation) {
  const Mechanism& m = file.mechanism;
  const bool angle = m.InputIsAngle();
  auto in = [&](double v) { return angle ? DegToRad(v) : v; };
  auto shown = [&](double v) { return angle ? RadToDeg(v) : v; };
  SweepOptions range;
  range.continuation = continuation;
  range.from = in(args.from.empty() ? file.sweep.from : ParseNumberFlag("--from", args.from));
  range.to = in(args.to.empty() ? file.sweep.to : ParseNumberFlag("--to", args.to));
  range.step = in(args.step.empty() ? file.sweep.step : ParseNumberFlag("--step", args.step));
  std::string why;
  CheckSampleCount(range.from, range.to, range.step, "--from/--to/--step");
  if (!range.IsValid(&why)) {
    Complain("--from/--to/--step: " + why);
    throw Exit{kExitBadInput};
  }
  const CouplerCurve c = TraceCurve(m, point, range);
  Table t;
  t.columns = {m.drive.input_name, "x", "y", "dx", "dy", "arc", "curvature", "singular"};
  for (size_t i = 0; i < c.inputs.size(); ++i)
    t.rows.push_back({shown(c.inputs[i]), c.points[i].x(), c.points[i].y(), c.d1[i].x(), c.d1[i].y(), c.arc_length[i], c.curvature[i],
                      static_cast<double>(c.singular[i])});
  if (args.format == "json") {
    nlohmann::json j = t.ToJson();
    j["mechanism"] = m.name;
    j["point"] = m.links[point.link].name + "." + m.links[point.link].points[point.point].name;
    j["complete"] = c.sweep.complete();
    j.update(SweepEventsJson(m, c.sweep));
    if (!c.sweep.complete()) j["message"] = c.sweep.message;
    WriteOutput(args.out, JsonText(j));
  } else {
    WriteOutput(args.out, t.ToCsv());
  }
  ReportSweep(args.file, m, c.sweep);
  if (!c.sweep.complete()) throw Exit{kExitFailed};
}

// --straight: the longest stretch within --qg (or the band of --stretch A:E) about --at.
void RunStraight(const Args& args, const MechanismFile& file, const PointRef& point, const ContinuationOptions& continuation) {
  const Mechanism& m = file.mechanism;
  const bool angle = m.InputIsAngle();
  if (!angle) {
    Complain("--straight needs a rotating drive (an R joint)");
    throw Exit{kExitBadInput};
  }
  const double resolution = DegToRad(ParseNumberFlag("--resolution", args.resolution));
  if (resolution <= 0) {
    Complain("--resolution must be positive");
    throw Exit{kExitBadInput};
  }
  std::optional<double> reference;
  if (!args.at.empty()) reference = DegToRad(ParseNumberFlag("--at", args.at));
  CheckSampleCount(reference.value_or(0) - kPi, reference.value_or(0) + kPi, resolution, "--at/--resolution", kStraightSearchSamples);
  StraightStretch s;
  if (!args.stretch.empty()) {
    const auto colon = args.stretch.find(':');
    if (colon == std::string::npos || !reference) {
      Complain("--stretch A:E needs the form A:E (degrees) and a reference point --at");
      throw Exit{kExitBadInput};
    }
    const double a = DegToRad(ParseNumberFlag("--stretch", args.stretch.substr(0, colon))),
                 e = DegToRad(ParseNumberFlag("--stretch", args.stretch.substr(colon + 1)));
    if (std::string why; !StretchIsValid(a, e, &why)) {
      Complain("--stretch: " + why);
      throw Exit{kExitBadInput};
    }
    CheckSampleCount(std::min({a, e, *reference}), std::max({a, e, *reference}), resolution, "--stretch/--at/--resolution");
    s = StretchBand(m, point, *reference, a, e, resolution, continuation);
  } else {
    const double qg = ParseNumberFlag("--qg", args.qg);
    if (qg <= 0) {
      Complain("--qg must be positive");
      throw Exit{kExitBadInput};
    }
    s = LongestStraightStretch(m, point, qg, reference, kPi, resolution, continuation);
  }
  if (!s.ok()) {
    Complain(args.file + ": " + s.message);
    throw Exit{kExitFailed};
  }
  Summary sum;
  sum.Add(m.drive.input_name + "_I", RadToDeg(s.reference), "deg");
  sum.Add("K_I_x", s.reference_point.x(), file.loads.LengthUnit());
  sum.Add("K_I_y", s.reference_point.y(), file.loads.LengthUnit());
  sum.Add("tangent_angle", RadToDeg(std::atan2(s.tangent.y(), s.tangent.x())), "deg");
  sum.Add(m.drive.input_name + "_A", RadToDeg(s.phi_a), "deg");
  sum.Add(m.drive.input_name + "_E", RadToDeg(s.phi_e), "deg");
  sum.Add(m.drive.input_name + "_G", RadToDeg(s.phi_g), "deg");
  sum.Add("L", s.length, file.loads.LengthUnit());
  sum.Add("delta_y", s.band, file.loads.LengthUnit());
  sum.Add("Q_G", s.qg, "1");
  WriteOutput(args.out, args.format == "json" ? JsonText(sum.ToJson()) : sum.ToCsv());
}

void Run(const Args& args) {
  CheckFormat(args.format);
  const MechanismFile file = LoadMechanism(args.file, args.sets);
  const PointRef point = ResolvePoint(file.mechanism, args.point, "--point");
  ContinuationOptions continuation;
  continuation.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  if (args.straight) {
    RunStraight(args, file, point, continuation);
  } else {
    RunTrace(args, file, point, continuation);
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
