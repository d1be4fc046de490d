// The loads of a mechanism (core/loads.hpp) at one pose and state of motion, as forces at points
// and torques on links in SI units, and what follows from them: the generalised forces Q on the
// solver's coordinates (for the joint reactions, multipliers.hpp), the drive torque by the
// principle of virtual work, and the potential energy of gravity and springs.
//
// A pose is given by the Taylor coefficients of the coordinates q(input) about it, columns
// q, dq/dinput, d2q/dinput2 / 2 (PositionSolver::Series with order >= 2). "Per input" means per
// radian for an R drive and per metre of slide for a P drive (the input's length unit converted
// with Loads::metres_per_unit), so that drive torques come out in N m and drive forces in N.
#pragma once

#include "koppel/core/formula.hpp"
#include "koppel/core/loads.hpp"
#include "koppel/solver/constraints.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel {

// The drive's state: input (rad or length unit), its speed and acceleration per second, the time.
struct MotionState {
  double input = 0.0;
  double speed = 0.0;
  double acceleration = 0.0;
  double time = 0.0;
};

// A point fixed to a link, moving with the input: position [m] and its first two derivatives by
// the SI input (m/rad or m/m), global frame.
struct PointMotion {
  Eigen::Vector2d p = Eigen::Vector2d::Zero(), d1 = Eigen::Vector2d::Zero(), d2 = Eigen::Vector2d::Zero();
};
// A link's angle [rad] and its first two derivatives by the SI input.
struct AngleMotion {
  double theta = 0.0, d1 = 0.0, d2 = 0.0;
};

// The kinematics of one pose in SI: built from the Taylor coefficients and the units.
class PoseMotion {
 public:
  PoseMotion(const ConstraintSystem& system, const Eigen::MatrixXd& series, double metres_per_unit);
  PointMotion Point(int link, const Eigen::Vector2d& local) const;  // local: body frame, length unit
  PointMotion Point(const PointRef& ref) const;
  AngleMotion Angle(int link) const;
  const ConstraintSystem& system() const { return system_; }
  const Eigen::MatrixXd& series() const { return series_; }
  double metres_per_unit() const { return metres_per_unit_; }
  double metres_per_input() const { return metres_per_input_; }  // 1 for an R drive

 private:
  const ConstraintSystem& system_;
  const Eigen::MatrixXd& series_;
  double metres_per_unit_;
  double metres_per_input_;
};

// What acts on the moving links: forces at points and torques, SI, with the transfer functions of
// their points and links (for virtual work).
struct AppliedLoads {
  struct Force {
    int link = -1;
    PointMotion at;                                    // where it acts
    Eigen::Vector2d force = Eigen::Vector2d::Zero();   // [N], global frame
  };
  struct Torque {
    int link = -1;
    AngleMotion of;
    double torque = 0.0;  // [N m], counter-clockwise positive
  };
  std::vector<Force> forces;
  std::vector<Torque> torques;
  void Add(const AppliedLoads& other);
};

// The mechanism's loads with their formulas compiled, ready to be evaluated at many poses.
class LoadModel {
 public:
  // The error names the load when a magnitude formula does not compile or the loads do not fit
  // the mechanism (CheckLoads). Keeps references: both must outlive the model.
  Outcome Prepare(const Mechanism& mechanism, const Loads& loads);

  // The loads at the pose (gravity, forces, torques, springs and dampers; no inertia) into *out
  // (reused from call to call); an error when a magnitude formula has no finite value there.
  Outcome Evaluate(const PoseMotion& pose, const MotionState& state, AppliedLoads* out) const;

  // Potential energy of gravity and springs at the pose [J] (dampers and formula loads have none).
  double PotentialEnergy(const PoseMotion& pose) const;

  // The variable values of a formula at the pose (see LoadVariables): for the drive torque formula
  // of a simulation, compiled over the same names.
  std::vector<double> Variables(const PoseMotion& pose, const MotionState& state) const;

  const Loads& loads() const { return *loads_; }
  const Mechanism& mechanism() const { return *mechanism_; }

 private:
  const Mechanism* mechanism_ = nullptr;
  const Loads* loads_ = nullptr;
  std::vector<CompiledFormula> force_magnitudes_, torque_magnitudes_;
};

// Q: the generalised forces of `loads` on the coordinates (N on x, y; N m about each link's
// body origin on theta).
Eigen::VectorXd GeneralizedForces(const PoseMotion& pose, const AppliedLoads& loads);

// The drive torque (force for a P drive) that holds `loads` by the principle of virtual work:
// -sum F . dp/dinput - sum M dtheta/dinput.
double VirtualWorkDrive(const AppliedLoads& loads);

}  // namespace koppel
