#include "koppel/analysis/loads_at_pose.hpp"

#include "koppel/core/plane.hpp"

#include <cmath>

namespace koppel {
PoseMotion::PoseMotion(const ConstraintSystem& system, const Eigen::MatrixXd& series, double metres_per_unit)
    : system_(system),
      series_(series),
      metres_per_unit_(metres_per_unit),
      metres_per_input_(system.mechanism().InputIsAngle() ? 1.0 : metres_per_unit) {}

PointMotion PoseMotion::Point(int link, const Eigen::Vector2d& local) const {
  PointMotion m;
  const int i = system_.CoordinateOf(link);
  if (i < 0) {
    m.p = local * metres_per_unit_;
    return m;
  }
  // p = o + R c;  p' = o' + theta' k x (R c);  p'' = o'' + theta'' k x (R c) - theta'^2 R c,
  // with the Taylor coefficients o' = c_1, o'' = 2 c_2 (derivatives by the input in its own unit)
  const Eigen::Vector2d r = Rotate(series_(i + 2, 0), local);
  const double w = series_(i + 2, 1), dw = 2.0 * series_(i + 2, 2);
  const Eigen::Vector2d o(series_(i, 0), series_(i + 1, 0)), o1(series_(i, 1), series_(i + 1, 1)),
      o2(2.0 * series_(i, 2), 2.0 * series_(i + 1, 2));
  const double to_si = metres_per_unit_ / metres_per_input_;  // d/dinput -> d/dinput_SI
  m.p = (o + r) * metres_per_unit_;
  m.d1 = (o1 + w * Perp(r)) * to_si;
  m.d2 = (o2 + dw * Perp(r) - w * w * r) * (to_si / metres_per_input_);
  return m;
}

PointMotion PoseMotion::Point(const PointRef& ref) const {
  return Point(ref.link, system_.mechanism().links[ref.link].points[ref.point].local);
}

AngleMotion PoseMotion::Angle(int link) const {
  AngleMotion a;
  const int i = system_.CoordinateOf(link);
  if (i < 0) return a;
  a.theta = series_(i + 2, 0);
  a.d1 = series_(i + 2, 1) / metres_per_input_;
  a.d2 = 2.0 * series_(i + 2, 2) / (metres_per_input_ * metres_per_input_);
  return a;
}

void AppliedLoads::Add(const AppliedLoads& other) {
  forces.insert(forces.end(), other.forces.begin(), other.forces.end());
  torques.insert(torques.end(), other.torques.begin(), other.torques.end());
}

Outcome LoadModel::Prepare(const Mechanism& mechanism, const Loads& loads) {
  mechanism_ = &mechanism;
  loads_ = &loads;
  if (const std::vector<std::string> problems = CheckLoads(mechanism, loads); !problems.empty())
    return Outcome::Error(problems.front());
  const std::vector<std::string> variables = LoadVariables(mechanism);
  auto compile = [&](const std::string& what, const std::string& formula, std::vector<CompiledFormula>& into) -> Outcome {
    Expected<CompiledFormula> f = CompiledFormula::Compile(formula, loads.parameters, variables);
    if (!f) return Outcome::Error(what + ": " + f.error());
    into.push_back(std::move(*f));
    return Done();
  };
  force_magnitudes_.clear();
  torque_magnitudes_.clear();
  for (const PointForce& f : loads.forces) {
    if (Outcome done = compile("force '" + f.name + "'", f.magnitude, force_magnitudes_); !done) return done;
  }
  for (const LinkTorque& t : loads.torques) {
    if (Outcome done = compile("torque '" + t.name + "'", t.magnitude, torque_magnitudes_); !done) return done;
  }
  return Done();
}

std::vector<double> LoadModel::Variables(const PoseMotion& pose, const MotionState& state) const {
  const ConstraintSystem& system = pose.system();
  std::vector<double> values = {state.input, state.speed, state.time};
  const double* q = pose.series().col(0).data();
  for (int o = 0; o < static_cast<int>(mechanism_->outputs.size()); ++o) {
    for (int c = 0; c < mechanism_->outputs[o].Components(); ++c) values.push_back(system.Output(o, c, q));
  }
  return values;
}

Outcome LoadModel::Evaluate(const PoseMotion& pose, const MotionState& state, AppliedLoads* out) const {
  const Loads& loads = *loads_;
  const Mechanism& m = *mechanism_;
  out->forces.clear();
  out->torques.clear();
  // gravity at every centre of gravity
  if (loads.gravity.squaredNorm() > 0.0) {
    for (const LinkMass& mass : loads.masses) {
      if (mass.mass > 0.0) out->forces.push_back({mass.link, pose.Point(mass.link, mass.centre), mass.mass * loads.gravity});
    }
  }
  const std::vector<double> variables = (loads.forces.empty() && loads.torques.empty()) ? std::vector<double>{}
                                                                                         : Variables(pose, state);
  auto magnitude = [&](const CompiledFormula& f, const std::string& what) -> Expected<double> {
    const double value = f.Evaluate(variables.data());
    if (std::isfinite(value)) return value;
    return Expected<double>::Error(what + ": formula '" + f.text() + "' has no finite value here");
  };
  for (size_t k = 0; k < loads.forces.size(); ++k) {
    const PointForce& f = loads.forces[k];
    const Expected<double> value = magnitude(force_magnitudes_[k], "force '" + f.name + "'");
    if (!value) return Outcome::Error(value.error());
    const double turn = m.links[f.direction_link].is_frame ? 0.0 : pose.Angle(f.direction_link).theta;
    out->forces.push_back({f.point.link, pose.Point(f.point), *value * Rotate(turn, f.direction)});
  }
  for (size_t k = 0; k < loads.torques.size(); ++k) {
    const LinkTorque& t = loads.torques[k];
    const Expected<double> value = magnitude(torque_magnitudes_[k], "torque '" + t.name + "'");
    if (!value) return Outcome::Error(value.error());
    out->torques.push_back({t.link, pose.Angle(t.link), *value});
  }
  // springs and dampers: the tension pulls `from` towards `to` and `to` towards `from`
  const double speed = state.speed * pose.metres_per_input();
  for (const SpringDamper& s : loads.springs) {
    const PointMotion a = pose.Point(s.from), b = pose.Point(s.to);
    const Eigen::Vector2d d = b.p - a.p;
    const double r = d.norm();
    if (!(r > 0.0))
      return Outcome::Error("spring '" + s.name + "': its two points coincide, so its line of action is undefined");
    const Eigen::Vector2d u = d / r;
    const double rate = u.dot(b.d1 - a.d1) * speed;  // dr/dt
    const double tension = s.stiffness * (r - s.free_length * pose.metres_per_unit()) + s.damping * rate;
    out->forces.push_back({s.from.link, a, tension * u});
    out->forces.push_back({s.to.link, b, -tension * u});
  }
  return Done();
}

double LoadModel::PotentialEnergy(const PoseMotion& pose) const {
  const Loads& loads = *loads_;
  double energy = 0.0;
  for (const LinkMass& mass : loads.masses) energy -= mass.mass * loads.gravity.dot(pose.Point(mass.link, mass.centre).p);
  for (const SpringDamper& s : loads.springs) {
    const double stretch = (pose.Point(s.to).p - pose.Point(s.from).p).norm() - s.free_length * pose.metres_per_unit();
    energy += 0.5 * s.stiffness * stretch * stretch;
  }
  return energy;
}

Eigen::VectorXd GeneralizedForces(const PoseMotion& pose, const AppliedLoads& loads) {
  const ConstraintSystem& system = pose.system();
  Eigen::VectorXd q_force = Eigen::VectorXd::Zero(system.NumCoordinates());
  for (const AppliedLoads::Force& f : loads.forces) {
    const int i = system.CoordinateOf(f.link);
    if (i < 0) continue;  // on the frame: taken by its supports
    const Eigen::Vector2d origin(pose.series()(i, 0) * pose.metres_per_unit(), pose.series()(i + 1, 0) * pose.metres_per_unit());
    q_force(i) += f.force.x();
    q_force(i + 1) += f.force.y();
    q_force(i + 2) += Cross(f.at.p - origin, f.force);
  }
  for (const AppliedLoads::Torque& t : loads.torques) {
    const int i = system.CoordinateOf(t.link);
    if (i >= 0) q_force(i + 2) += t.torque;
  }
  return q_force;
}

double VirtualWorkDrive(const AppliedLoads& loads) {
  double work = 0.0;  // virtual work of the loads per unit of input
  for (const AppliedLoads::Force& f : loads.forces) work += f.force.dot(f.at.d1);
  for (const AppliedLoads::Torque& t : loads.torques) work += t.torque * t.of.d1;
  return -work;
}

}  // namespace koppel
