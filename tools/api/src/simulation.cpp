// koppel simulate's motion in the model's units.
#include "koppel/api/simulation.hpp"

#include "display.hpp"
#include "model_impl.hpp"

#include "koppel/analysis/simulation.hpp"
#include "koppel/catalog/motor_curve.hpp"
#include "koppel/core/angles.hpp"

namespace koppel {

using namespace api_detail;

namespace {

constexpr double kRadPerSecondPerRpm = 2.0 * kPi / 60.0;

// The drive law in the solver's units (speeds per second).
DriveLaw DriveLawOf(const Model& model, const MotionRequest& request) {
  const int given = !request.torque.empty() + !request.motor.empty() + !request.motor_file.empty();
  if (given != 1) BadInput(model.path(), "drive", "give one drive law: a torque formula, a motor curve or a motor curve file");
  DriveLaw law;
  if (!request.torque.empty()) {
    law.kind = DriveLaw::Kind::kFormula;
    law.formula = request.torque;
    return law;
  }
  std::vector<std::pair<double, double>> points = request.motor;
  if (!request.motor_file.empty()) {
    const MotorCurveFile curve = ReadMotorCurve(request.motor_file);  // InputError: its diagnostics
    for (size_t i = 0; i < curve.speeds.size(); ++i) points.emplace_back(curve.speeds[i], curve.torques[i]);
  }
  const double speed_unit = model.input_is_angle() ? kRadPerSecondPerRpm : 1.0;
  law.kind = DriveLaw::Kind::kMotor;
  for (const auto& [speed, torque] : points) {
    law.speeds.push_back(speed * speed_unit);
    law.torques.push_back(torque);
  }
  return law;
}

SimulationOptions SimulationOptionsOf(const Model& model, const MotionRequest& request) {
  const Mechanism& m = model.mechanism();
  SimulationOptions options;
  options.t_start = request.t_start;
  options.t_end = request.t_end;
  options.initial_input = request.initial_input ? InputInternal(m, *request.initial_input) : m.hint.input;
  options.initial_speed = request.initial_speed * (m.InputIsAngle() ? kRadPerSecondPerRpm : 1.0);
  options.output_step = request.dt.value_or((request.t_end - request.t_start) / 200.0);
  if (request.tolerance) options.relative_tolerance = options.absolute_tolerance = *request.tolerance;
  return options;
}

// The columns and their units: t, the input, its speed, every output, the drive's torque, the energies.
void LayOut(const Model& model, Motion& motion) {
  const Mechanism& m = model.mechanism();
  const bool angle = m.InputIsAngle();
  const std::string length = model.length_unit();
  motion.units = {"s", angle ? "deg" : length, angle ? "rpm" : length + "/s"};
  motion.columns = {"t", m.drive.input_name, "speed"};
  for (int o = 0; o < static_cast<int>(m.outputs.size()); ++o) {
    const Output& out = m.outputs[o];
    for (int c = 0; c < out.Components(); ++c) {
      motion.columns.push_back(out.ComponentLabel(c));
      motion.units.push_back(m.OutputIsAngle(o) ? "deg" : length);
    }
  }
  for (const char* name : {angle ? "torque" : "force", "E_kin", "E_pot"}) motion.columns.push_back(name);
  for (const char* unit : {angle ? "N m" : "N", "J", "J"}) motion.units.push_back(unit);
}

std::vector<double> RowOf(const Mechanism& m, const SimulationRow& r) {
  const double speed_unit = m.InputIsAngle() ? kRadPerSecondPerRpm : 1.0;
  std::vector<double> row = {r.time, InputShown(m, r.input), r.speed / speed_unit};
  int column = 0;
  for (int o = 0; o < static_cast<int>(m.outputs.size()); ++o) {
    for (int c = 0; c < m.outputs[o].Components(); ++c, ++column) {
      row.push_back(m.OutputIsAngle(o) ? RadToDeg(r.outputs[column]) : r.outputs[column]);
    }
  }
  row.insert(row.end(), {r.drive, r.kinetic_energy, r.potential_energy});
  return row;
}

const char* BadPartName(SimulationResult::BadPart part) {
  switch (part) {
    case SimulationResult::BadPart::kNone: return "";
    case SimulationResult::BadPart::kLoads: return "loads";
    case SimulationResult::BadPart::kDrive: return "drive";
    case SimulationResult::BadPart::kOptions: return "options";
  }
  return "";
}

}  // namespace

std::string Motion::Brief() const {
  return std::string(ToString(status)) + ": " + std::to_string(rows.size()) + " rows, " + std::to_string(steps) + " steps" +
         (message.empty() ? "" : "; " + message);
}

Motion SimulateMotion(const Model& model, const MotionRequest& request) {
  const Mechanism& m = model.mechanism();
  const DriveLaw law = DriveLawOf(model, request);
  const SimulationResult result = Simulate(m, ModelAccess::File(model).loads, law, SimulationOptionsOf(model, request));
  Motion motion;
  motion.status = result.status;
  motion.message = result.message;
  motion.bad_input = BadPartName(result.bad_part);
  LayOut(model, motion);
  for (const SimulationRow& r : result.rows) motion.rows.push_back(RowOf(m, r));
  motion.steps = result.steps;
  motion.evaluations = result.evaluations;
  motion.singular_points = Shown(m, result.singular_points);
  return motion;
}

}  // namespace koppel
