// koppel simulate: the motion of a one-DOF mechanism under a drive torque (a formula or a motor
// curve) and its loads, from the equation of motion of the drive.
#include "commands.hpp"
#include "common.hpp"
#include "sweep_report.hpp"

#include "koppel/analysis/simulation.hpp"
#include "koppel/catalog/motor_curve.hpp"
#include "koppel/core/angles.hpp"

#include <fmt/core.h>

#include <filesystem>
#include <iostream>
#include <sstream>

namespace koppel::cli {
namespace simulate_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

struct SimulateArgs {
  std::string file;
  std::string torque, motor, time, initial, dt;
  std::string tolerance;
  std::vector<std::string> sets;
  std::string format = "csv";
  std::string out;
};

constexpr double kRpm = 2.0 * kPi / 60.0;  // rad/s per rpm

[[noreturn]] void BadInput(const std::string& message) {
  Complain(message);
  throw Exit{kExitBadInput};
}

// "a:b" -> {a, b}; "b" -> {0, b}.
std::pair<double, double> ParseTimeSpan(const std::string& text) {
  const auto colon = text.find(':');
  if (colon == std::string::npos) return {0.0, ParseNumberFlag("--t", text)};
  return {ParseNumberFlag("--t", text.substr(0, colon)), ParseNumberFlag("--t", text.substr(colon + 1))};
}

// "a,b" -> {a, b}
std::pair<double, double> ParsePair(const std::string& flag, const std::string& text) {
  const std::vector<double> values = ParseNumberListFlag(flag, text, 2, "input,speed");
  return {values[0], values[1]};
}

// A motor curve: "speed:torque,speed:torque,..." or a file of "speed,torque" lines
// (koppel/catalog/motor_curve.hpp). Speeds in rpm (length units/s for a P drive).
DriveLaw ParseMotor(const std::string& text, bool angle) {
  DriveLaw law;
  law.kind = DriveLaw::Kind::kMotor;
  std::vector<std::pair<std::string, std::string>> points;
  if (std::filesystem::exists(text)) {
    // a file (koppel/catalog/motor_curve.hpp), read within the input limit whatever it is
    try {
      const MotorCurveFile curve = ReadMotorCurve(text);
      for (size_t i = 0; i < curve.speeds.size(); ++i) {
        law.speeds.push_back(curve.speeds[i] * (angle ? kRpm : 1.0));
        law.torques.push_back(curve.torques[i]);
      }
      return law;
    } catch (const InputError& e) {
      for (const Diagnostic& d : e.diagnostics()) std::cerr << d.ToString() << "\n";
      throw Exit{kExitBadInput};
    }
  } else {
    std::stringstream list(text);
    for (std::string item; std::getline(list, item, ',');) {
      const auto colon = item.find(':');
      // "1500:2,5" splits into "1500:2" and "5": a decimal comma, most likely
      if (colon == std::string::npos)
        BadInput("--motor: expected 'speed:torque,...' or a file, found '" + item + "' in '" + text +
                 "' (a decimal comma? write a decimal point: 2.5, not 2,5)");
      points.emplace_back(item.substr(0, colon), item.substr(colon + 1));
    }
  }
  for (const auto& [speed, torque] : points) {
    law.speeds.push_back(ParseNumberFlag("--motor", speed) * (angle ? kRpm : 1.0));
    law.torques.push_back(ParseNumberFlag("--motor", torque));
  }
  return law;
}

// --t, --initial, --dt and --tolerance as the integrator's options (refused with exit 2).
SimulationOptions OptionsOf(const SimulateArgs& args, const Mechanism& m) {
  const bool angle = m.InputIsAngle();
  SimulationOptions options;
  std::tie(options.t_start, options.t_end) = ParseTimeSpan(args.time);
  options.initial_input = m.hint.input;
  if (!args.initial.empty()) {
    const auto [input, speed] = ParsePair("--initial", args.initial);
    options.initial_input = angle ? DegToRad(input) : input;
    options.initial_speed = speed * (angle ? kRpm : 1.0);
  }
  options.output_step = args.dt.empty() ? (options.t_end - options.t_start) / 200.0 : ParseNumberFlag("--dt", args.dt);
  if (!args.tolerance.empty()) options.relative_tolerance = options.absolute_tolerance = ParseNumberFlag("--tolerance", args.tolerance);
  std::string why;
  if (!options.IsValid(&why)) BadInput("--t/--initial/--dt/--tolerance: " + why);
  return options;
}

// The rows as they are printed: t, the input, its speed, every output, the drive's torque (or
// force) and the energies; `units` receives each column's unit (lengths in the file's unit).
Table SimulationTable(const MechanismFile& file, const SimulationResult& result, std::vector<std::string>& units) {
  const Mechanism& m = file.mechanism;
  const bool angle = m.InputIsAngle();
  const double speed_unit = angle ? kRpm : 1.0;
  const std::string length = file.loads.LengthUnit();
  Table table;
  units = {"s", angle ? "deg" : length, angle ? "rpm" : length + "/s"};
  table.columns = {"t", m.drive.input_name, "speed"};
  for (int o = 0; o < static_cast<int>(m.outputs.size()); ++o) {
    const Output& out = m.outputs[o];
    for (int c = 0; c < out.Components(); ++c) {
      table.columns.push_back(out.Components() == 2 ? out.name + (c == 0 ? "_x" : "_y") : out.name);
      units.push_back(m.OutputIsAngle(o) ? "deg" : length);
    }
  }
  for (const char* name : {angle ? "torque" : "force", "E_kin", "E_pot"}) table.columns.push_back(name);
  for (const char* unit : {angle ? "N m" : "N", "J", "J"}) units.push_back(unit);
  for (const SimulationRow& r : result.rows) {
    std::vector<double> row = {r.time, angle ? RadToDeg(r.input) : r.input, r.speed / speed_unit};
    int column = 0;
    for (int o = 0; o < static_cast<int>(m.outputs.size()); ++o) {
      for (int c = 0; c < m.outputs[o].Components(); ++c, ++column) {
        row.push_back(m.OutputIsAngle(o) ? RadToDeg(r.outputs[column]) : r.outputs[column]);
      }
    }
    row.insert(row.end(), {r.drive, r.kinetic_energy, r.potential_energy});
    table.rows.push_back(std::move(row));
  }
  return table;
}

void RunSimulate(const SimulateArgs& args) {
  CheckFormat(args.format);
  if (args.torque.empty() == args.motor.empty()) BadInput("give the drive torque: either --torque FORMULA or --motor CURVE");
  const MechanismFile file = LoadMechanism(args.file, args.sets);
  const Mechanism& m = file.mechanism;
  DriveLaw law;
  if (!args.torque.empty()) {
    law.kind = DriveLaw::Kind::kFormula;
    law.formula = args.torque;
  } else {
    law = ParseMotor(args.motor, m.InputIsAngle());
  }
  const SimulationOptions options = OptionsOf(args, m);
  const SimulationResult result = Simulate(m, file.loads, law, options);
  // the message goes to the input it is about: the file (loads), the drive flag or the options
  switch (result.bad_part) {
    case SimulationResult::BadPart::kNone: break;
    case SimulationResult::BadPart::kLoads: BadInput(args.file + ": " + result.message);
    case SimulationResult::BadPart::kDrive: BadInput((args.torque.empty() ? "--motor " : "--torque ") + (args.torque.empty() ? args.motor : args.torque) + ": " + result.message);
    case SimulationResult::BadPart::kOptions: BadInput("--t/--initial/--dt/--tolerance: " + result.message);
  }

  std::vector<std::string> units;
  const Table table = SimulationTable(file, result, units);
  if (args.format == "csv") {
    WriteOutput(args.out, table.ToCsv());
  } else {
    nlohmann::json j = table.ToJson();
    j["units"] = units;
    j["mechanism"] = m.name;
    j["file"] = file.path;
    j["status"] = ToString(result.status);
    j["steps"] = result.steps;
    j["evaluations"] = result.evaluations;
    j["singular_points"] = SingularPointsJson(m, result.singular_points);
    if (!result.complete()) j["message"] = result.message;
    WriteOutput(args.out, JsonText(j));
  }
  ReportSingularPoints(args.file, m, result.singular_points);
  if (!result.complete()) {
    Complain(args.file + ": " + result.message);
    throw Exit{kExitFailed};
  }
}

}  // namespace
}  // namespace simulate_command

void AddSimulateCommand(CLI::App& app) {
  using namespace simulate_command;
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "The motion of a one-DOF mechanism under a drive torque and the file's masses and loads (README.md,\n"
      "'Masses and loads'): the equation of motion J_red phi'' + 1/2 J_red' phi'^2 = M(phi, phi', t),\n"
      "integrated by Boost.Odeint's Dormand-Prince 5(4) with error control, positions solved at every step.\n"
      "The drive torque [N m; N for a P drive] acts on the drive joint's second link: --torque FORMULA, a\n"
      "formula of the input (radians), its speed NAME_dot (rad/s), t [s], the outputs and the parameters\n"
      "(--torque 0 for free motion); or --motor CURVE, a motor characteristic torque over speed, linear\n"
      "between its points, 'rpm:Nm,rpm:Nm,...' or a file of 'rpm,Nm' lines. Columns: t [s], the input\n"
      "[deg or length], speed [rpm; length/s for a P drive], every output (angles in degrees), torque (the\n"
      "drive's), E_kin and E_pot [J] (gravity and springs; formula loads and dampers have no potential).\n"
      "The run stops with exit 1, keeping its rows, where the motion cannot go on: a dead centre of the\n"
      "drive, a speed beyond the motor curve, a formula without a finite value.\n"
      "Example: koppel simulate tests/data/slider-crank-loads.yaml --motor 0:40,2900:0,3100:-5 --t 0:2");
  cmd->add_option("file", args->file, "Mechanism YAML file with masses and loads")->required();
  cmd->add_option("--torque", args->torque, "Drive torque formula [N m; N for a P drive]");
  cmd->add_option("--motor", args->motor, "Motor curve: 'rpm:Nm,rpm:Nm,...' or a file of 'rpm,Nm' lines");
  cmd->add_option("--t", args->time, "Time span 'T0:T1' or 'T' (from 0) [s]")->required();
  cmd->add_option("--initial", args->initial, "Initial input and speed 'deg,rpm' (length, length/s for a P drive); "
                                              "default: the assembly input, at rest");
  cmd->add_option("--dt", args->dt, "Time between table rows [s] (default: the span / 200)");
  cmd->add_option("--tolerance", args->tolerance, "Relative and absolute error per step of the integrator (default 1e-10)");
  cmd->add_option("--set", args->sets, "Override a parameter: NAME=VALUE (a formula; repeatable)");
  cmd->add_option("--format", args->format, "csv (default) or json");
  OutputFile(cmd->add_option("-o,--output-file", args->out, "Write to this file instead of stdout"));
  cmd->callback([args] { RunSimulate(*args); });
}

}  // namespace koppel::cli
