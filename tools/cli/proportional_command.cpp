// koppel proportional: proportionality deviation of an output over an input range (seed 001).
#include "commands.hpp"
#include "common.hpp"
#include "sweep_report.hpp"

#include "koppel/core/structure.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/analysis/proportionality.hpp"

namespace koppel::cli {
namespace proportional_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, output, from, to, at, length, resolution = "0.05", at_branch_point;
  std::vector<std::string> sets;
  std::string format = "csv", out;
};

void Run(const Args& args) {
  CheckFormat(args.format);
  const MechanismFile file = LoadMechanism(args.file, args.sets);
  const Mechanism& m = file.mechanism;
  const int output = ResolveScalarOutput(m, args.output, "--output", args.file);
  const bool angle = m.InputIsAngle();
  auto in = [&](double v) { return angle ? DegToRad(v) : v; };
  const double from = in(ParseNumberFlag("--from", args.from)), to = in(ParseNumberFlag("--to", args.to));
  const double length = args.length.empty() ? CrankLength(m) : ParseNumberFlag("--length", args.length);
  if (length <= 0 || from == to) {
    Complain(length <= 0 ? "no reference length: give --length" : "--from and --to must differ");
    throw Exit{kExitBadInput};
  }
  std::optional<double> at;
  if (!args.at.empty()) at = in(ParseNumberFlag("--at", args.at));
  ContinuationOptions continuation;
  continuation.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  const double resolution = in(ParseNumberFlag("--resolution", args.resolution));
  CheckSampleCount(from, to, resolution, "--from/--to/--resolution");
  SweepOptions check;
  check.from = from;
  check.to = to;
  check.step = resolution;
  std::string why;
  if (!check.IsValid(&why)) {
    Complain("--from/--to/--resolution: " + why);
    throw Exit{kExitBadInput};
  }
  const Proportionality p = ProportionalityDeviation(m, output, from, to, length, at, resolution, continuation);
  if (!Usable(p.status)) {
    ReportSweep(args.file, m, p.sweep);
    Complain(args.file + ": " + p.message);
    throw Exit{kExitFailed};
  }
  const std::string unit = angle ? "deg" : file.loads.LengthUnit();
  auto shown = [&](double v) { return angle ? RadToDeg(v) : v; };
  Summary s;
  s.Add("from", shown(from), unit);
  s.Add("to", shown(to), unit);
  s.Add("phi_P", shown(p.phi_p), unit);
  s.Add("reference", shown(p.reference), unit);
  s.Add("slope", p.slope, angle ? file.loads.LengthUnit() + "/rad" : "1");
  s.Add("delta_s", p.delta_s, file.loads.LengthUnit());
  s.Add("reference_length", length, file.loads.LengthUnit());
  s.Add("Q_P", p.qp, angle ? "1/rad" : "1/length");
  s.Add("chord_deviation", p.chord_deviation, file.loads.LengthUnit());
  if (args.format == "json") {
    nlohmann::json j = s.ToJson();
    j["complete"] = p.sweep.complete();
    j.update(SweepEventsJson(m, p.sweep));
    WriteOutput(args.out, JsonText(j));
  } else {
    WriteOutput(args.out, s.ToCsv());
  }
  ReportSweep(args.file, m, p.sweep);
  if (!p.sweep.complete()) {
    Complain(args.file + ": the figures above hold for the drivable part of the range only");
    throw Exit{kExitFailed};
  }
}

}  // namespace
}  // namespace proportional_command

void AddProportionalCommand(CLI::App& app) {
  using namespace proportional_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "proportional",
      "Proportionality deviation (Proportionalitätsabweichung) of an output over an input range phi_P.\n"
      "The ideal proportional line is the tangent of the output at the reference input (--at, default: the\n"
      "flat point, least |s''| in the range); delta_s is the width of the band parallel to it that holds the\n"
      "output over the range; Q_P = (delta_s / l) / phi_P with phi_P in radians and l the reference length\n"
      "(--length, default the crank length l1). This definition reproduces the proportional linkage's reading\n"
      "example; the chord deviation is printed for comparison. Where part of the range cannot be driven, the\n"
      "figures are those of the drivable part, the gaps are named and the exit code is 1.\n"
      "Example: koppel proportional catalog/entries/proportional-linkage.yaml --output s --from 112.5 --to 247.5");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--output", args->output, "Scalar output (default: the first)");
  cmd->add_option("--from", args->from, "Start of the range [deg or length]")->required();
  cmd->add_option("--to", args->to, "End of the range [deg or length]")->required();
  cmd->add_option("--at", args->at, "Reference input of the tangent (default: the flat point)");
  cmd->add_option("--length", args->length, "Reference length l (default: crank length)");
  cmd->add_option("--resolution", args->resolution, "Sampling step [deg or length] (default 0.05)");
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  AddBranchPointOption(cmd, args->at_branch_point);
  cmd->add_option("--format", args->format, "csv (default) or json");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
