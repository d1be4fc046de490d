// The mechanism model: links with named points, R and P joints, one drive and named outputs.
//
// Conventions (they hold everywhere in koppel):
// - Global frame: x right, y up, lengths in the file's length unit, angles counter-clockwise
//   positive, radians inside the library (degrees only at the YAML / CLI boundary).
// - Every link has its own body frame; its points are given in that frame. The frame link
//   (Gestell) is fixed: its body frame is the global frame.
// - A moving link's pose is (x, y, theta): the global position of its body origin and the
//   rotation of its body frame against the global frame.
// - An R joint (Drehgelenk, "D") makes point_a of link_a coincide with point_b of link_b.
//   Its joint angle is theta_b - theta_a.
// - A P joint (Schubgelenk, "S") lets link_b (the block) slide along a line of link_a (the
//   guide): the line through point_a with direction axis (unit, body frame of link_a). The block
//   keeps the rotation theta_b - theta_a = angle. Its displacement is
//   s = axis_global . (p_b - p_a), positive along axis.
// A Mechanism is built once (by the catalog reader or by code) and never mutated by the solver.
#pragma once

#include "koppel/core/expected.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace koppel {

enum class JointType { kRevolute, kPrismatic };

struct NamedPoint {
  std::string name;
  Eigen::Vector2d local = Eigen::Vector2d::Zero();  // body frame of the owning link
};

struct Link {
  std::string name;
  bool is_frame = false;
  std::vector<NamedPoint> points;

  // Index of the point called `point_name`, or -1.
  int FindPoint(const std::string& point_name) const;
};

struct Joint {
  std::string name;
  JointType type = JointType::kRevolute;
  int link_a = -1;  // R: either link; P: the guide
  int link_b = -1;  // R: the other link; P: the block
  int point_a = -1;
  int point_b = -1;
  Eigen::Vector2d axis = Eigen::Vector2d::UnitX();  // P only: unit, body frame of link_a
  double angle = 0.0;  // P only: theta_b - theta_a held by the joint [rad]
};

// A point of a link, by indices.
struct PointRef {
  int link = -1;
  int point = -1;
};

// The input of the mechanism: an R joint's angle or a P joint's displacement.
// input = joint value - zero, so `zero` is the joint value at which the input reads 0
// (radians for R, length for P).
struct Drive {
  int joint = -1;
  double zero = 0.0;
  std::string input_name = "phi";
};

enum class OutputKind {
  kJoint,               // R: joint angle theta_b - theta_a [rad]; P: displacement s [length]
  kLinkAngle,           // theta of a link against the global x axis [rad]
  kPoint,               // global x, y of a link point [length] (two components)
  kDistance,            // |p - q| between two link points [length]
  kDirection,           // angle of the line p -> q against the global x axis [rad]
  kTransmissionAngle,   // see transmission.hpp in the solver: angle folded to 0..pi/2 [rad]
};

struct Output {
  std::string name;
  OutputKind kind = OutputKind::kJoint;
  int joint = -1;  // kJoint; kTransmissionAngle: the output joint
  int link = -1;   // kLinkAngle; kTransmissionAngle: the coupler link
  PointRef p;      // kPoint, kDistance, kDirection
  PointRef q;      // kDistance, kDirection
  double offset = 0.0;  // angle outputs: subtracted from the value (a zero reference) [rad]

  int Components() const { return kind == OutputKind::kPoint ? 2 : 1; }
  // What tables, charts, readouts and forms call its component `c`: the output's name for a
  // scalar, ComponentName(name, c) for a point ("K_x", "K_y").
  std::string ComponentLabel(int c) const;
};

// Component `c` (0: x, 1: y) of a point or vector named `name`: "K_x", "K_y". The one rule every
// table column, chart label and form field follows.
std::string ComponentName(const std::string& name, int c);
// The inverse: "K_y" -> ("K", 1); nothing for a name without the suffix (or only the suffix).
std::optional<std::pair<std::string, int>> SplitComponentName(const std::string& name);

// Rough global positions of points that choose the assembly branch (Einbaulage).
struct AssemblyHint {
  double input = 0.0;  // the drive input the hint describes
  struct Entry {
    PointRef point;
    Eigen::Vector2d global = Eigen::Vector2d::Zero();
  };
  std::vector<Entry> points;
};

struct Mechanism {
  std::string name;
  std::vector<Link> links;
  std::vector<Joint> joints;
  Drive drive;
  std::vector<Output> outputs;
  AssemblyHint hint;

  int FindLink(const std::string& link_name) const;
  int FindJoint(const std::string& joint_name) const;
  int FindOutput(const std::string& output_name) const;
  int FrameLink() const;  // index of the (single) frame link, -1 if none

  // Unit of the drive input: true for an angle (R joint), false for a length (P joint).
  bool InputIsAngle() const;
  // Unit of an output's value, see IsAngleOutput.
  bool OutputIsAngle(int output) const;
};

// Unit of an output's value: true for an angle (an R joint's value, a link angle, a direction,
// a transmission angle), false for a length (a P joint's displacement, a point, a distance).
// The one place that decides it.
bool IsAngleOutput(const Mechanism& mechanism, const Output& output);

// An R joint named `name` between links a and b at the point of that name on each (the usual
// way to pin two links in code). Point indices are -1 where a link lacks the point.
Joint PinJoint(const Mechanism& mechanism, const std::string& name, int link_a, int link_b);

// The point of joint j on `link` (one of its two links).
PointRef JointPointOn(const Joint& joint, int link);

// The other joint of a binary link (exactly two joints), or -1.
int OtherJointOfBinaryLink(const Mechanism& mechanism, int link, int joint);

// The mirror image in the global x axis: every sense of rotation reversed (a crank turning
// counter-clockwise turns clockwise). R joint values, link angles and R-drive inputs change sign;
// slide displacements keep theirs.
Mechanism MirrorMechanism(const Mechanism& mechanism);

// Empty when the mechanism is consistent; otherwise one message per problem. The solver
// requires a consistent mechanism (exactly one frame link, indices in range, unit P axes,
// a drive on an existing joint).
std::vector<std::string> CheckConsistency(const Mechanism& mechanism);

// Characteristic length L: the largest distance of any point from its body origin (1 when every
// point sits at its origin). Every tolerance of the solver is relative to L, so a mechanism
// scaled by 1e-6 or 1e6 gives the same dimensionless results.
double LengthScale(const Mechanism& mechanism);

// A point named as users name it: a point output ("K"), "link.point", or a point name found on
// exactly one link. The error says which of these failed (or which links share the name).
Expected<PointRef> FindPointByText(const Mechanism& mechanism, const std::string& text);

// A scalar output (an angle or a distance: one component) by name; an empty name is the first
// scalar output, the default of every command that reads one output. The error names the
// mechanism's scalar outputs.
Expected<int> FindScalarOutput(const Mechanism& mechanism, const std::string& name);

}  // namespace koppel
