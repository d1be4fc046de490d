// TraceCouplerCurve and FindStraightLine (tools/api/src/coupler_curve.cpp): the crank pin of seed
// 000's slider-crank against its closed form (a circle of radius l1 about A0), and seed 003's
// straight-line example (Meyer zur Capellen: phi_I = 180, phi_A = 98.3, phi_G = 163.3 deg).
#include "koppel/api/coupler_curve.hpp"
#include "koppel/core/angles.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace koppel;
using Catch::Matchers::WithinAbs;

namespace coupler_curve_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

constexpr double kL1 = 1, kE = 0.8;   // the entry's crank and offset
constexpr double kSampleInput = 1e-9;  // [deg] from + i step in radians, shown in degrees: rounding only
constexpr double kPosition = 1e-9;     // the solver's closure tolerance, with margin
constexpr double kArc = 1e-6;          // 3-point Gauss on cubic Hermite pieces of 5 deg of a circle: error ~ h^6
constexpr double kDocument = 0.05;     // [deg] seed 003 gives its angles to 0.1 deg
constexpr double kSum = 1e-9;          // [deg] phi_E = phi_A + phi_G: a sum of two shown angles, rounding only
constexpr double kRatio = 1e-12;       // q_G = band / length: one division, rounding only

PointRef Point(const Model& m, const std::string& text) {
  const Expected<PointRef> p = FindPointByText(m.mechanism(), text);
  REQUIRE(p);
  return *p;
}

}  // namespace

TEST_CASE("TraceCouplerCurve: the crank pin A runs on the circle of radius l1 about A0", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("slider-crank-offset"));
  CouplerCurveRequest request;
  request.point = Point(m, "crank.A");
  request.from = 0;
  request.to = 180;
  request.step = 5;
  REQUIRE(request.IsValid(m, nullptr));
  const CouplerCurveTable c = TraceCouplerCurve(m, request);
  REQUIRE(c.complete());
  CHECK(c.point == "crank.A");
  REQUIRE(c.inputs.size() == 37);
  for (size_t i = 0; i < c.inputs.size(); ++i) {
    CHECK_THAT(c.inputs[i], WithinAbs(5.0 * i, kSampleInput));
    const double phi = DegToRad(5.0 * i);
    // A = A0 + l1 (sin phi, -cos phi), A0 = (0, -e): dA/dphi per radian, counter-clockwise
    CHECK_THAT(c.points[i].x, WithinAbs(kL1 * std::sin(phi), kPosition));
    CHECK_THAT(c.points[i].y, WithinAbs(-kE - kL1 * std::cos(phi), kPosition));
    CHECK_THAT(c.d1[i].x, WithinAbs(kL1 * std::cos(phi), kPosition));
    CHECK_THAT(c.d1[i].y, WithinAbs(kL1 * std::sin(phi), kPosition));
    CHECK_THAT(c.arc_length[i], WithinAbs(kL1 * phi, kArc));
    CHECK_THAT(c.curvature[i], WithinAbs(1 / kL1, kPosition));
    CHECK_FALSE(c.singular[i]);
  }
}

TEST_CASE("TraceCouplerCurve: the file's sweep stands for what the request leaves unset; a zero step is refused", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("slider-crank-offset"));
  CouplerCurveRequest request;
  request.point = Point(m, "crank.A");
  request.step = 90;  // from and to: the file's 0 .. 360
  const CouplerCurveTable c = TraceCouplerCurve(m, request);
  REQUIRE(c.inputs.size() == 5);
  CHECK_THAT(c.inputs.back(), WithinAbs(360, kSampleInput));
  request.step = 0;
  std::string why;
  CHECK_FALSE(request.IsValid(m, &why));
  CHECK_FALSE(why.empty());
  CHECK_THROWS_AS(TraceCouplerCurve(m, request), InputError);
}

TEST_CASE("FindStraightLine: seed 003's reading example in its convention", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("mzc-crank-rocker"));
  StraightLineRequest request;
  request.point = Point(m, "K");
  request.at = 180;
  request.qg = 0.005;
  const StraightLine s = FindStraightLine(m, request);
  REQUIRE(s.ok());
  CHECK_THAT(s.reference, WithinAbs(180, kDocument));
  CHECK_THAT(s.phi_a, WithinAbs(98.3, kDocument));
  CHECK_THAT(s.phi_g, WithinAbs(163.3, kDocument));
  CHECK_THAT(s.phi_e, WithinAbs(s.phi_a + s.phi_g, kSum));
  CHECK(s.qg <= 0.005);
  CHECK_THAT(s.qg, WithinAbs(s.band / s.length, kRatio));
  // the same point from --at -180: the document's convention puts phi_I in [0, 360) all the same
  request.at = -180;
  const StraightLine turned = FindStraightLine(m, request);
  REQUIRE(turned.ok());
  CHECK_THAT(turned.reference, WithinAbs(180, kDocument));
  CHECK_THAT(turned.phi_a, WithinAbs(s.phi_a, kDocument));
}

TEST_CASE("FindStraightLine: the requests that are not one", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("mzc-crank-rocker"));
  StraightLineRequest request;
  request.point = Point(m, "K");
  std::string why;
  REQUIRE(request.IsValid(m, &why));
  request.resolution = 0;
  CHECK_FALSE(request.IsValid(m, &why));
  request.resolution = 0.02;
  request.qg = -1;
  CHECK_FALSE(request.IsValid(m, &why));
  CHECK_THROWS_AS(FindStraightLine(m, request), InputError);
  request.qg = 0.005;
  request.stretch_a = 100;
  request.stretch_e = 250;
  CHECK_FALSE(request.IsValid(m, &why));  // a stretch needs the reference point
  request.at = 180;
  CHECK(request.IsValid(m, &why));
  CHECK(StraightStretchIsValid(300, 420, &why));  // through 0
  CHECK_FALSE(StraightStretchIsValid(250, 100, &why));
  CHECK_FALSE(StraightStretchIsValid(0, 400, &why));  // more than one turn
  // a P drive has no turn to search over
  std::string text = "koppel: 1\nname: slide\nlinks:\n  frame: {frame: true, points: {O: [0, 0]}}\n"
                     "  block: {points: {B: [0, 0]}}\njoints:\n  S: {type: P, links: [frame, block], points: [O, B], axis: [1, 0]}\n"
                     "drive: {joint: S, name: s}\nassembly: {input: 0}\nsweep: {from: 0, to: 1, step: 0.1}\n";
  const Model slide = Model::Parse(text, "slide");
  StraightLineRequest on_slide;
  on_slide.point = Point(slide, "block.B");
  CHECK_FALSE(on_slide.IsValid(slide, &why));
}

}  // namespace coupler_curve_test
