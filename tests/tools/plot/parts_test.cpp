// The parts of the workshop drawing: plates at half their width around the link's points, holes
// at the joints, slots over the pin's travel. References: the circle-intersection four-bar of
// tests/support/closed_forms (seed 003's dimensions) and seed 000's slider-crank (the slider's
// travel between its dead centres, s = sqrt((l2 -+ l1)^2 - e^2)); the plate's geometry against
// plain distances (independent of how the contour is built).
#include "koppel/plot/parts.hpp"

#include "tools/plot/cycle_fixtures.hpp"

#include "koppel/api/guide_travel.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/plot/sampled_run.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <random>

namespace koppel::parts_test {
namespace {

// an arc's radius is the one asked for, copied or halved: exact up to an ulp
constexpr double kCopiedRadius = 1e-15;
// [rad] sweeps of arcs from atan2 of O(1) vectors, summed over a few arcs: rounding only
constexpr double kTurnRoundoff = 1e-12;

using Vec = Eigen::Vector2d;
using Catch::Matchers::WithinAbs;

// The solver converges to 1e-12 of the length scale; the contour is built from sines and cosines.
constexpr double kTolerance = 1e-9;
// [length] a travel's end refined to its extreme (to 1e-12 in the input, where s' = 0), and the
// frame's slot placed with the identity: the closed form's value to roundoff and convergence
constexpr double kRefined = 1e-12;

struct Solved {
  Eigen::VectorXd q;
  std::vector<std::pair<double, double>> travel;
};

Solved Solve(const Mechanism& m, double input) {
  SweepOptions o;
  o.to = 2 * kPi;
  o.step = DegToRad(1);
  o.order = 0;
  const plot::SampledRun run = plot::SampleMechanism(m, o);
  REQUIRE(run.complete);
  const Expected<Eigen::VectorXd> pose = plot::PoseAt(m, run, input);
  REQUIRE(pose);
  std::vector<std::pair<double, double>> travel(m.joints.size(), {0.0, 0.0});
  for (const GuideTravel& t : FindGuideTravels(m, o.from, o.to, o.step)) {
    REQUIRE(t.status == AnalysisStatus::kComplete);
    travel[t.joint] = {t.low, t.high};
  }
  return {*pose, travel};
}

const plot::Part& PartOf(const std::vector<plot::Part>& parts, const std::string& link) {
  for (const plot::Part& p : parts)
    if (p.link == link) return p;
  FAIL("no part " << link);
  throw;
}

bool HasHoleAt(const plot::Part& part, const Vec& where) {
  for (const plot::Hole& h : part.holes)
    if ((h.centre - where).norm() < kTolerance) return true;
  return false;
}

// Points along the contour: every arc sampled, and the line to the next arc.
std::vector<Vec> Trace(const plot::Contour& c) {
  std::vector<Vec> points;
  for (size_t i = 0; i < c.arcs.size(); ++i) {
    const plot::Arc& a = c.arcs[i];
    for (int k = 0; k <= 8; ++k) {
      const double t = a.start + a.sweep * k / 8;
      points.push_back(a.centre + a.radius * Vec(std::cos(t), std::sin(t)));
    }
    const Vec to = c.arcs[(i + 1) % c.arcs.size()].From();
    for (int k = 1; k < 8; ++k) points.push_back(a.To() + (to - a.To()) * k / 8.0);
  }
  return points;
}

double Nearest(const std::vector<Vec>& points, const Vec& p) {
  double d = std::numeric_limits<double>::infinity();
  for (const Vec& q : points) d = std::min(d, (q - p).norm());
  return d;
}

}  // namespace

TEST_CASE("a rounded hull keeps its distance from the points it is drawn around", "[plot][parts]") {
  std::mt19937 random(20240528);  // fixed seed: the same point sets every run
  std::uniform_real_distribution<double> coordinate(-3, 3);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vec> points(1 + trial % 6);
    for (Vec& p : points) p = {coordinate(random), coordinate(random)};
    const double radius = 0.1 + 0.05 * (trial % 4);
    const plot::Contour c = plot::RoundedHull(points, radius);
    INFO("trial " << trial << ", " << points.size() << " points");
    // a closed convex outline turns once, counter-clockwise
    double turn = 0;
    for (const plot::Arc& a : c.arcs) {
      CHECK(a.sweep > 0);
      CHECK_THAT(a.radius, WithinAbs(radius, kCopiedRadius));
      CHECK(Nearest(points, a.centre) < 1e-12);  // each arc turns around one of the points
      turn += a.sweep;
    }
    CHECK_THAT(turn, WithinAbs(2 * kPi, kTurnRoundoff));
    // every point of the outline is at least `radius` from each point, and the arcs exactly
    for (const Vec& p : Trace(c)) CHECK(Nearest(points, p) > radius - kTolerance);
    // the lines between arcs are tangent to both: perpendicular to the radius at either end
    for (size_t i = 0; i < c.arcs.size(); ++i) {
      const plot::Arc& a = c.arcs[i];
      const Vec line = c.arcs[(i + 1) % c.arcs.size()].From() - a.To();
      if (line.norm() > kTolerance) CHECK_THAT((a.To() - a.centre).dot(line) / line.norm(), WithinAbs(0, kTolerance));
    }
  }
  // one point: a circle of two half arcs; no point: no outline
  CHECK(plot::RoundedHull({Vec(1, 2)}, 0.5).arcs.size() == 2);
  CHECK(plot::RoundedHull({}, 0.5).arcs.empty());
}

TEST_CASE("four-bar parts: holes at the joints, plates around the points", "[plot][parts]") {
  const Mechanism m = test::MzcCrankRocker();
  const double phi = DegToRad(30);
  const Solved s = Solve(m, phi);
  const plot::PartSizes sizes{0.3, 0.1};
  const std::vector<plot::Part> parts = plot::PartsAtPose(m, s.q, s.travel, sizes);
  REQUIRE(parts.size() == 4);
  CHECK(parts[0].frame);
  CHECK(parts[0].outline.arcs.empty());  // the frame has no plate
  // the closed form's joint positions
  const Vec a0(0, 0), b0(4, 0), a(std::cos(phi), std::sin(phi));
  const Vec b = test::MzcB(phi), k = test::MzcK(phi);
  const std::map<std::string, std::vector<Vec>> holes = {
      {"frame", {a0, b0}}, {"crank", {a0, a}}, {"coupler", {a, b}}, {"rocker", {b0, b}}};
  for (const auto& [link, at] : holes) {
    INFO(link);
    const plot::Part& part = PartOf(parts, link);
    REQUIRE(part.holes.size() == at.size());
    for (const Vec& p : at) CHECK(HasHoleAt(part, p));
    for (const plot::Hole& h : part.holes) CHECK(h.diameter == sizes.pin_diameter);
  }
  // the coupler's plate reaches round K, which is marked (no joint there)
  const plot::Part& coupler = PartOf(parts, "coupler");
  REQUIRE(coupler.marks.size() == 1);
  CHECK(coupler.marks[0].first == "K");
  CHECK((coupler.marks[0].second - k).norm() < kTolerance);
  const std::vector<Vec> coupler_points = {a, b, k};
  for (const Vec& p : Trace(coupler.outline)) CHECK(Nearest(coupler_points, p) > sizes.plate_width / 2 - kTolerance);
  CHECK(coupler.outline.arcs.size() == 3);
  // the crank's plate is a bar: two half circles of radius W/2 round A0 and A
  const plot::Part& crank = PartOf(parts, "crank");
  REQUIRE(crank.outline.arcs.size() == 2);
  for (const plot::Arc& arc : crank.outline.arcs) CHECK_THAT(arc.sweep, WithinAbs(kPi, kTurnRoundoff));
}

TEST_CASE("slider-crank parts: the frame's slot over the slider's travel", "[plot][parts]") {
  const double l1 = 1, l2 = 2.6, e = 0.8;
  const Mechanism m = test::SliderCrank(l1, l2, e);
  const Solved s = Solve(m, DegToRad(60));
  const plot::PartSizes sizes{0.3, 0.1};
  const std::vector<plot::Part> parts = plot::PartsAtPose(m, s.q, s.travel, sizes);
  const plot::Part& frame = PartOf(parts, "frame");
  REQUIRE(frame.slots.size() == 1);
  const plot::Slot& slot = frame.slots[0];
  CHECK(slot.joint == "S");
  // dead centres of seed 000: the travel's ends, refined (FindGuideTravels), cut where they are
  CHECK_THAT(slot.from.x(), WithinAbs(std::sqrt((l2 - l1) * (l2 - l1) - e * e), kRefined));
  CHECK_THAT(slot.to.x(), WithinAbs(std::sqrt((l2 + l1) * (l2 + l1) - e * e), kRefined));
  CHECK_THAT(slot.from.y(), WithinAbs(0, kTolerance));
  for (const plot::Arc& arc : slot.outline.arcs) CHECK_THAT(arc.radius, WithinAbs(sizes.pin_diameter / 2, kCopiedRadius));
  // the frame's pivot A0; the slider's pin B: the R and P joints at B share one hole
  CHECK(frame.holes.size() == 1);
  CHECK(HasHoleAt(frame, Vec(0, -e)));
  const plot::Part& slider = PartOf(parts, "slider");
  CHECK(slider.holes.size() == 1);
  CHECK(slider.outline.arcs.size() == 2);  // a round plate around its one point
}

TEST_CASE("part sizes: defaults and the pin inside the plate", "[plot][parts]") {
  // the shortest joint distance of a moving link is the crank's, 1: W = 1/4, D = W/2
  const plot::PartSizes d = plot::DefaultPartSizes(test::MzcCrankRocker());
  CHECK(d.plate_width == 0.25);
  CHECK(d.pin_diameter == 0.125);
  std::string why;
  CHECK(d.IsValid(&why));
  CHECK_FALSE(plot::PartSizes{0.2, 0.2}.IsValid(&why));
  CHECK_THAT(why, Catch::Contains("smaller than the plate width"));
  CHECK_FALSE(plot::PartSizes{0.2, 0}.IsValid(&why));
  CHECK_FALSE(plot::PartSizes{std::nan(""), 0.1}.IsValid(&why));
  const Mechanism m = test::SliderCrank(1, 2.6, 0.8);
  const Solved s = Solve(m, 0);
  CHECK_THROWS_AS(plot::PartsAtPose(m, s.q, s.travel, plot::PartSizes{0.1, 0.2}), std::invalid_argument);
}

}  // namespace koppel::parts_test
