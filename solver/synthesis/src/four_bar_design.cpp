#include "koppel/synthesis/four_bar_design.hpp"

#include "koppel/analysis/extremes.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/build.hpp"
#include "koppel/core/plane.hpp"

#include <cmath>

namespace koppel {
namespace {

// A global point in the body frame (origin, angle).
Eigen::Vector2d Local(const Eigen::Vector2d& global, const Eigen::Vector2d& origin, double angle) {
  const Eigen::Vector2d d = global - origin;
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
}

// A binary link with its body x axis along from -> to.
void AddBar(Mechanism& m, const std::string& name, const std::string& from_name, const Eigen::Vector2d& from,
            const std::string& to_name, const Eigen::Vector2d& to) {
  AddLink(m, name, {{from_name, Eigen::Vector2d::Zero()}, {to_name, Eigen::Vector2d((to - from).norm(), 0.0)}});
}

}  // namespace

std::optional<double> TransmissionMinimum(const Mechanism& designed, double from, double to) {
  SweepOptions stretch;
  stretch.from = from;
  stretch.to = to;
  stretch.step = DegToRad(1);
  const OutputExtremes mu = FindOutputExtremes(designed, 3, 0, stretch);  // outputs P, theta, psi, mu
  if (!mu.sweep.complete() || !Usable(mu.status)) return std::nullopt;
  return mu.minimum.value;
}

Mechanism DesignedFourBar(const FourBarGeometry& g, const std::string& name) {
  Mechanism m;
  m.name = name;
  AddLink(m, "frame", {{"A0", g.a0}, {"B0", g.b0}}, true);
  AddBar(m, "crank", "A0", g.a0, "A", g.a);
  AddLink(m, "coupler", {{"A", Local(g.a, g.plane_origin, g.plane_angle)},
                         {"B", Local(g.b, g.plane_origin, g.plane_angle)},
                         {"P", Eigen::Vector2d::Zero()}});
  AddBar(m, "rocker", "B0", g.b0, "B", g.b);
  Revolute(m, "A0", "frame", "crank");
  Revolute(m, "A", "crank", "coupler");
  Revolute(m, "B", "coupler", "rocker");
  Revolute(m, "B0", "frame", "rocker");
  // joint angle of A0 = the crank's angle against +x; the input reads `input` in this pose
  const double crank_angle = Direction(g.a - g.a0);
  SetDrive(m, "A0", crank_angle - g.input.value_or(crank_angle));
  PointOutput(m, "P", "coupler", "P");
  LinkAngleOutput(m, "theta", "coupler");
  const double rocker_angle = Direction(g.b - g.b0);
  LinkAngleOutput(m, "psi", "rocker").offset = rocker_angle - g.psi.value_or(rocker_angle);
  TransmissionOutput(m, "mu", "coupler", "B");
  HintInput(m, g.input.value_or(crank_angle));
  HintPoint(m, "crank", "A", g.a);
  HintPoint(m, "coupler", "A", g.a);
  HintPoint(m, "coupler", "B", g.b);
  HintPoint(m, "coupler", "P", g.plane_origin);
  HintPoint(m, "rocker", "B", g.b);
  return m;
}

std::optional<Eigen::Vector2d> FourBarJointB(const Eigen::Vector2d& a, const Eigen::Vector2d& b0, double b, double c, int branch) {
  const Eigen::Vector2d d = b0 - a;
  const double r = d.norm();
  if (!(r > 0)) return std::nullopt;
  // law of cosines in the triangle A B B0: the angle at A between A -> B0 and A -> B
  const double cos_gamma = (b * b + r * r - c * c) / (2 * std::abs(b) * r);
  if (!(cos_gamma >= -1 && cos_gamma <= 1)) return std::nullopt;
  const double gamma = Direction(d) + branch * std::acos(cos_gamma);
  return Eigen::Vector2d(a + std::abs(b) * Eigen::Vector2d(std::cos(gamma), std::sin(gamma)));
}

int FourBarBranch(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& b0) {
  const double s = Cross(b0 - a, b - a);
  return s > 0 ? 1 : s < 0 ? -1 : 0;
}

}  // namespace koppel
