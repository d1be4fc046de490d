// Model::Curvature, Poles and Centrodes (tools/api/src/instant_geometry.cpp) on the catalog's
// crank-rocker (a : b : c : d = 1 : 3.5 : 3 : 4, A0 at the origin, B0 = (d, 0), B above the frame
// line), against independent geometry: the pose from two circles (A on the crank circle, B where
// the coupler and rocker circles meet), the coupler's pole where the crank and rocker lines meet,
// the crank-rocker pole on the coupler line and the frame line (Aronhold-Kennedy), a joint point
// of the rocker turning about B0 (radius c), and the moving centrode as that pole seen from the
// coupler (origin A, x along A->B).
#include "koppel/api/model.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/diagnostic.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace koppel::instant_geometry_test {
namespace {

using Catch::Matchers::WithinAbs;

// The catalog's closed-form checks ask 1e-9 of the solver's pose; the API adds only a unit
// conversion, and the poles, centres and centrodes are held to the same (they pass at it: the
// lines that meet at them cross at no less than ~20 deg here).
constexpr double kClosedForm = 1e-9;

constexpr double a = 1, b = 3.5, c = 3, d = 4;

struct Vec {
  double x, y;
};
Vec operator-(Vec p, Vec q) { return {p.x - q.x, p.y - q.y}; }
Vec operator+(Vec p, Vec q) { return {p.x + q.x, p.y + q.y}; }
Vec operator*(double s, Vec p) { return {s * p.x, s * p.y}; }
double Cross(Vec p, Vec q) { return p.x * q.y - p.y * q.x; }
double Norm(Vec p) { return std::hypot(p.x, p.y); }

// The crossing of line p + s u with line q + t v.
Vec Meet(Vec p, Vec u, Vec q, Vec v) { return p + (Cross(q - p, v) / Cross(u, v)) * u; }

struct Pose {
  Vec a0{0, 0}, b0{d, 0}, A, B;
};
// A on the crank circle; B on the coupler circle round A and the rocker circle round B0, the
// intersection above the line A B0 (the catalog's branch for this range of phi).
Pose PoseAt(double phi_deg) {
  Pose p;
  const double phi = DegToRad(phi_deg);
  p.A = {a * std::cos(phi), a * std::sin(phi)};
  const Vec ab0 = p.b0 - p.A;
  const double l = Norm(ab0), along = (l * l + b * b - c * c) / (2 * l), across = std::sqrt(b * b - along * along);
  const Vec u = (1 / l) * ab0, n{-u.y, u.x};
  p.B = p.A + along * u + across * n;
  return p;
}
Vec CouplerPole(const Pose& p) { return Meet(p.a0, p.A - p.a0, p.b0, p.B - p.b0); }

Model CrankRocker() { return Model::Load(test::CatalogEntryPath("crank-rocker")); }

void CheckAt(const std::optional<Point2>& got, Vec want, double tol) {
  REQUIRE(got.has_value());
  CHECK_THAT(got->x, WithinAbs(want.x, tol));
  CHECK_THAT(got->y, WithinAbs(want.y, tol));
}

const InstantCentreEntry& Entry(const PolesReport& r, const std::string& x, const std::string& y) {
  for (const InstantCentreEntry& e : r.centres)
    if ((e.link_a == x && e.link_b == y) || (e.link_a == y && e.link_b == x)) return e;
  FAIL("no instant centre of " << x << " and " << y);
  return r.centres.front();
}

}  // namespace

TEST_CASE("Model::Poles: the six instant centres of the crank-rocker by Aronhold-Kennedy", "[api]") {
  const Model m = CrankRocker();
  for (const double phi : {30.0, 60.0, 120.0}) {
    INFO("phi " << phi);
    const Pose p = PoseAt(phi);
    const PolesReport r = m.Poles(phi);
    REQUIRE(Usable(r.status));
    CHECK(r.input == phi);
    REQUIRE(r.centres.size() == 6);  // every pair of 4 links
    const auto check = [&](const std::string& x, const std::string& y, Vec want, double tol) {
      INFO(x << "-" << y);
      const InstantCentreEntry& e = Entry(r, x, y);
      CHECK(e.defined);
      CHECK_FALSE(e.at_infinity);
      CheckAt(e.position, want, tol);
    };
    // the pins are the poles of the links they join
    check("frame", "crank", p.a0, kClosedForm);
    check("frame", "rocker", p.b0, kClosedForm);
    check("crank", "coupler", p.A, kClosedForm);
    check("coupler", "rocker", p.B, kClosedForm);
    // the coupler's pole: crank line x rocker line; crank-rocker: coupler line x frame line
    check("frame", "coupler", CouplerPole(p), kClosedForm);
    check("crank", "rocker", Meet(p.A, p.B - p.A, p.a0, p.b0 - p.a0), kClosedForm);
  }
}

TEST_CASE("Model::Curvature: a joint point on the rocker turns about B0; the coupler's pole", "[api]") {
  const Model m = CrankRocker();
  const double phi = 60;
  const Pose p = PoseAt(phi);
  const CurvatureReport r = m.Curvature("coupler.B", phi);
  REQUIRE(Usable(r.status));
  CHECK(r.input == phi);
  CHECK(r.input_name == "phi");
  CHECK(r.input_unit == "deg");
  CHECK(r.point == "coupler.B");
  CHECK(r.link == "coupler");
  CHECK_THAT(r.position.x, WithinAbs(p.B.x, kClosedForm));
  CHECK_THAT(r.position.y, WithinAbs(p.B.y, kClosedForm));
  // B also lies on the rocker: its path is the circle of radius c about B0
  CheckAt(r.centre, p.b0, kClosedForm);
  REQUIRE(r.rho.has_value());
  REQUIRE(r.curvature.has_value());
  CHECK_THAT(std::abs(*r.rho), WithinAbs(c, kClosedForm));
  CHECK_THAT(*r.curvature * *r.rho, WithinAbs(1.0, kClosedForm));
  // the carrying link's pole, and the inflection circle through it: W diametrically opposite,
  // the circle's centre halfway, its diameter |W - P| (the definitions in instant_geometry.hpp)
  const Vec pole = CouplerPole(p);
  CheckAt(r.pole, pole, kClosedForm);
  REQUIRE(r.inflection_pole.has_value());
  REQUIRE(r.inflection_centre.has_value());
  REQUIRE(r.inflection_diameter.has_value());
  const Vec w{r.inflection_pole->x, r.inflection_pole->y}, centre{r.inflection_centre->x, r.inflection_centre->y};
  CHECK_THAT(Norm(w - pole), WithinAbs(*r.inflection_diameter, kClosedForm));
  CHECK_THAT(Norm(centre - 0.5 * (w + pole)), WithinAbs(0.0, kClosedForm));
  // the quantities as koppel curvature prints them: the same numbers under their names
  bool seen_pole = false, seen_rho = false;
  for (const NamedValue& q : r.Quantities()) {
    if (q.name == "pole_x") seen_pole = q.value == r.pole->x && q.unit == "length";
    if (q.name == "rho") seen_rho = q.value == r.rho && q.unit == "length";
  }
  CHECK(seen_pole);
  CHECK(seen_rho);
  // the crank's pin turns about A0 on the crank: radius a
  const CurvatureReport crank = m.Curvature("crank.A", phi);
  REQUIRE(Usable(crank.status));
  CheckAt(crank.centre, p.a0, kClosedForm);
  CheckAt(crank.pole, p.a0, kClosedForm);  // the crank turns about A0
}

TEST_CASE("Model::Curvature and Poles: bad input named", "[api]") {
  const Model m = CrankRocker();
  CHECK_THROWS_AS(m.Curvature("coupler.B", std::nan("")), InputError);
  CHECK_THROWS_AS(m.Curvature("coupler.B", INFINITY), InputError);
  CHECK_THROWS_AS(m.Curvature("coupler.Z", 60), InputError);
  CHECK_THROWS_AS(m.Poles(std::nan("")), InputError);
}

TEST_CASE("Model::Centrodes: the coupler's pole in the frame and in the coupler", "[api]") {
  const Model m = CrankRocker();
  const double at = 60;
  const CentrodesReport r = m.Centrodes("coupler", "", 0, 180, 30, at);
  REQUIRE(Usable(r.status));
  CHECK(r.link == "coupler");
  CHECK(r.reference == "frame");  // "" is the frame
  REQUIRE(r.inputs.size() == 7);  // 0, 30, ..., 180 deg
  REQUIRE(r.fixed.size() == 7);
  REQUIRE(r.moving.size() == 7);
  REQUIRE(r.moving_at.size() == 7);
  const Pose at_pose = PoseAt(at);
  const Vec ex_at = (1 / b) * (at_pose.B - at_pose.A), ey_at{-ex_at.y, ex_at.x};
  for (size_t i = 0; i < r.inputs.size(); ++i) {
    INFO("row " << i);
    CHECK_THAT(r.inputs[i], WithinAbs(30.0 * i, kClosedForm));
    const Pose p = PoseAt(30.0 * i);
    const Vec pole = CouplerPole(p);
    CheckAt(r.fixed[i], pole, kClosedForm);
    // the coupler's own frame: origin A, x along A->B (the file's points A: [0, 0], B: [b, 0])
    const Vec ex = (1 / b) * (p.B - p.A), ey{-ex.y, ex.x}, rel = pole - p.A;
    const Vec own{rel.x * ex.x + rel.y * ex.y, rel.x * ey.x + rel.y * ey.y};
    CheckAt(r.moving[i], own, kClosedForm);
    // carried to the pose at `at`
    CheckAt(r.moving_at[i], at_pose.A + own.x * ex_at + own.y * ey_at, kClosedForm);
  }
  // at `at` the two centrodes touch at the pole
  CheckAt(r.moving_at[2], CouplerPole(at_pose), kClosedForm);
  CHECK_THAT(r.moving_at[2]->x, WithinAbs(r.fixed[2]->x, kClosedForm));
  CHECK_THAT(r.moving_at[2]->y, WithinAbs(r.fixed[2]->y, kClosedForm));
}

TEST_CASE("Model::Centrodes: bad links and ranges are input errors", "[api]") {
  const Model m = CrankRocker();
  CHECK_THROWS_AS(m.Centrodes("nothing", "", 0, 90, 10, 0), InputError);
  CHECK_THROWS_AS(m.Centrodes("coupler", "nothing", 0, 90, 10, 0), InputError);
  CHECK_THROWS_AS(m.Centrodes("coupler", "coupler", 0, 90, 10, 0), InputError);
  CHECK_THROWS_AS(m.Centrodes("coupler", "", 0, 90, 0, 0), InputError);
  CHECK_THROWS_AS(m.Centrodes("coupler", "", 0, INFINITY, 10, 0), InputError);
  CHECK_THROWS_AS(m.Centrodes("coupler", "", 0, 90, 10, std::nan("")), InputError);
  CHECK_THROWS_AS(m.Centrodes("coupler", "", 0, 1e12, 1e-3, 0), InputError);  // more than kMaxSweepSamples
}

}  // namespace koppel::instant_geometry_test
