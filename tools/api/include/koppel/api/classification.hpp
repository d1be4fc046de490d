// What `koppel classify` reports, in the API's units (model.hpp): the mobility by count and by
// rank, whether the drive turns fully, and for four-bars and slider-cranks the Grashof type with
// the lengths and the inequality it rests on (the rules: koppel/analysis/classification.hpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace koppel {

class Model;

struct ModelClassification {
  int mobility = 0;          // Grübler–Kutzbach count 3(n-1) - 2j
  bool assembled = false;    // the mechanism assembles at its hint
  int rank_mobility = -1;    // n - rank of the joint equations at the assembly pose; -1 unless assembled
  // "full": an R drive that comes round to the same pose; "limited" otherwise (a P drive always)
  std::string drive_rotation;
  // "crank-rocker", "double-crank", "double-rocker", "triple-rocker", "change-point",
  // "crank-slider", "rocker-slider"; empty: neither a four-bar nor a slider-crank
  std::string grashof;
  // the lengths the rule compares [the file's length unit]: four-bar s, l, p, q; slider-crank a, b, e
  std::vector<std::pair<std::string, double>> lengths;
  std::string rule;  // the inequality with its numbers, in words (empty with no Grashof type)
  std::vector<std::string> notes;
};

// The classification of the model's mechanism (analysis Classify: the chain, the mobility check
// and the drivable range of the hint's branch).
ModelClassification ClassifyModel(const Model& model);

}  // namespace koppel
