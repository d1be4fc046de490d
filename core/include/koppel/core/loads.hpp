// Masses and loads of a mechanism: what statics, kinetostatics and the equation of motion need
// beside the geometry. Kept apart from Mechanism, which the kinematics never needs to carry them.
//
// Units: SI (kg, N, s, m) for every quantity here, except lengths that belong to the geometry —
// centres of gravity and the free lengths of springs — which are in the mechanism's length unit;
// `metres_per_unit` says how long that unit is (1 when the file is in metres). So a file drawn in
// millimetres declares 0.001 and keeps its points in millimetres; forces come out in N, torques in
// N m, moments of inertia are kg m^2. Angles in radians, as everywhere inside koppel.
//
// Magnitudes of forces and torques are formulas (muparser, see expression.hpp) over the file's
// parameters and the names of LoadVariables(): the drive input (radians or length unit), its speed
// (rad/s or length unit/s), the time t [s], and every output by name (point outputs as NAME_x,
// NAME_y) in radians or length units, offsets applied.
#pragma once

#include "koppel/core/expression.hpp"
#include "koppel/core/mechanism.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel {

struct LinkMass {
  int link = -1;
  double mass = 0.0;                                // [kg]
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // centre of gravity, body frame of the link [length unit]
  double inertia = 0.0;                             // moment of inertia about the centre of gravity [kg m^2]
};

// A force magnitude * direction acting on a link at one of its points. The direction is fixed in
// the frame, or turns with `direction_link` (given in that link's body frame).
struct PointForce {
  std::string name;
  PointRef point;
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // unit
  int direction_link = -1;  // the link whose body frame holds `direction`; the frame link for a fixed direction
  std::string magnitude;    // formula [N]
};

// A torque on a link, counter-clockwise positive [N m] (its reaction is not modelled: it comes
// from outside the mechanism).
struct LinkTorque {
  std::string name;
  int link = -1;
  std::string magnitude;  // formula [N m]
};

// A linear spring and viscous damper in parallel between two points. Its tension
// stiffness (r - free_length) + damping dr/dt pulls the two points together (r their distance).
struct SpringDamper {
  std::string name;
  PointRef from, to;
  double stiffness = 0.0;    // [N/m]
  double free_length = 0.0;  // [length unit]
  double damping = 0.0;      // [N s/m]
};

struct Loads {
  double metres_per_unit = 1.0;                       // the mechanism's length unit [m]
  bool length_unit_given = false;                     // the file says its unit (`units: {length: ...}`)
  std::string length_unit_name;                       // the unit's name as the file gives it ("mm"); empty: a number or none
  Eigen::Vector2d gravity = Eigen::Vector2d::Zero();   // [m/s^2], global frame
  std::vector<LinkMass> masses;                       // at most one per link
  std::vector<PointForce> forces;
  std::vector<LinkTorque> torques;
  std::vector<SpringDamper> springs;
  ParameterSet parameters;  // the constants the magnitude formulas may name (the file's parameters)

  bool HasMass() const;  // some link has a mass or a moment of inertia
  // The label of the file's length unit in outputs: its name ("mm"), "<metres> m" for a unit
  // given as a number of metres, "length" when the file names none (lengths are the file's own).
  std::string LengthUnit() const;
};

// The names a magnitude formula may use besides the parameters, in this order: the drive input
// (mechanism.drive.input_name), its speed (input_name + "_dot"), "t", then every output
// (a point output NAME as NAME_x and NAME_y).
std::vector<std::string> LoadVariables(const Mechanism& mechanism);

// Empty when the loads fit the mechanism: indices in range, no mass on the frame link, one mass
// per link, finite non-negative masses, inertias, stiffnesses, dampings and free lengths, unit
// directions, metres_per_unit > 0.
std::vector<std::string> CheckLoads(const Mechanism& mechanism, const Loads& loads);

}  // namespace koppel
