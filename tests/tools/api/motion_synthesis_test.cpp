// Motion generation as `koppel synth motion` runs it (tools/api/src/motion_synthesis.cpp): the
// poses file, the circle-point grid (checked against the poses' own box), the Burmester curves
// (each sample checked by the definition of a centre point: equally far from the circle point's
// four positions), and the report of a search with its work limit.
#include "koppel/api/motion_synthesis.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/diagnostic.hpp"
#include "koppel/core/limits.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace koppel;
using Catch::Matchers::WithinAbs;

namespace motion_synthesis_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

// the poses file's numbers, read back through degrees
constexpr double kRead = 1e-12;
// grid arithmetic: a few roundings of numbers of order 10
constexpr double kGrid = 1e-12;
// a sample of the centre-point curve is refined to meet its four positions: the distances agree
// to 1e-9 of the poses' size (about 1 here), with margin
constexpr double kCentrePoint = 1e-7;

// The circle point (global, first pose) carried into pose j.
std::pair<double, double> Carried(const std::vector<MotionPose>& poses, size_t j, double x, double y) {
  const double turn = DegToRad(poses[j].angle - poses[0].angle), dx = x - poses[0].x, dy = y - poses[0].y;
  return {poses[j].x + std::cos(turn) * dx - std::sin(turn) * dy, poses[j].y + std::sin(turn) * dx + std::cos(turn) * dy};
}

}  // namespace

TEST_CASE("ReadMotionPoses: the file's poses in degrees; a bad file names its line", "[api]") {
  const std::vector<MotionPose> poses = ReadMotionPoses(test::TestDataPath("motion-three-poses.yaml"));
  REQUIRE(poses.size() == 3);
  CHECK_THAT(poses[0].x, WithinAbs(2.2, kRead));
  CHECK_THAT(poses[0].y, WithinAbs(3.3, kRead));
  CHECK_THAT(poses[0].angle, WithinAbs(15, kRead));
  CHECK_THAT(poses[2].angle, WithinAbs(-3.90644221239416, kRead));
  CHECK_THROWS_AS(ReadMotionPoses(test::TestDataPath("no-such-poses.yaml")), InputError);
}

TEST_CASE("MotionGrid: n x n cell centres, symmetric about the poses' box", "[api]") {
  const std::vector<MotionPose> poses = ReadMotionPoses(test::TestDataPath("motion-three-poses.yaml"));
  const auto grid = MotionGrid(poses, 4);
  REQUIRE(grid.size() == 16);
  double lo_x = poses[0].x, hi_x = lo_x, lo_y = poses[0].y, hi_y = lo_y;
  for (const MotionPose& p : poses) {
    lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x), lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
  }
  // the mean of the cell centres is the box's centre (the margin is the same on every side)
  double mx = 0, my = 0;
  for (const auto& [x, y] : grid) mx += x / 16, my += y / 16;
  CHECK_THAT(mx, WithinAbs(0.5 * (lo_x + hi_x), kGrid));
  CHECK_THAT(my, WithinAbs(0.5 * (lo_y + hi_y), kGrid));
  // evenly spaced, and the margin reaches beyond the poses on each side
  const double step = grid[4].first - grid[0].first;
  CHECK_THAT(grid[8].first - grid[4].first, WithinAbs(step, kGrid));
  CHECK(grid.front().first < lo_x);
  CHECK(grid.back().first > hi_x);
  CHECK_THROWS_AS(MotionGrid(poses, 0), InputError);
  CHECK_THROWS_AS(MotionGrid(poses, 101), InputError);
}

TEST_CASE("MotionCurves: every centre point is equally far from its circle point's four positions", "[api]") {
  const std::vector<MotionPose> poses = ReadMotionPoses(test::TestDataPath("motion-four-poses.yaml"));
  REQUIRE(poses.size() == 4);
  const BurmesterCurveTable curves = MotionCurves(poses);
  INFO(curves.message);
  REQUIRE(curves.status == DesignStatus::kOk);
  CHECK(curves.table.columns == std::vector<std::string>{"direction", "centre_x", "centre_y", "circle_x", "circle_y"});
  REQUIRE(curves.table.rows.size() > 100);
  for (const std::vector<double>& row : curves.table.rows) {
    const double r0 = std::hypot(row[3] - row[1], row[4] - row[2]);
    for (size_t j = 1; j < 4; ++j) {
      const auto [x, y] = Carried(poses, j, row[3], row[4]);
      CHECK_THAT(std::hypot(x - row[1], y - row[2]), WithinAbs(r0, kCentrePoint * std::max(1.0, r0)));
    }
  }
  CHECK_THROWS_AS(MotionCurves(std::vector<MotionPose>(poses.begin(), poses.begin() + 3)), InputError);
}

TEST_CASE("SynthesiseMotionReport: a grid search, its files, and the work limit before the work", "[api]") {
  MotionSpec spec;
  spec.poses = ReadMotionPoses(test::TestDataPath("motion-three-poses.yaml"));
  spec.grid = 3;
  const MotionReport report = SynthesiseMotionReport(spec, "three.yaml");
  INFO(report.message);
  REQUIRE(report.paired);
  CHECK(report.dyads <= 9);
  CHECK(report.failed == 0);
  REQUIRE(report.status == DesignStatus::kOk);
  for (size_t i = 0; i < report.designs.size(); ++i) {
    const Design& d = report.designs[i];
    CHECK(d.model->name() == "four-bar-" + std::to_string(i + 1));
    // the file reads back as the same four-bar: the crank pivot where the figures put it
    const Model back = Model::Parse(d.yaml, "four-bar.yaml");
    CHECK(back.sweep_to() > back.sweep_from());
    // the first defect_free without a branch or order defect, each part by mu_min, largest first
    const bool free = static_cast<int>(i) < report.defect_free;
    CHECK(free == (d.Get("branch_defect") == 0 && d.Get("order_defect") == 0));
    if (i > 0 && free == (static_cast<int>(i) - 1 < report.defect_free)) CHECK(report.designs[i - 1].Get("mu_min") >= d.Get("mu_min"));
  }
  // --grid 20: 400 circle points, about 160 000 four-bars: refused as a status, nothing paired
  spec.grid = 20;
  const MotionReport over = SynthesiseMotionReport(spec, "three.yaml");
  CHECK(over.status == DesignStatus::kInvalidRequest);
  CHECK(over.four_bars > static_cast<double>(kMaxMotionFourBars));
  CHECK_FALSE(over.paired);
  CHECK(over.designs.empty());
  CHECK_THROWS_AS(SynthesiseMotion(spec), InputError);
  spec.grid = 3;
  spec.poses.push_back(spec.poses.back());
  spec.poses.back().x += 1;
  CHECK_THROWS_AS(SynthesiseMotionReport(spec), InputError);  // a grid is for three poses
}

}  // namespace motion_synthesis_test
