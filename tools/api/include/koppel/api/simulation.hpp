// The motion of a Model under a drive torque and the file's masses and loads (koppel simulate;
// koppel/analysis/simulation.hpp explains the equation of motion), as a table in the model's
// units: t [s], the input [deg | length], its speed [rpm | length/s], every output [deg | length],
// the drive's torque [N m] (force [N] for a P drive), E_kin and E_pot [J].
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/api/model.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace koppel {

// The drive law is one of: a torque formula (of the input in radians, its speed NAME_dot in
// rad/s, t, the outputs and the parameters), a motor curve given as points, or a motor curve file
// (koppel/catalog/motor_curve.hpp: `speed,torque` lines). Speeds in rpm (length/s for a P drive).
struct MotionRequest {
  std::string torque;
  std::vector<std::pair<double, double>> motor;  // (speed, torque) points
  std::string motor_file;
  double t_start = 0, t_end = 1;          // [s]
  std::optional<double> initial_input;    // [deg | length]; unset: the assembly hint's input
  double initial_speed = 0;               // [rpm | length/s]
  std::optional<double> dt;               // [s] between rows; unset: (t_end - t_start) / 200
  std::optional<double> tolerance;        // the integrator's relative and absolute error per step; unset: 1e-10
};

struct Motion {
  // complete: reached t_end; partial: the motion cannot go on (message), rows up to there;
  // failed: no pose at the start, or bad input (bad_input names which).
  AnalysisStatus status = AnalysisStatus::kNotRun;
  std::string message;
  // Which input `message` is about when the run was refused: "loads" (the mechanism file),
  // "drive" (the torque formula or motor curve) or "options" (the time span, start, step,
  // tolerance); empty otherwise.
  std::string bad_input;
  std::vector<std::string> columns, units;
  std::vector<std::vector<double>> rows;
  long steps = 0;        // accepted integrator steps
  long evaluations = 0;  // right-hand sides (each a solved pose)
  std::vector<SingularPosition> singular_points;  // met on the way
  bool complete() const { return status == AnalysisStatus::kComplete; }
  std::string Brief() const;
};

// Throws InputError for a request with no drive law or two, and for a motor curve file that does
// not read (its diagnostics). Every other refusal is a Motion with bad_input set.
Motion SimulateMotion(const Model& model, const MotionRequest& request);

}  // namespace koppel
