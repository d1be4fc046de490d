// koppel proportional: proportionality deviation of an output over an input range (seed 001).
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"
#include "sweep_report.hpp"

#include "koppel/api/proportionality.hpp"

namespace koppel::cli {
namespace proportional_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, output, from, to, at, length, resolution = "0.05", at_branch_point;
  std::vector<std::string> sets;
  std::string format = "csv", out;
};

// The flags as a request, refused with the flags' names (exit 2).
ProportionalityRequest RequestOf(const Args& args, const Model& model) {
  ProportionalityRequest request;
  request.output = model.mechanism().outputs[ResolveScalarOutput(model.mechanism(), args.output, "--output", args.file)].name;
  request.from = ParseNumberFlag("--from", args.from);
  request.to = ParseNumberFlag("--to", args.to);
  const double length = args.length.empty() ? ReferenceLength(model) : ParseNumberFlag("--length", args.length);
  if (length <= 0 || request.from == request.to) {
    Complain(length <= 0 ? "no reference length: give --length" : "--from and --to must differ");
    throw Exit{kExitBadInput};
  }
  request.length = length;
  if (!args.at.empty()) request.at = ParseNumberFlag("--at", args.at);
  request.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  request.resolution = ParseNumberFlag("--resolution", args.resolution);
  CheckSampleCount(request.from, request.to, request.resolution, "--from/--to/--resolution");
  return request;
}

Summary SummaryOf(const Model& model, const ProportionalityReport& p) {
  const bool angle = model.input_is_angle();
  const std::string unit = angle ? "deg" : model.length_unit(), length = model.length_unit();
  Summary s;
  s.Add("from", p.from, unit);
  s.Add("to", p.to, unit);
  s.Add("phi_P", p.range, unit);
  s.Add("reference", p.reference, unit);
  s.Add("slope", p.slope, angle ? length + "/rad" : "1");
  s.Add("delta_s", p.delta_s, length);
  s.Add("reference_length", p.reference_length, length);
  s.Add("Q_P", p.qp, angle ? "1/rad" : "1/length");
  s.Add("chord_deviation", p.chord_deviation, length);
  return s;
}

void Run(const Args& args) {
  CheckFormat(args.format);
  const Model model = LoadModel(args.file, args.sets);
  const ProportionalityRequest request = RequestOf(args, model);
  const ProportionalityReport p = Checked([&] { return FindProportionality(model, request); });
  if (!Usable(p.status)) {
    ReportSweep(args.file, model, p.sweep);
    Complain(args.file + ": " + p.message);
    throw Exit{kExitFailed};
  }
  const Summary s = SummaryOf(model, p);
  if (args.format == "json") {
    nlohmann::json j = s.ToJson();
    j["complete"] = p.sweep.complete();
    j.update(SweepEventsJson(p.sweep));
    WriteOutput(args.out, JsonText(j));
  } else {
    WriteOutput(args.out, s.ToCsv());
  }
  ReportSweep(args.file, model, p.sweep);
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
