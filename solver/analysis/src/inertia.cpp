#include "koppel/analysis/inertia.hpp"

namespace koppel {

ReducedInertia ReduceInertia(const PoseMotion& pose, const std::vector<LinkMass>& masses) {
  // J_red = sum m p'.p' + J_S theta'^2, so dJ_red/dinput = 2 sum m p'.p'' + J_S theta' theta''
  ReducedInertia r;
  for (const LinkMass& mass : masses) {
    const PointMotion s = pose.Point(mass.link, mass.centre);
    const AngleMotion a = pose.Angle(mass.link);
    r.value += mass.mass * s.d1.squaredNorm() + mass.inertia * a.d1 * a.d1;
    r.derivative += 2.0 * (mass.mass * s.d1.dot(s.d2) + mass.inertia * a.d1 * a.d2);
  }
  return r;
}

AppliedLoads InertiaLoads(const PoseMotion& pose, const std::vector<LinkMass>& masses, const MotionState& state) {
  AppliedLoads loads;
  const double speed = state.speed * pose.metres_per_input();
  const double acceleration = state.acceleration * pose.metres_per_input();
  for (const LinkMass& mass : masses) {
    const PointMotion s = pose.Point(mass.link, mass.centre);
    const AngleMotion a = pose.Angle(mass.link);
    const Eigen::Vector2d a_s = s.d2 * speed * speed + s.d1 * acceleration;
    const double alpha = a.d2 * speed * speed + a.d1 * acceleration;
    if (mass.mass > 0.0) loads.forces.push_back({mass.link, s, -mass.mass * a_s});
    if (mass.inertia > 0.0) loads.torques.push_back({mass.link, a, -mass.inertia * alpha});
  }
  return loads;
}

double KineticEnergy(const PoseMotion& pose, const std::vector<LinkMass>& masses, double speed) {
  const double v = speed * pose.metres_per_input();
  return 0.5 * ReduceInertia(pose, masses).value * v * v;
}

}  // namespace koppel
