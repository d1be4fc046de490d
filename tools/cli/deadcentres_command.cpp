// koppel deadcentres: the dead centres (Totlagen) of an output, their kind, and the stroke.
#include "commands.hpp"
#include "common.hpp"
#include "sweep_report.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/analysis/dead_centres.hpp"

namespace koppel::cli {
namespace {

struct Args {
  std::string file, output, from, to, step = "1", at_branch_point;
  std::vector<std::string> sets;
  std::string format = "csv", out;
  bool summary = false;
};

void Run(const Args& args) {
  CheckFormat(args.format);
  const MechanismFile file = LoadMechanism(args.file, args.sets);
  const Mechanism& m = file.mechanism;
  const int output = ResolveScalarOutput(m, args.output);
  const bool angle_in = m.InputIsAngle(), angle_out = m.OutputIsAngle(output);
  auto in = [&](double v) { return angle_in ? DegToRad(v) : v; };
  auto in_display = [&](double v) { return angle_in ? RadToDeg(v) : v; };
  auto out_display = [&](double v) { return angle_out ? RadToDeg(v) : v; };
  SweepOptions range;
  range.from = in(args.from.empty() ? file.sweep.from : ParseNumberFlag("--from", args.from));
  range.to = in(args.to.empty() ? file.sweep.to : ParseNumberFlag("--to", args.to));
  range.step = in(ParseNumberFlag("--step", args.step));
  range.continuation.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  std::string why;
  CheckSampleCount(range.from, range.to, range.step, "--from/--to/--step");
  if (!range.IsValid(&why)) {
    Complain("--from/--to/--step: " + why);
    throw Exit{kExitBadInput};
  }
  const DeadCentreReport r = FindDeadCentres(m, output, 0, range);
  const std::string name = m.outputs[output].name, in_unit = angle_in ? "deg" : "length", out_unit = angle_out ? "deg" : "length";
  Summary summary;
  if (r.has_stroke) {
    summary.Add(m.drive.input_name + "_a", in_display(r.phi_a), in_unit);
    summary.Add(m.drive.input_name + "_i", in_display(r.phi_i), in_unit);
    summary.Add(name + "_a", out_display(r.s_a), out_unit);
    summary.Add(name + "_i", out_display(r.s_i), out_unit);
    summary.Add(name + "_H", out_display(r.stroke), out_unit);
    if (angle_in) {
      summary.Add(m.drive.input_name + "_H", RadToDeg(r.phi_h), "deg");
      summary.Add("phase_ratio", r.phase_ratio, "1");
    }
  }
  Table table;
  table.columns = {m.drive.input_name, name, name + "_d2"};
  std::vector<std::string> kinds;
  for (const DeadCentre& d : r.points) {
    table.rows.push_back({in_display(d.input), out_display(d.value), d.second});
    kinds.push_back(ToString(d.kind));
  }
  if (args.format == "json") {
    nlohmann::json points = nlohmann::json::array();
    for (size_t i = 0; i < r.points.size(); ++i)
      points.push_back({{"input", table.rows[i][0]}, {"value", table.rows[i][1]}, {"d2", table.rows[i][2]}, {"kind", kinds[i]}});
    nlohmann::json j = {{"mechanism", m.name}, {"output", name}, {"input_unit", in_unit}, {"output_unit", out_unit},
                        {"dead_centres", points}, {"classified", r.classified}, {"summary", summary.ToJson()},
                        {"complete", r.sweep.complete()}};
    j.update(SweepEventsJson(m, r.sweep));
    if (!r.sweep.complete()) j["message"] = r.sweep.message;
    WriteOutput(args.out, JsonText(j));
  } else if (args.summary) {
    WriteOutput(args.out, summary.ToCsv());
  } else {
    std::string csv = "kind," + table.columns[0] + "," + table.columns[1] + "," + table.columns[2] + "\n";
    for (size_t i = 0; i < table.rows.size(); ++i)
      csv += kinds[i] + "," + FormatNumber(table.rows[i][0]) + "," + FormatNumber(table.rows[i][1]) + "," + FormatNumber(table.rows[i][2]) + "\n";
    WriteOutput(args.out, csv);
  }
  ReportSweep(args.file, m, r.sweep);
  if (!r.sweep.complete()) {
    Complain(args.file + ": the dead centres over the drivable part are listed");
    throw Exit{kExitFailed};
  }
}

}  // namespace

void AddDeadCentresCommand(CLI::App& app) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "deadcentres",
      "Dead centres (Totlagen) of a scalar output: the inputs where its first-order transfer function\n"
      "vanishes, found over the sweep and refined to 1e-12 by Newton on the first-order transfer function.\n"
      "Each is classified extended (Strecklage, crank and coupler stretched) or folded (Decklage) where the\n"
      "drive link and the link it drives line up, else 'unclassified'. Columns: kind, input (deg for an R drive),\n"
      "the output there (deg for angles), its second-order transfer function. --summary prints phi_a, phi_i,\n"
      "s_a, s_i, the stroke s_H, the crank angle of the forward stroke phi_H (from phi_a to phi_i,\n"
      "counter-clockwise) and the phase ratio phi_H/(360 - phi_H).\n"
      "The search follows the assembly branch like `analyze`: singular points met are reported on stderr;\n"
      "where part of the range cannot be driven, the dead centres over the drivable part are listed, the gaps\n"
      "named, and the exit code is 1.\n"
      "Example: koppel deadcentres catalog/entries/slider-crank-offset.yaml --output s --summary");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--output", args->output, "Scalar output (default: the first)");
  cmd->add_option("--from", args->from, "Search from this input (default: the file's sweep)");
  cmd->add_option("--to", args->to, "Search up to this input (default: the file's sweep)");
  cmd->add_option("--step", args->step, "Search step; dead centres closer than this may be missed (default 1)");
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  AddBranchPointOption(cmd, args->at_branch_point);
  cmd->add_flag("--summary", args->summary, "Print the stroke summary instead of the dead centres");
  cmd->add_option("--format", args->format, "csv (default) or json (both tables)");
  cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout");
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
