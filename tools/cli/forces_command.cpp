// koppel forces: drive torque and joint reactions over a sweep (statics, or kinetostatics at a
// constant drive speed), with the virtual-work check and the reduced moment of inertia.
#include "commands.hpp"
#include "common.hpp"
#include "sweep_report.hpp"

#include "koppel/analysis/forces.hpp"
#include "koppel/core/angles.hpp"

#include <fmt/core.h>

#include <functional>
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

// One column of the table: its name, unit and how to read it off a row (empty when the row
// does not have it).
struct Column {
  std::string name, unit;
  std::function<std::optional<double>(const ForcesRow&)> value;
};

std::vector<Column> Layout(const Mechanism& m) {
  const bool angle = m.InputIsAngle();
  const std::string drive = angle ? "torque" : "force", drive_unit = angle ? "N m" : "N";
  const std::string inertia = angle ? "J_red" : "m_red";
  std::vector<Column> columns;
  auto computed = [](auto get) {
    return [get](const ForcesRow& r) -> std::optional<double> { return r.computed ? std::optional<double>(get(r)) : std::nullopt; };
  };
  auto by_virtual_work = [](auto get) {
    return [get](const ForcesRow& r) -> std::optional<double> { return r.virtual_work ? std::optional<double>(get(r)) : std::nullopt; };
  };
  columns.push_back({m.drive.input_name, angle ? "deg" : "length", [angle](const ForcesRow& r) {
                       return std::optional<double>(angle ? RadToDeg(r.input) : r.input);
                     }});
  columns.push_back({drive, drive_unit, computed([](const ForcesRow& r) { return r.drive; })});
  columns.push_back({drive + "_vw", drive_unit, by_virtual_work([](const ForcesRow& r) { return r.drive_virtual_work; })});
  columns.push_back({inertia, angle ? "kg m^2" : "kg", by_virtual_work([](const ForcesRow& r) { return r.reduced_inertia; })});
  columns.push_back({inertia + "_d1", angle ? "kg m^2/rad" : "kg/m",
                     by_virtual_work([](const ForcesRow& r) { return r.reduced_inertia_derivative; })});
  for (size_t j = 0; j < m.joints.size(); ++j) {
    const std::string& name = m.joints[j].name;
    columns.push_back({name + "_x", "N", computed([j](const ForcesRow& r) { return r.joints[j].force.x(); })});
    columns.push_back({name + "_y", "N", computed([j](const ForcesRow& r) { return r.joints[j].force.y(); })});
    if (m.joints[j].type == JointType::kPrismatic) {
      columns.push_back({name + "_N", "N", computed([j](const ForcesRow& r) { return r.joints[j].normal; })});
      columns.push_back({name + "_M", "N m", computed([j](const ForcesRow& r) { return r.joints[j].moment; })});
    }
  }
  columns.push_back({"singular", "1", [](const ForcesRow& r) { return std::optional<double>(r.singular ? 1.0 : 0.0); }});
  return columns;
}

std::string ToCsv(const std::vector<Column>& columns, const ForcesResult& result) {
  std::string out;
  for (size_t c = 0; c < columns.size(); ++c) out += (c ? "," : "") + columns[c].name;
  out += "\n";
  for (const ForcesRow& row : result.rows) {
    for (size_t c = 0; c < columns.size(); ++c) {
      if (c) out += ",";
      if (const std::optional<double> v = columns[c].value(row)) out += FormatNumber(*v);
    }
    out += "\n";
  }
  return out;
}

nlohmann::json ToJson(const std::vector<Column>& columns, const ForcesResult& result) {
  nlohmann::json names = nlohmann::json::array(), units = nlohmann::json::array(), rows = nlohmann::json::array();
  for (const Column& c : columns) {
    names.push_back(c.name);
    units.push_back(c.unit);
  }
  for (const ForcesRow& row : result.rows) {
    nlohmann::json values = nlohmann::json::array();
    for (const Column& c : columns) {
      if (const std::optional<double> v = c.value(row)) {
        FormatNumber(*v);  // the same refusal of non-finite numbers as CSV
        values.push_back(*v);
      } else {
        values.push_back(nullptr);
      }
    }
    rows.push_back(values);
  }
  return {{"columns", names}, {"units", units}, {"rows", rows}};
}

void RunForces(const ForcesArgs& args) {
  CheckFormat(args.format);
  const MechanismFile file = LoadMechanism(args.file, args.sets);
  const Mechanism& m = file.mechanism;
  const bool angle = m.InputIsAngle();
  auto to_internal = [&](double v) { return angle ? DegToRad(v) : v; };
  ForcesOptions options;
  options.sweep.from = to_internal(args.from.empty() ? file.sweep.from : ParseNumberFlag("--from", args.from));
  options.sweep.to = to_internal(args.to.empty() ? file.sweep.to : ParseNumberFlag("--to", args.to));
  options.sweep.step = to_internal(args.step.empty() ? file.sweep.step : ParseNumberFlag("--step", args.step));
  options.sweep.continuation.at_branch_point = ParseBranchPointFlag(args.at_branch_point);
  if (!args.speed.empty()) {
    const double speed = ParseNumberFlag("--speed", args.speed);
    options.speed = angle ? speed * 2.0 * kPi / 60.0 : speed;  // rpm -> rad/s
  }
  std::string why;
  if (!options.IsValid(&why)) {
    Complain("--from/--to/--step/--speed: " + why);
    throw Exit{kExitBadInput};
  }
  const Loads& loads = file.loads;
  if (!loads.HasMass() && loads.forces.empty() && loads.torques.empty() && loads.springs.empty())
    Complain(args.file + ": note: the file gives no masses and no loads, so every force is zero (README.md, 'Masses and loads')");
  const ForcesResult result = AnalyseForces(m, loads, options);
  if (result.bad_input) {
    Complain(args.file + ": " + result.message);
    throw Exit{kExitBadInput};
  }
  const std::vector<Column> columns = Layout(m);
  if (args.format == "csv") {
    WriteOutput(args.out, ToCsv(columns, result));
  } else {
    nlohmann::json j = ToJson(columns, result);
    j["mechanism"] = m.name;
    j["file"] = file.path;
    j["kinetostatic"] = result.kinetostatic;
    if (options.speed) j["speed"] = {{"value", ParseNumberFlag("--speed", args.speed)}, {"unit", angle ? "rpm" : "length/s"}};
    j["status"] = ToString(result.status);
    j["worst_disagreement"] = result.worst_disagreement;
    j.update(SweepEventsJson(m, result.sweep));
    if (!result.complete()) j["message"] = result.message;
    WriteOutput(args.out, JsonText(j));
  }
  ReportSweep(args.file, m, result.sweep);
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
      "(README.md, 'Masses and loads'). Without --speed: statics, the torque that holds the loads at rest.\n"
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
