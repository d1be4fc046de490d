// The dyads that can guide a plane through its poses, chosen by how many poses there are (the
// choice `koppel synth motion` and the API's SynthesiseMotion make before pairing them into
// four-bars with FourBarsFromDyads):
//   5 poses fix them: the Ball–Burmester points (no circle points may be given);
//   4 poses: the given circle points' centre points, or else the centre-point curve sampled along
//     `curve_samples` lines through the base pole;
//   3 poses: one centre point per given circle point;
//   2 poses: one per circle point for the crank turning `crank_turn` [rad] between the poses.
#pragma once

#include "koppel/synthesis/burmester.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel {

struct DyadRequest {
  std::vector<Eigen::Vector2d> circle_points;  // global, in the first pose
  double crank_turn = 0;                       // two poses only [rad]
  int curve_samples = 18;                      // four poses without circle points
  // Leave out circle points that have no centre point (a grid of candidates); otherwise the
  // first such point ends the choice with its status.
  bool skip_unsolvable = false;
};

struct DyadChoice {
  BurmesterStatus status = BurmesterStatus::kNoSolution;
  std::string message;  // why not; or, with dyads, what the Ball–Burmester search noted
  std::vector<Dyad> dyads;
  bool ok() const { return status == BurmesterStatus::kOk; }
};

// kInvalidRequest for fewer than 2 or more than 5 poses, circle points with five poses, none with
// two or three, or curve_samples outside 1..1000.
DyadChoice DyadsForPoses(const std::vector<Pose>& poses, const DyadRequest& request);

}  // namespace koppel
