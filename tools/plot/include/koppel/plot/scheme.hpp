// The kinematic scheme (kinematisches Schema) of any mechanism at a solved pose, in the usual
// notation: frame pivots hatched, revolute joints as circles, sliders as blocks on their guides
// (a hatched line on the frame, a slot on a moving link), binary links as bars, links with
// three or more points as polygons, point labels, and the drive arrow (counter-clockwise for an
// R drive at the frame: the positive sense of the input). Optional: faint overlays of other
// poses (the dead centres of seed 000 "Bild 3", labels with a suffix) and a traced curve.
//
// Each moving link is one SVG group drawn in its body frame with a transform; with `animatable`
// the groups and labels carry their coordinates as data attributes so that the page of
// `koppel view` moves the same drawing by changing transforms only.
#pragma once

#include "koppel/core/mechanism.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel::plot {

struct OverlayPose {
  Eigen::VectorXd q;
  std::string suffix;  // appended to the point labels: "a" gives A_a
};

struct SchemeScene {
  Eigen::VectorXd q;                 // the pose drawn (the solver's coordinates)
  std::string caption;               // e.g. "φ = 120°"
  std::vector<OverlayPose> overlays;
  std::vector<std::vector<Eigen::Vector2d>> trace;  // global points, one subpath per run
  std::string trace_name;
  std::vector<Eigen::VectorXd> extent;  // poses the view and the guides must cover (the sweep)
  double width = 640;                   // px
  bool animatable = false;
};

// Precondition: CheckConsistency(mechanism) is empty and every q has NumCoordinates() entries
// (throws std::invalid_argument otherwise).
std::string DrawScheme(const Mechanism& mechanism, const SchemeScene& scene);

}  // namespace koppel::plot
