// koppel analyze: a sweep of the drive with every declared output and its transfer functions.
#include "commands.hpp"
#include "common.hpp"
#include "sweep_report.hpp"

#include "koppel/api/sweep_layout.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"

#include <fmt/core.h>

namespace koppel::cli {
namespace analyze_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct AnalyzeArgs {
  std::string file;
  std::string from, to, step, at_branch_point;
  std::vector<std::string> sets;
  std::string format = "csv";
  std::string out;
  int order = 2;
};

// The table of a sweep (koppel/api/sweep_layout.hpp): the input, every output's derivatives
// 0..order, and the singular flag. A transfer function that cannot be computed at a row (above
// the row's valid order, or not defined there: an output that is not differentiable) is empty in
// CSV and null in JSON, never a number.
std::string ToCsv(const Mechanism& m, const SweepColumns& t, const SweepResult& r) {
  std::string out;
  out.reserve(r.inputs.size() * (r.outputs.cols() + 2) * 16);  // about 16 characters a number
  for (size_t c = 0; c < t.names.size(); ++c) out += (c ? "," : "") + t.names[c];
  out += "\n";
  for (size_t i = 0; i < r.inputs.size(); ++i) {
    AppendNumber(out, m.InputIsAngle() ? RadToDeg(r.inputs[i]) : r.inputs[i]);
    for (int c = 0; c < r.outputs.cols(); ++c) {
      const double v = r.outputs(i, c);
      out += ',';
      if (t.order_of_column[c + 1] <= r.valid_order[i] && r.Defined(static_cast<int>(i), c))
        AppendNumber(out, t.angle_value[c + 1] ? RadToDeg(v) : v);
    }
    out += r.singular[i] ? ",1\n" : ",0\n";
  }
  return out;
}

nlohmann::json ToJson(const Mechanism& m, const SweepColumns& t, const SweepResult& r) {
  nlohmann::json rows = nlohmann::json::array();
  for (size_t i = 0; i < r.inputs.size(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    row.push_back(m.InputIsAngle() ? RadToDeg(r.inputs[i]) : r.inputs[i]);
    for (int c = 0; c < r.outputs.cols(); ++c) {
      const double v = t.angle_value[c + 1] ? RadToDeg(r.outputs(i, c)) : r.outputs(i, c);
      FormatNumber(v);  // the same refusal of non-finite numbers as CSV
      if (t.order_of_column[c + 1] <= r.valid_order[i] && r.Defined(static_cast<int>(i), c)) {
        row.push_back(v);
      } else {
        row.push_back(nullptr);
      }
    }
    row.push_back(static_cast<int>(r.singular[i]));
    rows.push_back(row);
  }
  return {{"columns", t.names}, {"units", t.units}, {"rows", rows}};
}

void RunAnalyze(const AnalyzeArgs& args) {
  CheckFormat(args.format);
  const MechanismFile file = LoadMechanism(args.file, args.sets);
  const Mechanism& m = file.mechanism;
  const bool angle_input = m.InputIsAngle();
  // The YAML and the command line give the input in degrees (R drive) or lengths (P drive).
  auto to_internal = [&](double v) { return angle_input ? DegToRad(v) : v; };
  const double from = args.from.empty() ? file.sweep.from : ParseNumberFlag("--from", args.from);
  const double to = args.to.empty() ? file.sweep.to : ParseNumberFlag("--to", args.to);
  const double step = args.step.empty() ? file.sweep.step : ParseNumberFlag("--step", args.step);
  CheckSampleCount(from, to, step, "--from/--to/--step");

  SweepOptions options;
  options.from = to_internal(from);
  options.to = to_internal(to);
  options.step = to_internal(step);
  options.order = args.order;
  options.continuation.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  std::string why;
  if (!options.IsValid(&why)) {
    Complain("--from/--to/--step/--order: " + why);
    throw Exit{kExitBadInput};
  }
  const SweepResult result = Sweep(m, options);
  const SweepColumns table = SweepLayout(m, options.order, file.loads.LengthUnit());

  if (args.format == "csv") {
    WriteOutput(args.out, ToCsv(m, table, result));
  } else {
    nlohmann::json j = ToJson(m, table, result);
    j["mechanism"] = m.name;
    j["file"] = file.path;
    j["input"] = {{"name", m.drive.input_name}, {"unit", angle_input ? "deg" : file.loads.LengthUnit()},
                  {"from", from}, {"to", to}, {"step", step}};
    j["order"] = options.order;
    j["complete"] = result.complete() && result.undefined.empty();
    j["status"] = ToString(result.status);
    j.update(SweepEventsJson(m, EventsOf(result)));
    if (!result.message.empty()) j["message"] = result.message;
    WriteOutput(args.out, JsonText(j));
  }
  ReportSweep(args.file, m, EventsOf(result));
  if (!result.complete()) throw Exit{kExitFailed};
  // every sample there, but an output has no number in some cells (not differentiable there)
  if (!result.undefined.empty()) {
    Complain(args.file + ": " + result.message);
    throw Exit{kExitFailed};
  }
}

}  // namespace
}  // namespace analyze_command

void AddAnalyzeCommand(CLI::App& app) {
  using namespace analyze_command;
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "analyze",
      "Sweep the drive and tabulate every output of the mechanism with its transfer functions.\n"
      "Columns: the input (degrees for an R drive, length for a P drive), then for each output NAME:\n"
      "NAME, NAME_d1, NAME_d2 ... (d_k = k-th derivative with respect to the input in radians, or in\n"
      "length units for a P drive); a point output K gives K_x, K_y and their derivatives. Angle\n"
      "outputs (R joints, links, directions, transmission angles) are printed in degrees; their\n"
      "derivatives in radians. Derivatives are exact (Taylor series through the constraint equations),\n"
      "not differences of positions. The last column, singular, is 1 where the pose is a singular\n"
      "position (reciprocal condition of the Jacobian below 1e-6): there the transfer functions up to 3rd\n"
      "order are the branch's limits and higher orders are left empty.\n"
      "The sweep starts at the file's `assembly` hint and follows that branch outward to both ends of the\n"
      "range: through branch points (see --at-branch-point), up to limit points (dead centres of the\n"
      "drive). It prints every row it reaches; when part of the range cannot be driven, it names the gaps\n"
      "and the singular points that bound them on stderr and exits 1.\n"
      "Example: koppel analyze catalog/entries/slider-crank-offset.yaml --set e=0 --step 5");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--from", args->from, "First input value [deg or length] (default: the file's sweep.from, else 0)");
  cmd->add_option("--to", args->to, "Last input value [deg or length] (default: the file's sweep.to, else 360)");
  cmd->add_option("--step", args->step, "Input step [deg or length] (default: the file's sweep.step, else 1)");
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE (a formula; repeatable)");
  cmd->add_option("--order", args->order, fmt::format("Highest transfer-function order in the table, 0..{} (default 2)", kMaxOrder));
  AddBranchPointOption(cmd, args->at_branch_point);
  cmd->add_option("--format", args->format, "csv (default) or json");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout"));
  cmd->callback([args] { RunAnalyze(*args); });
}

}  // namespace koppel::cli
