#include "koppel/synthesis/motion_dyads.hpp"

#include <fmt/core.h>

namespace koppel {
namespace {

DyadChoice Refused(BurmesterStatus status, std::string message) {
  DyadChoice c;
  c.status = status;
  c.message = std::move(message);
  return c;
}

}  // namespace

DyadChoice DyadsForPoses(const std::vector<Pose>& poses, const DyadRequest& request) {
  const size_t n = poses.size();
  if (n < 2 || n > 5) return Refused(BurmesterStatus::kInvalidRequest, fmt::format("motion generation takes 2 to 5 poses, not {}", n));
  DyadChoice choice;
  if (n == 5) {
    if (!request.circle_points.empty())
      return Refused(BurmesterStatus::kInvalidRequest, "five poses fix the dyads (the Ball-Burmester points): no circle points");
    const BallBurmester bb = BallBurmesterPoints(poses);
    choice.status = bb.status;
    choice.message = bb.message;
    choice.dyads = bb.dyads;
    return choice;
  }
  if (n == 4 && request.circle_points.empty()) {
    if (request.curve_samples < 1 || request.curve_samples > 1000)
      return Refused(BurmesterStatus::kInvalidRequest, "the centre-point curve's samples must be 1 to 1000");
    const BurmesterCurves curves = CentrePointCurve(poses, request.curve_samples, false);
    if (!curves.ok()) return Refused(curves.status, curves.message);
    for (const BurmesterCurveSample& s : curves.samples) choice.dyads.push_back(s.dyad);
    choice.status = BurmesterStatus::kOk;
    return choice;
  }
  if (request.circle_points.empty())
    return Refused(BurmesterStatus::kInvalidRequest,
                   n == 2 ? "two poses: give the circle points (twice for a four-bar)" : "three poses: give the circle points (twice for a four-bar)");
  for (const Eigen::Vector2d& c : request.circle_points) {
    const CentrePointResult r = n == 2 ? CentrePointTwoPoses(poses, c, request.crank_turn) : CentrePoint(poses, c);
    if (r.ok()) {
      choice.dyads.push_back(r.dyad);
    } else if (!request.skip_unsolvable || r.status == BurmesterStatus::kInvalidRequest) {
      return Refused(r.status, fmt::format("circle point ({}, {}): {}", c.x(), c.y(), r.message));
    }
  }
  choice.status = BurmesterStatus::kOk;
  return choice;
}

}  // namespace koppel
