// The dyads by the number of poses (motion_dyads.hpp), on the poses of the crank-rocker
// A0 (0, 0), A (1, 0.2), B (3.1, 2.4), B0 (4, 0.3) read off koppel's sweep
// (tests/data/motion-five-poses.yaml): the known pivots are an exact answer, and every dyad
// returned is checked against the circle conditions |A_j - A0| = |A_1 - A0| evaluated here.
#include "koppel/synthesis/motion_dyads.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::motion_dyads_test {
namespace {

std::vector<Pose> FivePoses() {
  const double p[5][3] = {{2.2, 3.3, 15},
                          {2.48598787909819, 3.48145273691967, 6.11892321283816},
                          {2.4665273929408, 3.50994854354389, -3.90644221239416},
                          {1.95132500529917, 3.08335354035025, -12.1217291854381},
                          {1.42227564999058, 2.23224622167394, -11.1093603534674}};
  std::vector<Pose> poses;
  for (const auto& q : p) poses.push_back({Eigen::Vector2d(q[0], q[1]), DegToRad(q[2])});
  return poses;
}

// The largest difference of |A_j - A0| from |A_1 - A0| over the poses, A_j moved with the plane.
double CircleError(const std::vector<Pose>& poses, const Dyad& d) {
  const double r1 = (d.circle - d.centre).norm();
  double worst = 0;
  for (const Pose& p : poses) {
    const double t = p.angle - poses[0].angle;
    const Eigen::Vector2d local = d.circle - poses[0].point;
    const Eigen::Vector2d a = p.point + Eigen::Vector2d(std::cos(t) * local.x() - std::sin(t) * local.y(), std::sin(t) * local.x() + std::cos(t) * local.y());
    worst = std::max(worst, std::abs((a - d.centre).norm() - r1));
  }
  return worst;
}

bool HasCentre(const DyadChoice& c, const Eigen::Vector2d& centre) {
  for (const Dyad& d : c.dyads)
    if ((d.centre - centre).norm() < 1e-7) return true;
  return false;
}

}  // namespace

TEST_CASE("dyads for five, four, three poses contain the known pivots and meet the circle conditions", "[motion]") {
  const std::vector<Pose> all = FivePoses();
  for (size_t n : {5, 4, 3}) {
    const std::vector<Pose> poses(all.begin(), all.begin() + static_cast<long>(n));
    DyadRequest request;
    if (n == 3) request.circle_points = {{1, 0.2}, {3.1, 2.4}};
    const DyadChoice c = DyadsForPoses(poses, request);
    INFO(n << " poses: " << c.message);
    REQUIRE(c.ok());
    REQUIRE(!c.dyads.empty());
    for (const Dyad& d : c.dyads) CHECK(CircleError(poses, d) < 1e-7 * (1 + (d.circle - d.centre).norm()));
    if (n != 4) {  // the sampled centre-point curve passes near, not through, the known pivots
      CHECK(HasCentre(c, {0, 0}));
      CHECK(HasCentre(c, {4, 0.3}));
    }
  }
}

TEST_CASE("dyads: requests that do not fit the number of poses are invalid", "[motion]") {
  const std::vector<Pose> all = FivePoses();
  DyadRequest with_points;
  with_points.circle_points = {{1, 0.2}};
  CHECK(DyadsForPoses(all, with_points).status == BurmesterStatus::kInvalidRequest);              // five fix them
  CHECK(DyadsForPoses({all[0], all[1], all[2]}, {}).status == BurmesterStatus::kInvalidRequest);  // three need points
  CHECK(DyadsForPoses({all[0]}, with_points).status == BurmesterStatus::kInvalidRequest);
  DyadRequest samples;
  samples.curve_samples = 0;
  CHECK(DyadsForPoses({all[0], all[1], all[2], all[3]}, samples).status == BurmesterStatus::kInvalidRequest);
}

}  // namespace koppel::motion_dyads_test
