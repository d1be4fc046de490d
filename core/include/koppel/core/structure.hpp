// Structural analysis read off the joint graph alone (no positions): how many links take part
// in 2, 3, 4 ... joints, joints by type, the Grübler–Kutzbach mobility, and the structure
// formula (Strukturbild) as text. The actual mobility needs the constraint Jacobian's rank and
// is computed by the solver (solver/structure_rank.hpp).
#pragma once

#include "koppel/core/mechanism.hpp"

#include <map>
#include <string>

namespace koppel {

struct StructureSummary {
  int links = 0;                        // including the frame
  std::map<int, int> links_by_degree;   // joints per link -> number of links (2 binary, 3 ternary ...)
  int joints = 0;
  int revolute = 0;                     // "D"
  int prismatic = 0;                    // "S"
  int gruebler_mobility = 0;            // 3 (n - 1) - 2 j for one-DOF joints
  int drive_joints = 0;
  int drive_joints_at_frame = 0;
  std::string formula;                  // one line per joint: "A0: D frame-crank (drive)"
};

StructureSummary AnalyseStructure(const Mechanism& mechanism);

// The link an output belongs to (Abtriebsglied): the moving link of an output joint (link_b,
// or link_a when link_b is the frame), the link of a link angle or point. -1 for outputs that
// span several links (distance, direction between links) or a transmission angle.
int OutputLink(const Mechanism& mechanism, const Output& output);

// The crank length l1: the distance between the drive link's drive joint point and its other
// joint point (the reference length of the seeds' relative figures). 0 when the drive link has
// no second joint.
double CrankLength(const Mechanism& mechanism);

// "binary", "ternary", "quaternary", ... for a link with `degree` joints.
std::string DegreeName(int degree);

}  // namespace koppel
