// koppel forces: drive torque and joint reactions over a sweep (statics, or kinetostatics at a
// constant drive speed), with the virtual-work check and the reduced moment of inertia.
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"
#include "sweep_report.hpp"

#include "koppel/api/forces.hpp"

#include <optional>

namespace koppel::cli {
namespace forces_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct ForcesArgs {
  std::string file;
  std::string from, to, step, speed, at_branch_point;
  std::vector<std::string> sets;
  std::string format = "csv";
  std::string out;
};

std::string ToCsv(const ForcesTable& table) {
  std::string out = CsvLine(table.columns);
  for (const std::vector<std::optional<double>>& row : table.rows) {
    for (size_t c = 0; c < row.size(); ++c) {
      if (c) out += ",";
      if (row[c]) out += FormatNumber(*row[c]);
    }
    out += "\n";
  }
  return out;
}

nlohmann::json ToJson(const ForcesTable& table) {
  nlohmann::json rows = nlohmann::json::array();
  for (const std::vector<std::optional<double>>& row : table.rows) {
    nlohmann::json values = nlohmann::json::array();
    for (const std::optional<double>& v : row) {
      if (v) {
        FormatNumber(*v);  // the same refusal of non-finite numbers as CSV
        values.push_back(*v);
      } else {
        values.push_back(nullptr);
      }
    }
    rows.push_back(values);
  }
  return {{"columns", table.columns}, {"units", table.units}, {"rows", rows}};
}

ForcesRequest ReadRequest(const ForcesArgs& args) {
  ForcesRequest request;
  if (!args.from.empty()) request.from = ParseNumberFlag("--from", args.from);
  if (!args.to.empty()) request.to = ParseNumberFlag("--to", args.to);
  if (!args.step.empty()) request.step = ParseNumberFlag("--step", args.step);
  request.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  if (!args.speed.empty()) request.speed = ParseNumberFlag("--speed", args.speed);
  return request;
}

void RunForces(const ForcesArgs& args) {
  CheckFormat(args.format);
  const Model model = LoadModel(args.file, args.sets);
  const ForcesRequest request = ReadRequest(args);
  if (std::string why; !request.IsValid(model, &why)) {
    Complain("--from/--to/--step/--speed: " + why);
    throw Exit{kExitBadInput};
  }
  const ForcesTable result = AnalyseForces(model, request);
  for (const std::string& note : result.notes) Complain(args.file + ": " + note);
  if (result.bad_input) {
    Complain(args.file + ": " + result.message);
    throw Exit{kExitBadInput};
  }
  if (args.format == "csv") {
    WriteOutput(args.out, ToCsv(result));
  } else {
    nlohmann::json j = ToJson(result);
    j["mechanism"] = model.name();
    j["file"] = model.path();
    j["kinetostatic"] = result.kinetostatic;
    if (request.speed) j["speed"] = {{"value", *request.speed}, {"unit", model.input_is_angle() ? "rpm" : "length/s"}};
    j["status"] = ToString(result.status);
    j["worst_disagreement"] = result.worst_disagreement;
    j.update(SweepEventsJson(result.sweep));
    if (!result.complete()) j["message"] = result.message;
    WriteOutput(args.out, JsonText(j));
  }
  ReportSweep(args.file, model, result.sweep);
  if (!result.complete()) {
    if (result.message != result.sweep.message) Complain(args.file + ": " + result.message);
    throw Exit{kExitFailed};
  }
}

}  // namespace
}  // namespace forces_command

void AddForcesCommand(CLI::App& app) {
  using namespace forces_command;
  auto args = std::make_shared<ForcesArgs>();
  CLI::App* cmd = app.add_subcommand(
      "forces",
      "Drive torque and joint reactions over a sweep of the drive, from the masses and loads of the file\n"
      "(docs/mechanism-file.md, 'Masses and loads'). Without --speed: statics, the torque that holds the loads at rest.\n"
      "With --speed: kinetostatics, the drive turning at that constant speed, inertia forces included.\n"
      "Columns: the input (degrees, or length for a P drive); torque [N m] (force [N] for a P drive), the\n"
      "torque the drive exerts on its joint's second link, from the joint reactions (Lagrange multipliers);\n"
      "torque_vw, the same by the principle of virtual work (-sum of loads times their transfer functions;\n"
      "the two must agree, else exit 1); J_red [kg m^2] and J_red_d1 [kg m^2/rad], the reduced moment of\n"
      "inertia and its derivative (m_red [kg], m_red_d1 [kg/m] for a P drive); for every joint J: J_x, J_y\n"
      "[N], the force its first link (links: [a, b]) exerts on the second, global frame; for a P joint also\n"
      "J_N [N], the same along the slide's normal (axis turned +90 deg), and J_M [N m], the moment across the\n"
      "slide (guide on block, about the block's point); singular, 1 at a singular pose, where the drive\n"
      "torque is unbounded (limit point) or the reactions undetermined (branch point): those cells are left\n"
      "empty and the command exits 1.\n"
      "Example: koppel forces tests/data/slider-crank-loads.yaml --speed 600 --step 10");
  cmd->add_option("file", args->file, "Mechanism YAML file with masses and loads")->required();
  cmd->add_option("--speed", args->speed, "Constant drive speed [rpm; length units/s for a P drive]: kinetostatics");
  cmd->add_option("--from", args->from, "First input value [deg or length] (default: the file's sweep.from, else 0)");
  cmd->add_option("--to", args->to, "Last input value [deg or length] (default: the file's sweep.to, else 360)");
  cmd->add_option("--step", args->step, "Input step [deg or length] (default: the file's sweep.step, else 1)");
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE (a formula; repeatable)");
  AddBranchPointOption(cmd, args->at_branch_point);
  cmd->add_option("--format", args->format, "csv (default) or json");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout"));
  cmd->callback([args] { RunForces(*args); });
}

}  // namespace koppel::cli
