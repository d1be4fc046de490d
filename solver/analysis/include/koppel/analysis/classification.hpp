// Classification of a mechanism: its mobility by count and by rank, whether the drive turns
// fully, and for four-bars and slider-cranks their Grashof type with the inequality it rests on.
//
// Four-bar (four binary links, four R joints), with s the shortest link, l the longest and p, q
// the others (Grashof 1883):
//   s + l < p + q: the shortest link turns fully against its neighbours; relative to the frame
//     crank-rocker   the shortest link is adjacent to the frame (it is the crank),
//     double-crank   the shortest link is the frame,
//     double-rocker  the shortest link is the coupler (opposite the frame);
//   s + l > p + q: triple-rocker (no link turns fully);
//   s + l = p + q: change-point (Grashof-neutral: branch points where all links line up).
// Slider-crank (RRRP with the slide on the frame), crank a, coupler b, offset e of the crank
// pivot from the line the coupler's pin runs on:
//   a + |e| < b: crank-slider (the crank turns fully); a + |e| > b: rocker-slider;
//   a + |e| = b: change-point (a branch point where the coupler stands normal to the slide).
// Equality is decided to 1e-9 L.
#pragma once

#include "koppel/core/mechanism.hpp"

#include <string>
#include <vector>

namespace koppel {

enum class GrashofType {
  kNotApplicable,  // neither a four-bar nor a slider-crank with its slide on the frame
  kCrankRocker,
  kDoubleCrank,
  kDoubleRocker,
  kTripleRocker,
  kChangePoint,
  kCrankSlider,
  kRockerSlider,
};
const char* ToString(GrashofType type);  // "crank-rocker", ..., "not-applicable"

struct Classification {
  int mobility = 0;          // Grübler–Kutzbach count
  int rank_mobility = -1;    // n - rank of the joints' equations at a regular assembled pose; -1: not assembled
  bool assembled = false;
  bool drive_turns_fully = false;  // a rotating drive that comes round to the same pose
  GrashofType grashof = GrashofType::kNotApplicable;
  // The lengths the rule compares: four-bar s, l, p, q; slider-crank a (crank), b (coupler), e (offset).
  std::vector<std::pair<std::string, double>> lengths;
  std::string rule;          // the inequality with its numbers, in words
  std::vector<std::string> notes;
};

// Grashof type and lengths of the mechanism's chain (no solving).
Classification ClassifyChain(const Mechanism& mechanism);
// Everything: the chain, the mobility check and the drivable range of the hint's branch.
Classification Classify(const Mechanism& mechanism);

}  // namespace koppel
