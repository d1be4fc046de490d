// Building a Mechanism in code, by name: links with their points, R and P joints, the drive,
// outputs and the assembly hint, each referring to links, points and joints by the names a
// mechanism file would use. For the code that makes mechanisms (synthesis, cognates, tests);
// files are read by the catalog. A name that does not exist is a bug in the calling code:
// std::invalid_argument naming it. Conventions as in mechanism.hpp (radians, body frames).
#pragma once

#include "koppel/core/mechanism.hpp"

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace koppel {

using PointList = std::vector<std::pair<std::string, Eigen::Vector2d>>;

// Adds a link with its points (body frame; for the frame link, global); returns its index.
int AddLink(Mechanism& m, const std::string& name, const PointList& points, bool frame = false);

// An R joint: point `point_a` of link_a on point `point_b` of link_b; both default to the joint's
// name (the usual way: the pin B joins the points called B on both links).
Joint& Revolute(Mechanism& m, const std::string& name, const std::string& link_a, const std::string& link_b,
                const std::string& point_a = "", const std::string& point_b = "");
// A P joint: the block's point `on_block` slides on the guide's line through `on_guide` along
// `axis` (guide body frame; normalised here), keeping the rotation `angle` against the guide.
Joint& Prismatic(Mechanism& m, const std::string& name, const std::string& guide, const std::string& on_guide,
                 const std::string& block, const std::string& on_block, const Eigen::Vector2d& axis, double angle = 0.0);

// The drive on joint `joint`: input = joint value - zero.
void SetDrive(Mechanism& m, const std::string& joint, double zero = 0.0, const std::string& input_name = "phi");

// Outputs, named as in a mechanism file's `outputs:`.
Output& JointOutput(Mechanism& m, const std::string& name, const std::string& joint);
Output& LinkAngleOutput(Mechanism& m, const std::string& name, const std::string& link);
Output& PointOutput(Mechanism& m, const std::string& name, const std::string& link, const std::string& point);
Output& DistanceOutput(Mechanism& m, const std::string& name, const std::string& link_p, const std::string& p,
                       const std::string& link_q, const std::string& q);
Output& DirectionOutput(Mechanism& m, const std::string& name, const std::string& link_p, const std::string& p,
                        const std::string& link_q, const std::string& q);
Output& TransmissionOutput(Mechanism& m, const std::string& name, const std::string& coupler, const std::string& joint);

// The assembly hint: the input it describes, and rough global positions of link points there.
void HintInput(Mechanism& m, double input);
void HintPoint(Mechanism& m, const std::string& link, const std::string& point, const Eigen::Vector2d& global);

// The point `point` of link `link`, by name.
PointRef PointByName(const Mechanism& m, const std::string& link, const std::string& point);

}  // namespace koppel
