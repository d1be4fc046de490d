// AnalyseMotionFourBar, MotionFourBarCount and FourBarsFromDyads
// (solver/synthesis/src/motion_synthesis.cpp): the re-analysis of a four-bar known to carry the
// plane through the poses must pass it, with the crank angles, Grashof type and mu_min of
// independent geometry; the pairs are counted by hand.
#include "koppel/synthesis/motion_synthesis.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/plane.hpp"
#include "koppel/solver/sweep.hpp"
#include "koppel/synthesis/four_bar_design.hpp"
#include "support/closed_forms.hpp"

#include "hand_picked_four_bar.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::motion_synthesis_test {
namespace {

// Poses from the solver (Newton to 1e-13 of the size) against the drawn geometry: the issue's
// 1e-9 of the mechanism's size (~4).
constexpr double kPose = 1e-9;
// mu_min (refined by Newton from a 1-degree search) against a closed form sampled every 1e-4 rad:
// mu is quadratic at an interior minimum, so the sampled minimum is high by < 1e-8 rad.
constexpr double kMuMin = 1e-7;

// The plane's poses at the drawn input plus the offsets (the solver's sweep of the known four-bar).
std::vector<Pose> PosesOf(const Mechanism& m, const std::vector<double>& offsets_deg) {
  std::vector<Pose> poses;
  for (double offset : offsets_deg) {
    SweepOptions s;
    s.from = s.to = m.hint.input + DegToRad(offset);
    s.order = 0;
    const SweepResult r = Sweep(m, s);
    REQUIRE(r.complete());
    poses.push_back({{r.outputs(0, 0), r.outputs(0, 1)}, r.outputs(0, 2)});
  }
  return poses;
}

TEST_CASE("the known crank-rocker passes with its crank angles, type and mu_min", "[motion_synthesis]") {
  const FourBarGeometry g = test::HandPickedFourBar(0.3);
  const std::vector<double> offsets = {0, 40, 95};
  const std::vector<Pose> poses = PosesOf(DesignedFourBar(g, "known"), offsets);
  const MotionFourBar f = AnalyseMotionFourBar(poses, {g.a0, g.a}, {g.b0, g.b});
  INFO(f.message);
  REQUIRE(f.passes);
  CHECK(f.pose_error <= kPose);
  CHECK_FALSE(f.branch_defect);
  CHECK_FALSE(f.order_defect);
  CHECK(f.grashof == GrashofType::kCrankRocker);
  CHECK(f.crank_turns_fully);
  // reference: the crank's drawn angle plus the offsets the poses were made at
  const double phi0 = Direction(g.a - g.a0);
  REQUIRE(f.pose_inputs.size() == offsets.size());
  for (size_t j = 0; j < offsets.size(); ++j)
    CHECK_THAT(f.pose_inputs[j], Catch::Matchers::WithinAbs(phi0 + DegToRad(offsets[j]), kPose));
  CHECK_THAT(f.drive_to - f.drive_from, Catch::Matchers::WithinAbs(2 * kPi, kPose));
  // reference: the closed form of the crank-rocker's mu (tests/support, law of cosines) sampled
  // over the travel, with the crank angle measured from the frame line A0 -> B0
  const double a = (g.a - g.a0).norm(), b = (g.b - g.a).norm(), c = (g.b0 - g.b).norm(), d = (g.b0 - g.a0).norm();
  const double frame = Direction(g.b0 - g.a0);
  double mu_min = 1e300;
  for (double phi = f.pose_inputs.front(); phi <= f.pose_inputs.back(); phi += 1e-4)
    mu_min = std::min(mu_min, test::CrankRockerMu(a, b, c, d, phi - frame));
  mu_min = std::min(mu_min, test::CrankRockerMu(a, b, c, d, f.pose_inputs.back() - frame));
  CHECK_THAT(f.mu_min, Catch::Matchers::WithinAbs(mu_min, kMuMin));
}

TEST_CASE("poses out of the crank's order are an order defect", "[motion_synthesis]") {
  // reference, a hand count: driven ccw the crank meets them 0, 95, 40, 150 deg on, driven cw
  // 0, 265, 320, 210 deg on: neither in order (three poses are always in order one way round)
  const FourBarGeometry g = test::HandPickedFourBar(0.3);
  const std::vector<Pose> poses = PosesOf(DesignedFourBar(g, "known"), {0, 95, 40, 150});
  const MotionFourBar f = AnalyseMotionFourBar(poses, {g.a0, g.a}, {g.b0, g.b});
  CHECK(f.order_defect);
  // 0, 95, 40 alone are in order clockwise (0, 265, 320 deg on): no defect, the travel runs cw
  const MotionFourBar three = AnalyseMotionFourBar(PosesOf(DesignedFourBar(g, "known"), {0, 95, 40}), {g.a0, g.a}, {g.b0, g.b});
  INFO(three.message);
  CHECK_FALSE(three.order_defect);
  REQUIRE(three.pose_inputs.size() == 3);
  CHECK(three.pose_inputs[1] < three.pose_inputs[0]);
}

TEST_CASE("dyads sharing a point are no four-bar", "[motion_synthesis]") {
  const FourBarGeometry g = test::HandPickedFourBar(0.3);
  const std::vector<Pose> poses = PosesOf(DesignedFourBar(g, "known"), {0, 40, 95});
  const MotionFourBar f = AnalyseMotionFourBar(poses, {g.a0, g.a}, {g.a0, g.b});  // A0 = B0
  CHECK_FALSE(f.passes);
  CHECK_THAT(f.message, Catch::StartsWith("a link of zero length"));
}

TEST_CASE("the pairs of n dyads are n (n - 1), or half of them driven one way", "[motion_synthesis]") {
  // reference: a hand count of ordered and unordered pairs
  MotionOptions both, one;
  one.both_drives = false;
  CHECK(MotionFourBarCount(0, both) == 0);
  CHECK(MotionFourBarCount(1, both) == 0);
  CHECK(MotionFourBarCount(2, both) == 2);
  CHECK(MotionFourBarCount(5, both) == 20);
  CHECK(MotionFourBarCount(5, one) == 10);
  CHECK(MotionFourBarCount(100000, both) == 9999900000ull);  // no 32-bit overflow
}

TEST_CASE("every pair of dyads is accounted for, the known four-bar among the passing", "[motion_synthesis]") {
  const FourBarGeometry g = test::HandPickedFourBar(0.3);
  const std::vector<Pose> poses = PosesOf(DesignedFourBar(g, "known"), {0, 40, 95});
  // the known dyads and a third whose circle point is the plane's origin, centre elsewhere
  const std::vector<Dyad> dyads = {{g.a0, g.a}, {g.b0, g.b}, {{1.5, -1.0}, g.plane_origin}};
  for (bool both : {true, false}) {
    MotionOptions options;
    options.both_drives = both;
    options.threads = 2;
    const MotionResult r = FourBarsFromDyads(poses, dyads, options);
    INFO("both drives " << both);
    CHECK(static_cast<std::uint64_t>(r.four_bars.size() + r.rejected + r.failed) == MotionFourBarCount(dyads.size(), options));
    CHECK(r.failures.size() == static_cast<size_t>(r.failed));
    bool known = false;
    for (const MotionFourBar& f : r.four_bars) {
      known = known || ((f.crank.centre - g.a0).norm() == 0 && (f.rocker.centre - g.b0).norm() == 0);
      CHECK(f.passes);
    }
    CHECK(known);
    for (size_t i = 1; i < r.four_bars.size(); ++i) CHECK(r.four_bars[i - 1].mu_min >= r.four_bars[i].mu_min);
  }
}

TEST_CASE("motion options reject nonsense", "[motion_synthesis]") {
  MotionOptions o;
  std::string why;
  CHECK(o.IsValid(&why));
  o.threads = -1;
  CHECK_FALSE(o.IsValid(&why));
  CHECK_FALSE(why.empty());
}

}  // namespace
}  // namespace koppel::motion_synthesis_test
