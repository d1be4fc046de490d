// The links of a mechanism as the workshop cuts them (koppel export --dxf, koppel animate): each
// moving link a plate of width W around its points, with a hole of diameter D at each of its
// joints and a slot of width D along each guide it carries, as long as the pin travels in it;
// the frame its pivot holes and the slots of its guides, no plate. Global coordinates of one
// pose, in the mechanism's length unit; x right, y up, angles counter-clockwise.
//
// A prismatic joint is cut as a pin in a slot: the slot on the guide (the joint's first link),
// the pin's hole on the other link at its point. A pin in a slot also lets the link turn; the
// drawing is the plan of the parts, not a proof that they make the joint.
#pragma once

#include "koppel/core/mechanism.hpp"

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace koppel::plot {

// An arc around `centre` from angle `start` through `sweep` [rad], counter-clockwise positive.
struct Arc {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0, start = 0, sweep = 0;
  Eigen::Vector2d From() const;
  Eigen::Vector2d To() const;
};

// A closed convex contour: arcs in counter-clockwise order, each joined to the next by a straight
// line (their common tangent). A contour around one point is a circle: two half arcs.
struct Contour {
  std::vector<Arc> arcs;
};

// The points at distance `radius` around the convex hull of `points`: a plate of width 2 radius
// around them, a slot around its centre line. Empty for no points.
Contour RoundedHull(const std::vector<Eigen::Vector2d>& points, double radius);

struct Hole {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double diameter = 0;
  std::string joint;  // the joint it carries (the first one where joints share a point)
};

struct Slot {
  std::string joint;                         // the prismatic joint
  Eigen::Vector2d from = Eigen::Vector2d::Zero(), to = Eigen::Vector2d::Zero();  // centre line
  Contour outline;                           // width: the pin's diameter
};

struct Part {
  std::string link;     // the link's name (a layer of the DXF)
  bool frame = false;   // the frame: pivots and guides only, no outline
  Contour outline;      // the plate
  std::vector<Hole> holes;
  std::vector<Slot> slots;
  std::vector<std::pair<std::string, Eigen::Vector2d>> marks;  // the link's points that hold no joint (coupler points)
};

struct PartSizes {
  double plate_width = 0;   // W [length unit]
  double pin_diameter = 0;  // D [length unit]; 0 < D < W so that a hole leaves material around it
  // Empty *why and true when both are finite and 0 < D < W.
  bool IsValid(std::string* why) const;
};

// W = 1/4 of the shortest distance between two joint points of one moving link (a plate that
// narrow still reads as a linkage), or 1/10 of the length scale where no link has two; D = W/2.
PartSizes DefaultPartSizes(const Mechanism& mechanism);

// Every link as a part at pose q (the solver's coordinates), the frame first. Preconditions:
// CheckConsistency(mechanism) is empty, q has NumCoordinates() entries, travel has one entry per
// joint: a prismatic joint's least and greatest displacement of its pin along the guide, from the
// guide's point [length unit] (CycleSamples::travel; 0, 0 for other joints), sizes.IsValid()
// (std::invalid_argument otherwise).
std::vector<Part> PartsAtPose(const Mechanism& mechanism, const Eigen::VectorXd& q,
                              const std::vector<std::pair<double, double>>& travel, const PartSizes& sizes);

}  // namespace koppel::plot
