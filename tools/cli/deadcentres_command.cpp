// koppel deadcentres: the dead centres (Totlagen) of an output, their kind, and the stroke; for a
// transmission angle its extremes mu_min and mu_max.
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"
#include "sweep_report.hpp"

#include "koppel/api/model.hpp"

namespace koppel::cli {
namespace deadcentres_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct Args {
  std::string file, output, from, to, step = "1", at_branch_point;
  std::vector<std::string> sets;
  std::string format = "csv", out;
  bool summary = false;
};

// The units of the input and of the output searched, as the tables name them.
struct Units {
  std::string in, out;
};

// A transmission angle: mu_min, phi_mu_min, mu_max, phi_mu_max; the stroke of a transmission
// angle means nothing. Any other output: the stroke between its dead centres.
Summary SummaryOf(const Model& model, const DeadCentres& d, const Units& u) {
  const std::string& name = d.output;
  const std::string input = model.input_name();
  Summary summary;
  if (d.transmission_angle) {
    if (!d.has_extremes) return summary;
    summary.Add(name + "_min", d.minimum.value, u.out);
    summary.Add(input + "_" + name + "_min", d.minimum.input, u.in);
    summary.Add(name + "_max", d.maximum.value, u.out);
    summary.Add(input + "_" + name + "_max", d.maximum.input, u.in);
    return summary;
  }
  if (!d.has_stroke) return summary;
  summary.Add(input + "_a", d.input_a, u.in);
  summary.Add(input + "_i", d.input_i, u.in);
  summary.Add(name + "_a", d.value_a, u.out);
  summary.Add(name + "_i", d.value_i, u.out);
  summary.Add(name + "_H", d.stroke, u.out);
  if (model.input_is_angle()) {
    summary.Add(input + "_H", d.forward_angle, "deg");
    summary.Add("phase_ratio", d.phase_ratio, "1");
    summary.Add("time_ratio", d.time_ratio, "1");
  }
  return summary;
}

nlohmann::json ExtremesJson(const DeadCentres& d) {
  if (!d.has_extremes) return {{"status", ToString(d.extremes_status)}, {"message", d.extremes_message}};
  auto one = [&](const OutputExtremePoint& x) {
    FormatNumber(x.input);  // the CSV's refusal of non-finite numbers
    FormatNumber(x.value);
    return nlohmann::json{{"input", x.input}, {"value", x.value}, {"at", x.at}};
  };
  return {{"min", one(d.minimum)}, {"max", one(d.maximum)}};
}

std::string Json(const Model& model, const DeadCentres& d, const Summary& summary, const Units& u) {
  nlohmann::json points = nlohmann::json::array();
  for (const DeadCentrePoint& p : d.points) {
    for (double v : {p.input, p.value, p.second}) FormatNumber(v);
    points.push_back({{"input", p.input}, {"value", p.value}, {"d2", p.second}, {"kind", p.kind}});
  }
  nlohmann::json j = {{"mechanism", model.mechanism().name}, {"output", d.output}, {"input_unit", u.in},
                      {"output_unit", u.out}, {"dead_centres", points}, {"classified", d.classified},
                      {"summary", summary.ToJson()}, {"extremes", ExtremesJson(d)}, {"complete", d.sweep.complete()}};
  j.update(SweepEventsJson(d.sweep));
  if (!d.search_message.empty()) j["message"] = d.search_message;
  return JsonText(j);
}

std::string Csv(const Model& model, const DeadCentres& d) {
  std::string csv = CsvLine({"kind", model.input_name(), d.output, d.output + "_d2"});
  for (const DeadCentrePoint& p : d.points)
    csv += CsvField(p.kind) + "," + FormatNumber(p.input) + "," + FormatNumber(p.value) + "," + FormatNumber(p.second) + "\n";
  return csv;
}

// What could not be had, on stderr: a gap in the range, a sign change not refined, a summary
// without its numbers. True when there was something.
bool ReportProblems(const Args& args, const DeadCentres& d, const Summary& summary) {
  bool problem = false;
  if (!d.sweep.complete()) {
    Complain(args.file + ": the dead centres over the drivable part are listed");
    problem = true;
  }
  if (!d.unresolved.empty()) {
    Complain(args.file + ": " + d.search_message);
    problem = true;
  }
  if (args.summary && summary.quantity.empty()) {
    Complain(args.file + ": no summary: " +
             (d.transmission_angle ? "the extremes of '" + d.output + "' were not found: " + d.extremes_message
                                   : std::to_string(d.points.size()) + " dead centre" + (d.points.size() == 1 ? "" : "s") +
                                         " found, a stroke needs two"));
    problem = true;
  }
  return problem;
}

void Run(const Args& args) {
  CheckFormat(args.format);
  const Model model = LoadModel(args.file, args.sets);
  const int output = ResolveScalarOutput(model.mechanism(), args.output, "--output", args.file);
  const std::string output_name = model.mechanism().outputs[output].name;
  const SweepSpan span =
      model.Span(OptionalNumberFlag("--from", args.from), OptionalNumberFlag("--to", args.to), ParseNumberFlag("--step", args.step));
  const AtBranchPoint action = ParseBranchPointFlag(args.at_branch_point);
  CheckSampleCount(span.from, span.to, span.step, "--from/--to/--step");
  const DeadCentres d = Checked([&] { return model.FindDeadCentres(output_name, span.from, span.to, span.step, action); });
  const Units units{model.input_is_angle() ? "deg" : model.length_unit(), model.output_is_angle(output_name) ? "deg" : model.length_unit()};
  const Summary summary = SummaryOf(model, d, units);
  if (args.format == "json") {
    WriteOutput(args.out, Json(model, d, summary, units));
  } else {
    WriteOutput(args.out, args.summary ? summary.ToCsv() : Csv(model, d));
  }
  ReportSweep(args.file, model, d.sweep);
  if (ReportProblems(args, d, summary)) throw Exit{kExitFailed};
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
