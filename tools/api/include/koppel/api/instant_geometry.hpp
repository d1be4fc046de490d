// What koppel::Model::Curvature, Poles and Centrodes return (koppel curvature, koppel poles): the
// instantaneous geometry of the motion at one input, in the API's units (model.hpp): positions in
// the file's length unit, global frame; inputs in degrees for an R drive. The theory and the
// formulas: koppel/analysis/curvature.hpp and instant_centres.hpp.
#pragma once

#include "koppel/analysis/status.hpp"

#include <optional>
#include <string>
#include <vector>

namespace koppel {

struct Point2 {
  double x = 0, y = 0;
};

// A named number as the CLI prints it (quantity,value,unit): empty where it does not exist.
struct NamedValue {
  std::string name;
  std::optional<double> value;
  std::string unit;
};

// The motion of the link that carries a point, against the frame, and that point's path.
// Every optional is empty where the quantity does not exist here; `message` says why.
struct CurvatureReport {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // complete; partial: some quantities do not exist; failed: no pose
  std::string message;
  double input = 0;       // [deg | length]
  std::string input_name, input_unit;  // "phi", "deg" or the length unit
  std::string length_unit = "length";  // the file's ("mm"): the unit of every length figure
  std::string point;      // the point as named, e.g. "K"
  std::string link;       // the link that carries it
  Point2 position;        // K_x, K_y
  std::optional<Point2> pole;            // the instant centre; empty: the link translates (pole at infinity)
  std::optional<Point2> pole_direction;  // unit vector of the pole's velocity along the fixed centrode (pole tangent)
  std::optional<Point2> inflection_centre;  // centre of the inflection circle (Wendekreis)
  std::optional<Point2> inflection_pole;    // W (Wendepol), diametrically opposite the pole
  std::optional<double> inflection_diameter;  // 0 when the link turns about a fixed pivot
  std::optional<Point2> ball_point;      // Ballscher Punkt, where it exists
  std::optional<double> curvature;       // signed 1/rho [1/length]; 0 at an inflection; empty at a cusp
  std::optional<double> rho;             // signed radius of curvature; empty at an inflection or a cusp
  std::optional<Point2> centre;          // centre of curvature (with rho)
  // Everything under the names koppel curvature prints: the input (input_name), POINT_x, POINT_y,
  // pole_x, pole_y, pole_direction_x/_y, inflection_x/_y (the circle's centre),
  // inflection_diameter, inflection_pole_x/_y, ball_x/_y, curvature, rho, centre_x/_y.
  std::vector<NamedValue> Quantities() const;
  std::string Brief() const;
};

// The instant centre of two links.
struct InstantCentreEntry {
  std::string link_a, link_b;
  bool defined = true;       // false: the two links move together (no pole)
  bool at_infinity = false;  // relative translation: the pole lies at infinity in `direction`
  bool from_acceleration = false;  // the relative motion stood still: the pole of the accelerations
  Point2 position;           // finite poles
  Point2 direction;          // poles at infinity (unit vector)
};

struct PolesReport {
  AnalysisStatus status = AnalysisStatus::kNotRun;
  std::string message;
  double input = 0;  // [deg | length]
  std::vector<InstantCentreEntry> centres;  // every pair, links in file order
  std::string Brief() const;
};

// The centrodes of `link` against `reference`: at each input the pole in the reference link's
// frame (the fixed centrode, Rastpolbahn; global for the frame) and in the link's own (the moving
// centrode, Gangpolbahn), and the moving centrode carried to the pose at `at` (where the two
// curves touch at the pole) so both can be drawn in one picture.
struct CentrodesReport {
  AnalysisStatus status = AnalysisStatus::kNotRun;
  std::string message;
  std::string link, reference;
  std::vector<double> inputs;                      // [deg | length]
  std::vector<std::optional<Point2>> fixed, moving, moving_at;  // empty where the pole is at infinity
  std::string Brief() const;
};

}  // namespace koppel
