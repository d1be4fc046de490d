#include "koppel/plot/parts.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/constraints.hpp"
#include "plot_support.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace koppel::plot {
namespace {

using Vec = Eigen::Vector2d;

// A link's body frame in the pose: global = origin + R(theta) local (the frame: the identity).
struct Placement {
  Vec origin = Vec::Zero();
  double theta = 0;
  Vec Global(const Vec& local) const { return origin + Eigen::Rotation2Dd(theta) * local; }
  Vec Direction(const Vec& local) const { return Eigen::Rotation2Dd(theta) * local; }
};

Placement PlacementOf(const ConstraintSystem& system, int link, const Eigen::VectorXd& q) {
  const int c = system.CoordinateOf(link);
  if (c < 0) return {};
  return {Vec(q[c], q[c + 1]), q[c + 2]};
}

// Two joints that share a point of a link share its hole: the same point within this fraction of
// the length scale (far below any hole the workshop drills).
constexpr double kSamePoint = 1e-9;

class PartBuilder {
 public:
  PartBuilder(const Mechanism& m, const Eigen::VectorXd& q, const std::vector<std::pair<double, double>>& travel,
              const PartSizes& sizes)
      : m_(m), system_(m), q_(q), travel_(travel), sizes_(sizes), same_(kSamePoint * LengthScale(m)) {}

  Part Build(int link) const {
    const Link& l = m_.links[link];
    const Placement at = PlacementOf(system_, link, q_);
    Part part;
    part.link = l.name;
    part.frame = l.is_frame;
    std::vector<Vec> body;  // what the plate must cover
    for (const NamedPoint& p : l.points) body.push_back(at.Global(p.local));
    std::vector<bool> joint_point(l.points.size(), false);
    for (size_t j = 0; j < m_.joints.size(); ++j) {
      const Joint& joint = m_.joints[j];
      if (joint.type == JointType::kPrismatic && joint.link_a == link) {
        part.slots.push_back(SlotOf(static_cast<int>(j), at));
        body.push_back(part.slots.back().from);
        body.push_back(part.slots.back().to);
        joint_point[joint.point_a] = true;
        continue;
      }
      // the hole: an R joint's on both links, a P joint's pin on the block
      int point = -1;
      if (joint.link_b == link) point = joint.point_b;
      else if (joint.link_a == link && joint.type == JointType::kRevolute) point = joint.point_a;
      if (point < 0) continue;
      joint_point[point] = true;
      AddHole(part, at.Global(l.points[point].local), joint.name);
    }
    for (size_t i = 0; i < l.points.size(); ++i)
      if (!joint_point[i] && !l.is_frame) part.marks.emplace_back(l.points[i].name, body[i]);
    if (!l.is_frame) part.outline = RoundedHull(body, sizes_.plate_width / 2);
    return part;
  }

 private:
  void AddHole(Part& part, const Vec& centre, const std::string& joint) const {
    for (const Hole& h : part.holes)
      if ((h.centre - centre).norm() <= same_) return;
    part.holes.push_back({centre, sizes_.pin_diameter, joint});
  }

  Slot SlotOf(int j, const Placement& guide) const {
    const Joint& joint = m_.joints[j];
    const Vec p = m_.links[joint.link_a].points[joint.point_a].local;
    Slot slot;
    slot.joint = joint.name;
    slot.from = guide.Global(p + travel_[j].first * joint.axis);
    slot.to = guide.Global(p + travel_[j].second * joint.axis);
    slot.outline = RoundedHull({slot.from, slot.to}, sizes_.pin_diameter / 2);
    return slot;
  }

  const Mechanism& m_;
  ConstraintSystem system_;
  const Eigen::VectorXd& q_;
  const std::vector<std::pair<double, double>>& travel_;
  const PartSizes& sizes_;
  double same_;
};

}  // namespace

Vec Arc::From() const { return centre + radius * Vec(std::cos(start), std::sin(start)); }
Vec Arc::To() const { return centre + radius * Vec(std::cos(start + sweep), std::sin(start + sweep)); }

Contour RoundedHull(const std::vector<Vec>& points, double radius) {
  const std::vector<Vec> hull = ConvexHull(points);
  Contour contour;
  if (hull.empty()) return contour;
  if (hull.size() == 1) {
    contour.arcs = {{hull[0], radius, 0, kPi}, {hull[0], radius, kPi, kPi}};
    return contour;
  }
  // edge i runs from hull[i] to hull[i + 1]; on a counter-clockwise hull its outward normal is
  // the edge turned clockwise. The arc at vertex i turns from edge i-1's normal to edge i's.
  const size_t n = hull.size();
  std::vector<double> normal_angle(n);
  for (size_t i = 0; i < n; ++i) {
    const Vec d = hull[(i + 1) % n] - hull[i];
    normal_angle[i] = std::atan2(-d.x(), d.y());
  }
  for (size_t i = 0; i < n; ++i) {
    const double from = normal_angle[(i + n - 1) % n];
    double sweep = std::remainder(normal_angle[i] - from, 2 * kPi);
    if (sweep <= 0) sweep += 2 * kPi;  // a convex corner turns left; two points turn by pi
    contour.arcs.push_back({hull[i], radius, from, sweep});
  }
  return contour;
}

bool PartSizes::IsValid(std::string* why) const {
  why->clear();
  if (!std::isfinite(plate_width) || !std::isfinite(pin_diameter) || !(pin_diameter > 0))
    *why = "the pin diameter and the plate width must be positive numbers";
  else if (!(pin_diameter < plate_width))
    *why = "the pin diameter must be smaller than the plate width (a hole as wide as the plate cuts it through)";
  return why->empty();
}

PartSizes DefaultPartSizes(const Mechanism& m) {
  double shortest = std::numeric_limits<double>::infinity();
  for (int l = 0; l < static_cast<int>(m.links.size()); ++l) {
    if (m.links[l].is_frame) continue;
    std::vector<Vec> joints;
    for (const Joint& j : m.joints) {
      if (j.link_a == l) joints.push_back(m.links[l].points[j.point_a].local);
      if (j.link_b == l) joints.push_back(m.links[l].points[j.point_b].local);
    }
    for (size_t a = 0; a < joints.size(); ++a)
      for (size_t b = a + 1; b < joints.size(); ++b)
        if (const double d = (joints[a] - joints[b]).norm(); d > kSamePoint * LengthScale(m)) shortest = std::min(shortest, d);
  }
  PartSizes sizes;
  sizes.plate_width = std::isfinite(shortest) ? shortest / 4 : LengthScale(m) / 10;
  sizes.pin_diameter = sizes.plate_width / 2;
  return sizes;
}

std::vector<Part> PartsAtPose(const Mechanism& m, const Eigen::VectorXd& q, const std::vector<std::pair<double, double>>& travel,
                              const PartSizes& sizes) {
  std::string why;
  const ConstraintSystem system(m);
  if (q.size() != system.NumCoordinates()) throw std::invalid_argument("PartsAtPose: pose of the wrong size");
  if (travel.size() != m.joints.size()) throw std::invalid_argument("PartsAtPose: one travel per joint expected");
  if (!sizes.IsValid(&why)) throw std::invalid_argument("PartsAtPose: " + why);
  const PartBuilder builder(m, q, travel, sizes);
  std::vector<Part> parts;
  const int frame = m.FrameLink();
  if (frame >= 0) parts.push_back(builder.Build(frame));
  for (int l = 0; l < static_cast<int>(m.links.size()); ++l)
    if (l != frame) parts.push_back(builder.Build(l));
  return parts;
}

}  // namespace koppel::plot
