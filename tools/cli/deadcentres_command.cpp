// koppel deadcentres: the dead centres (Totlagen) of an output, their kind, and the stroke; for a
// transmission angle its extremes mu_min and mu_max.
#include "commands.hpp"
#include "common.hpp"
#include "sweep_report.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/analysis/dead_centres.hpp"

namespace koppel::cli {
namespace deadcentres_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, output, from, to, step = "1", at_branch_point;
  std::vector<std::string> sets;
  std::string format = "csv", out;
  bool summary = false;
};

// Degrees for angles, lengths as they are.
struct Units {
  bool angle_in = false, angle_out = false;
  std::string length = "length";  // the file's length unit (Loads::LengthUnit)
  double In(double v) const { return angle_in ? RadToDeg(v) : v; }
  double Out(double v) const { return angle_out ? RadToDeg(v) : v; }
  std::string in_unit() const { return angle_in ? "deg" : length; }
  std::string out_unit() const { return angle_out ? "deg" : length; }
};

// A transmission angle: mu_min, phi_mu_min, mu_max, phi_mu_max (extremes.hpp); the stroke of a
// transmission angle means nothing. Any other output: the stroke between its dead centres.
Summary SummaryOf(const Mechanism& m, int output, const DeadCentreReport& r, const Units& u) {
  const std::string name = m.outputs[output].name, input = m.drive.input_name;
  Summary summary;
  if (m.outputs[output].kind == OutputKind::kTransmissionAngle) {
    if (!Usable(r.extremes.status)) return summary;
    summary.Add(name + "_min", u.Out(r.extremes.minimum.value), u.out_unit());
    summary.Add(input + "_" + name + "_min", u.In(r.extremes.minimum.input), u.in_unit());
    summary.Add(name + "_max", u.Out(r.extremes.maximum.value), u.out_unit());
    summary.Add(input + "_" + name + "_max", u.In(r.extremes.maximum.input), u.in_unit());
    return summary;
  }
  if (!r.has_stroke) return summary;
  summary.Add(input + "_a", u.In(r.phi_a), u.in_unit());
  summary.Add(input + "_i", u.In(r.phi_i), u.in_unit());
  summary.Add(name + "_a", u.Out(r.s_a), u.out_unit());
  summary.Add(name + "_i", u.Out(r.s_i), u.out_unit());
  summary.Add(name + "_H", u.Out(r.stroke), u.out_unit());
  if (u.angle_in) {
    summary.Add(input + "_H", RadToDeg(r.phi_h), "deg");
    summary.Add("phase_ratio", r.phase_ratio, "1");
  }
  return summary;
}

nlohmann::json ExtremesJson(const OutputExtremes& e, const Units& u) {
  if (!Usable(e.status)) return {{"status", ToString(e.status)}, {"message", e.message}};
  auto one = [&](const OutputExtreme& x) {
    FormatNumber(u.In(x.input));  // the CSV's refusal of non-finite numbers
    FormatNumber(u.Out(x.value));
    return nlohmann::json{{"input", u.In(x.input)}, {"value", u.Out(x.value)}, {"at", ToString(x.kind)}};
  };
  return {{"min", one(e.minimum)}, {"max", one(e.maximum)}};
}

std::string Json(const Mechanism& m, int output, const DeadCentreReport& r, const Summary& summary, const Units& u) {
  nlohmann::json points = nlohmann::json::array();
  for (const DeadCentre& d : r.points) {
    const std::vector<double> row = {u.In(d.input), u.Out(d.value), d.second};
    for (double v : row) FormatNumber(v);
    points.push_back({{"input", row[0]}, {"value", row[1]}, {"d2", row[2]}, {"kind", ToString(d.kind)}});
  }
  nlohmann::json j = {{"mechanism", m.name}, {"output", m.outputs[output].name}, {"input_unit", u.in_unit()},
                      {"output_unit", u.out_unit()}, {"dead_centres", points}, {"classified", r.classified},
                      {"summary", summary.ToJson()}, {"extremes", ExtremesJson(r.extremes, u)}, {"complete", r.sweep.complete()}};
  j.update(SweepEventsJson(m, r.sweep));
  if (!r.message.empty()) j["message"] = r.message;
  return JsonText(j);
}

std::string Csv(const Mechanism& m, int output, const DeadCentreReport& r, const Units& u) {
  const std::string name = m.outputs[output].name;
  std::string csv = "kind," + m.drive.input_name + "," + name + "," + name + "_d2\n";
  for (const DeadCentre& d : r.points)
    csv += std::string(ToString(d.kind)) + "," + FormatNumber(u.In(d.input)) + "," + FormatNumber(u.Out(d.value)) + "," +
           FormatNumber(d.second) + "\n";
  return csv;
}

// What could not be had, on stderr: a gap in the range, a sign change not refined, a summary
// without its numbers. True when there was something.
bool ReportProblems(const Args& args, const Mechanism& m, int output, const DeadCentreReport& r, const Summary& summary) {
  bool problem = false;
  if (!r.sweep.complete()) {
    Complain(args.file + ": the dead centres over the drivable part are listed");
    problem = true;
  }
  if (!r.unresolved.empty()) {
    Complain(args.file + ": " + r.message);
    problem = true;
  }
  if (args.summary && summary.quantity.empty()) {
    const bool transmission = m.outputs[output].kind == OutputKind::kTransmissionAngle;
    Complain(args.file + ": no summary: " +
             (transmission ? "the extremes of '" + m.outputs[output].name + "' were not found: " + r.extremes.message
                           : std::to_string(r.points.size()) + " dead centre" + (r.points.size() == 1 ? "" : "s") +
                                 " found, a stroke needs two"));
    problem = true;
  }
  return problem;
}

void Run(const Args& args) {
  CheckFormat(args.format);
  const MechanismFile file = LoadMechanism(args.file, args.sets);
  const Mechanism& m = file.mechanism;
  const int output = ResolveScalarOutput(m, args.output, "--output", args.file);
  const Units units{m.InputIsAngle(), m.OutputIsAngle(output), file.loads.LengthUnit()};
  auto in = [&](double v) { return units.angle_in ? DegToRad(v) : v; };
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
  const Summary summary = SummaryOf(m, output, r, units);
  if (args.format == "json") {
    WriteOutput(args.out, Json(m, output, r, summary, units));
  } else {
    WriteOutput(args.out, args.summary ? summary.ToCsv() : Csv(m, output, r, units));
  }
  ReportSweep(args.file, m, r.sweep);
  if (ReportProblems(args, m, output, r, summary)) throw Exit{kExitFailed};
}

}  // namespace
}  // namespace deadcentres_command

void AddDeadCentresCommand(CLI::App& app) {
  using namespace deadcentres_command;
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "deadcentres",
      "Dead centres (Totlagen) of a scalar output: the inputs where its first-order transfer function\n"
      "vanishes, found over the sweep and refined to 1e-12 by Newton on the first-order transfer function.\n"
      "Over whole turns of a crank the search is periodic (a dead centre at the start is found once); over\n"
      "a part of the turn the range's ends are searched too. Each is classified extended (Strecklage, crank\n"
      "and coupler stretched) or folded (Decklage) where the drive link and the link it drives line up, else\n"
      "'unclassified'. Columns: kind, input (deg for an R drive), the output there (deg for angles), its\n"
      "second-order transfer function. --summary prints phi_a, phi_i, s_a, s_i, the stroke s_H, the crank\n"
      "angle of the forward stroke phi_H (from phi_a to phi_i, counter-clockwise) and the phase ratio\n"
      "phi_H/(360 - phi_H); for a transmission angle mu instead mu_min, phi_mu_min, mu_max, phi_mu_max (each\n"
      "a stationary point, the fold at 90 deg, or an end of a range that is not whole turns).\n"
      "The search follows the assembly branch like `analyze`: singular points met are reported on stderr;\n"
      "where part of the range cannot be driven, the dead centres over the drivable part are listed, the gaps\n"
      "named, and the exit code is 1; so is it when a summary cannot be had.\n"
      "Example: koppel deadcentres catalog/entries/slider-crank-offset.yaml --output s --summary\n"
      "Example: koppel deadcentres catalog/entries/crank-rocker.yaml --output mu --summary");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--output", args->output, "Scalar output (default: the first)");
  cmd->add_option("--from", args->from, "Search from this input (default: the file's sweep)");
  cmd->add_option("--to", args->to, "Search up to this input (default: the file's sweep)");
  cmd->add_option("--step", args->step, "Search step; dead centres closer than this may be missed (default 1)");
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE");
  AddBranchPointOption(cmd, args->at_branch_point);
  cmd->add_flag("--summary", args->summary, "Print the stroke summary (a transmission angle: its extremes) instead of the dead centres");
  cmd->add_option("--format", args->format, "csv (default) or json (both tables)");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout"));
  cmd->callback([args] { Run(*args); });
}

}  // namespace koppel::cli
