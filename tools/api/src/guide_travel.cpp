#include "koppel/api/guide_travel.hpp"

#include "koppel/analysis/extremes.hpp"

#include <stdexcept>

namespace koppel {
namespace {

// The mechanism with the displacement of one prismatic joint as its only output: the value the
// slot must cover, searched like any other output.
Mechanism WithDisplacementOutput(const Mechanism& m, int joint) {
  Mechanism copy = m;
  Output s;
  s.name = m.joints[joint].name;
  s.kind = OutputKind::kJoint;
  s.joint = joint;
  copy.outputs = {s};
  return copy;
}

GuideTravel TravelOf(const Mechanism& m, int joint, const SweepOptions& range) {
  GuideTravel travel;
  travel.joint = joint;
  travel.name = m.joints[joint].name;
  const OutputExtremes extremes = FindOutputExtremes(WithDisplacementOutput(m, joint), 0, 0, range);
  travel.status = extremes.status;
  travel.message = extremes.message;
  // a failed search has no extremes to give (not even the samples': they fall short)
  if (!Usable(extremes.status)) return travel;
  travel.low = extremes.minimum.value;
  travel.high = extremes.maximum.value;
  return travel;
}

}  // namespace

std::vector<GuideTravel> FindGuideTravels(const Mechanism& m, double from, double to, double step, BranchPointAction at_branch_point) {
  SweepOptions range;
  range.from = from;
  range.to = to;
  range.step = step;
  range.continuation.at_branch_point = at_branch_point;
  if (std::string why; !range.IsValid(&why)) throw std::invalid_argument("FindGuideTravels: " + why);
  std::vector<GuideTravel> travels;
  for (int j = 0; j < static_cast<int>(m.joints.size()); ++j)
    if (m.joints[j].type == JointType::kPrismatic) travels.push_back(TravelOf(m, j, range));
  return travels;
}

}  // namespace koppel
