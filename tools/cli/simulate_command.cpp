// koppel simulate: the motion of a one-DOF mechanism under a drive torque (a formula or a motor
// curve) and its loads, from the equation of motion of the drive.
#include "commands.hpp"
#include "common.hpp"
#include "model_loading.hpp"
#include "sweep_report.hpp"

#include "koppel/api/simulation.hpp"

#include <filesystem>
#include <sstream>
#include <tuple>

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

// --motor: a file of "speed,torque" lines (read by the API), or "speed:torque,speed:torque,...".
void ParseMotor(const std::string& text, MotionRequest& request) {
  if (std::filesystem::exists(text)) {
    request.motor_file = text;
    return;
  }
  std::stringstream list(text);
  std::vector<std::pair<std::string, std::string>> points;
  for (std::string item; std::getline(list, item, ',');) {
    const auto colon = item.find(':');
    // "1500:2,5" splits into "1500:2" and "5": a decimal comma, most likely
    if (colon == std::string::npos)
      BadInput("--motor: expected 'speed:torque,...' or a file, found '" + item + "' in '" + text +
               "' (a decimal comma? write a decimal point: 2.5, not 2,5)");
    points.emplace_back(item.substr(0, colon), item.substr(colon + 1));
  }
  for (const auto& [speed, torque] : points) request.motor.emplace_back(ParseNumberFlag("--motor", speed), ParseNumberFlag("--motor", torque));
}

// The flags as a request (refused with exit 2 where a flag does not read).
MotionRequest RequestOf(const SimulateArgs& args) {
  MotionRequest request;
  if (!args.torque.empty()) {
    request.torque = args.torque;
  } else {
    ParseMotor(args.motor, request);
  }
  std::tie(request.t_start, request.t_end) = ParseTimeSpan(args.time);
  if (!args.initial.empty()) {
    const std::vector<double> values = ParseNumberListFlag("--initial", args.initial, 2, "input,speed");
    request.initial_input = values[0];
    request.initial_speed = values[1];
  }
  if (!args.dt.empty()) request.dt = ParseNumberFlag("--dt", args.dt);
  if (!args.tolerance.empty()) request.tolerance = ParseNumberFlag("--tolerance", args.tolerance);
  return request;
}

// A refused run: the message goes to the input it is about, the file (loads), the drive flag or the options.
void ReportRefusal(const SimulateArgs& args, const Motion& motion) {
  if (motion.bad_input == "loads") BadInput(args.file + ": " + motion.message);
  if (motion.bad_input == "drive")
    BadInput((args.torque.empty() ? "--motor " : "--torque ") + (args.torque.empty() ? args.motor : args.torque) + ": " + motion.message);
  if (motion.bad_input == "options") BadInput("--t/--initial/--dt/--tolerance: " + motion.message);
}

void RunSimulate(const SimulateArgs& args) {
  CheckFormat(args.format);
  if (args.torque.empty() == args.motor.empty()) BadInput("give the drive torque: either --torque FORMULA or --motor CURVE");
  const Model model = LoadModel(args.file, args.sets);
  const MotionRequest request = RequestOf(args);
  const Motion motion = Checked([&] { return SimulateMotion(model, request); });
  ReportRefusal(args, motion);

  const Table table{motion.columns, motion.rows};
  if (args.format == "csv") {
    WriteOutput(args.out, table.ToCsv());
  } else {
    nlohmann::json j = table.ToJson();
    j["units"] = motion.units;
    j["mechanism"] = model.mechanism().name;
    j["file"] = model.path();
    j["status"] = ToString(motion.status);
    j["steps"] = motion.steps;
    j["evaluations"] = motion.evaluations;
    j["singular_points"] = SingularPointsJson(motion.singular_points);
    if (!motion.complete()) j["message"] = motion.message;
    WriteOutput(args.out, JsonText(j));
  }
  ReportSingularPoints(args.file, model, motion.singular_points);
  if (!motion.complete()) {
    Complain(args.file + ": " + motion.message);
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
      "The motion of a one-DOF mechanism under a drive torque and the file's masses and loads\n"
      "(docs/mechanism-file.md, 'Masses and loads'): the equation of motion J_red phi'' + 1/2 J_red' phi'^2 = M(phi, phi', t),\n"
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
