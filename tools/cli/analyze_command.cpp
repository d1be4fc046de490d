// koppel analyze: a sweep of the drive with every declared output and its transfer functions.
#include "commands.hpp"
#include "common.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"

#include <fmt/core.h>

#include <iostream>

namespace koppel::cli {
namespace {

struct AnalyzeArgs {
  std::string file;
  std::string from, to, step;
  std::vector<std::string> sets;
  std::string format = "csv";
  std::string out;
  int order = 2;
};

// Unit of the k-th derivative of an output, for JSON and for the reader of a table.
std::string DerivativeUnit(bool output_is_angle, bool input_is_angle, int k) {
  const std::string value = output_is_angle ? "rad" : "length";
  if (k == 0) return output_is_angle ? "deg" : "length";
  const std::string per = input_is_angle ? "rad" : "length";
  return value + "/" + per + (k > 1 ? "^" + std::to_string(k) : "");
}

void RunAnalyze(const AnalyzeArgs& args) {
  CheckFormat(args.format);
  const MechanismFile file = LoadMechanism(args.file, args.sets);
  const Mechanism& m = file.mechanism;
  const bool angle_input = m.InputIsAngle();
  // The YAML and the command line give the input in degrees (R drive) or lengths (P drive).
  auto to_internal = [&](double v) { return angle_input ? DegToRad(v) : v; };
  auto to_display = [&](double v) { return angle_input ? RadToDeg(v) : v; };
  const double from = args.from.empty() ? file.sweep.from : ParseNumberFlag("--from", args.from);
  const double to = args.to.empty() ? file.sweep.to : ParseNumberFlag("--to", args.to);
  const double step = args.step.empty() ? file.sweep.step : ParseNumberFlag("--step", args.step);
  if (step == 0.0) {
    Complain("--step must not be 0");
    throw Exit{kExitBadInput};
  }
  if (args.order < 0 || args.order > kMaxOrder) {
    Complain(fmt::format("--order must be between 0 and {}", kMaxOrder));
    throw Exit{kExitBadInput};
  }
  CheckSampleCount(from, to, step, "--from/--to/--step");

  SweepOptions options;
  options.from = to_internal(from);
  options.to = to_internal(to);
  options.step = to_internal(step);
  options.order = args.order;
  const SweepResult result = Sweep(m, options);

  // columns: input, then per output component: value, d1 .. d_order
  Table table;
  std::vector<std::string> units;
  table.columns.push_back(m.drive.input_name);
  units.push_back(angle_input ? "deg" : "length");
  std::vector<bool> column_is_angle_value;
  for (const Output& o : m.outputs) {
    for (int c = 0; c < o.Components(); ++c) {
      const std::string base = o.Components() == 2 ? o.name + (c == 0 ? "_x" : "_y") : o.name;
      for (int k = 0; k <= result.order; ++k) {
        table.columns.push_back(k == 0 ? base : base + "_d" + std::to_string(k));
        units.push_back(DerivativeUnit(o.IsAngle(), angle_input, k));
        column_is_angle_value.push_back(k == 0 && o.IsAngle());
      }
    }
  }
  for (size_t i = 0; i < result.inputs.size(); ++i) {
    std::vector<double> row;
    row.reserve(table.columns.size());
    row.push_back(to_display(result.inputs[i]));
    for (int c = 0; c < result.outputs.cols(); ++c) {
      const double v = result.outputs(i, c);
      row.push_back(column_is_angle_value[c] ? RadToDeg(v) : v);
    }
    table.rows.push_back(std::move(row));
  }

  if (args.format == "csv") {
    WriteOutput(args.out, table.ToCsv());
  } else {
    nlohmann::json j = table.ToJson();
    j["mechanism"] = m.name;
    j["file"] = file.path;
    j["input"] = {{"name", m.drive.input_name}, {"unit", angle_input ? "deg" : "length"},
                  {"from", from}, {"to", to}, {"step", step}};
    j["order"] = result.order;
    j["units"] = units;
    j["complete"] = result.complete();
    j["status"] = ToString(result.status);
    if (!result.complete()) {
      j["message"] = result.message;
      j["stopped_at"] = to_display(result.stopped_at);
    }
    WriteOutput(args.out, JsonText(j));
  }
  if (!result.complete()) {
    Complain(args.file + ": " + result.message);
    throw Exit{kExitFailed};
  }
}

}  // namespace

void AddAnalyzeCommand(CLI::App& app) {
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "analyze",
      "Sweep the drive and tabulate every output of the mechanism with its transfer functions.\n"
      "Columns: the input (degrees for an R drive, length for a P drive), then for each output NAME:\n"
      "NAME, NAME_d1, NAME_d2 ... (d_k = k-th derivative with respect to the input in radians, or in\n"
      "length units for a P drive); a point output K gives K_x, K_y and their derivatives. Angle\n"
      "outputs are printed in degrees; their derivatives in radians. Derivatives are exact (Taylor\n"
      "series through the constraint equations), not differences of positions.\n"
      "The sweep follows the assembly branch chosen by the file's `assembly` hint and stops, with\n"
      "exit code 1 and a message, where the mechanism cannot be driven further (dead centre of the\n"
      "drive, not assemblable).\n"
      "Example: koppel analyze catalog/entries/slider-crank-offset.yaml --set e=0 --step 5");
  cmd->add_option("file", args->file, "Mechanism YAML file")->required();
  cmd->add_option("--from", args->from, "First input value [deg or length] (default: the file's sweep.from, else 0)");
  cmd->add_option("--to", args->to, "Last input value [deg or length] (default: the file's sweep.to, else 360)");
  cmd->add_option("--step", args->step, "Input step [deg or length] (default: the file's sweep.step, else 1)");
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE (a formula; repeatable)");
  cmd->add_option("--order", args->order, "Highest transfer-function order in the table, 0..8 (default 2)");
  cmd->add_option("--format", args->format, "csv (default) or json");
  cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout");
  cmd->callback([args] { RunAnalyze(*args); });
}

}  // namespace koppel::cli
