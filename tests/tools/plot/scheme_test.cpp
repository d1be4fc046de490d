// The kinematic scheme read back with an XML parser: the symbols a mechanism needs (pivots,
// joints, blocks, guides, bars, polygons, labels, drive arrow), each at the place the
// mechanism's geometry puts it. References: seed 000's crank position A = A0 + l1 (sin φ, -cos φ)
// and the independent circle-intersection four-bar of tests/support/closed_forms.
#include "koppel/plot/scheme.hpp"

#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"
#include "tools/plot/svg_reading.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/plot/sampled_run.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>

namespace koppel {
namespace {

// px coordinates are written with 2 decimals, transform entries with 3 to 6.
constexpr double kPxTolerance = 0.02;

struct Drawn {
  pugi::xml_document doc;
  double scale, ox, oy;
  Eigen::Vector2d ToPx(const Eigen::Vector2d& w) const { return {ox + scale * w.x(), oy - scale * w.y()}; }
};

plot::SampledRun FullTurn(const Mechanism& m) {
  SweepOptions o;
  o.from = 0;
  o.to = DegToRad(360);
  o.step = DegToRad(5);
  o.order = 0;
  return plot::SampleMechanism(m, o);
}

Drawn Draw(const Mechanism& m, double phi, plot::SchemeScene scene = {}) {
  const plot::SampledRun run = FullTurn(m);
  REQUIRE(run.complete);
  const Expected<Eigen::VectorXd> pose = plot::PoseAt(m, run, phi);
  REQUIRE(pose);
  scene.q = *pose;
  for (int i = 0; i < run.size(); ++i) scene.extent.push_back(run.poses.row(i).transpose());
  scene.animatable = true;
  Drawn d{test::ParseSvg(plot::DrawScheme(m, scene)), 0, 0, 0};
  const auto root = d.doc.document_element();
  d.scale = root.attribute("data-scale").as_double();
  d.ox = root.attribute("data-ox").as_double();
  d.oy = root.attribute("data-oy").as_double();
  REQUIRE(d.scale > 0);
  return d;
}

// Where the scheme put each joint circle, in px: the circle's centre through its group's transform.
std::map<std::string, Eigen::Vector2d> JointCircles(const Drawn& d) {
  std::map<std::string, Eigen::Vector2d> at;
  for (const auto& group : test::Find(d.doc, "g", "joints"))
    for (const auto& c : test::Find(group, "circle", "joint"))
      at[c.attribute("data-joint").as_string()] =
          test::Apply(test::ParseMatrix(group.attribute("transform").as_string()),
                      {c.attribute("cx").as_double(), c.attribute("cy").as_double()});
  return at;
}

}  // namespace

TEST_CASE("scheme of seed 000's slider-crank at 120 deg: symbols in place", "[plot]") {
  const double l1 = 1, l2 = 2.6, e = 0.8, phi = DegToRad(120);
  const Mechanism m = test::SliderCrank(l1, l2, e);
  const Drawn d = Draw(m, phi);
  // one pivot (A0), three revolute joints, one block on a hatched guide, the drive arrow
  CHECK(test::Find(d.doc, "polygon", "pivot").size() == 1);
  CHECK(test::Find(d.doc, "line", "guide").size() == 1);
  CHECK(test::Find(d.doc, "path", "hatch").size() == 2);
  CHECK(test::Find(d.doc, "polygon", "block").size() == 1);
  CHECK(test::Find(d.doc, "path", "drive-arrow").size() == 1);
  CHECK(test::Find(d.doc, "line", "bar").size() == 2);  // crank and coupler
  const auto joints = JointCircles(d);
  REQUIRE(joints.size() == 3);
  // seed 000: A0 = (0, -e), A = A0 + l1 (sin φ, -cos φ), B on the slide line at s
  const Eigen::Vector2d a0(0, -e), a = a0 + l1 * Eigen::Vector2d(std::sin(phi), -std::cos(phi));
  const double s = test::SliderCrank(l1, l2, e, phi).s;
  CHECK((joints.at("A0") - d.ToPx(a0)).norm() < kPxTolerance);
  CHECK((joints.at("A") - d.ToPx(a)).norm() < kPxTolerance);
  CHECK((joints.at("B") - d.ToPx({s, 0})).norm() < kPxTolerance);
  // the guide covers the slider's stroke s_i..s_a (seed 000's dead-centre positions)
  const auto guide = test::Find(d.doc, "line", "guide")[0];
  const double x1 = guide.attribute("x1").as_double(), x2 = guide.attribute("x2").as_double();
  const double s_a = std::sqrt((l1 + l2) * (l1 + l2) - e * e), s_i = std::sqrt((l2 - l1) * (l2 - l1) - e * e);
  CHECK(std::min(x1, x2) < d.ToPx({s_i, 0}).x());
  CHECK(std::max(x1, x2) > d.ToPx({s_a, 0}).x());
  // labels: one per point name, at the point (offset 7 px up right)
  std::map<std::string, Eigen::Vector2d> labels;
  for (const auto& t : test::Find(d.doc, "text", "label"))
    labels[t.attribute("data-point").as_string()] = {t.attribute("x").as_double(), t.attribute("y").as_double()};
  CHECK(labels.size() == 4);  // A0, F, A, B
  CHECK((labels.at("A") - d.ToPx(a) - Eigen::Vector2d(7, -7)).norm() < kPxTolerance);
  CHECK((labels.at("F") - d.ToPx({0, 0}) - Eigen::Vector2d(7, -7)).norm() < kPxTolerance);
}

TEST_CASE("scheme of the six-link proportional linkage: two pivots, three blocks, two slots", "[plot]") {
  const Mechanism m = test::ProportionalLinkage(1, 0.5, 1.83);
  const Drawn d = Draw(m, DegToRad(150));
  CHECK(test::Find(d.doc, "polygon", "pivot").size() == 2);   // A0, B0
  CHECK(test::Find(d.doc, "polygon", "block").size() == 3);   // block 2, block 4, slider 5
  CHECK(test::Find(d.doc, "line", "slot").size() == 2);       // the slot of link 3 guides blocks 2 and 4
  CHECK(test::Find(d.doc, "line", "guide").size() == 1);      // slider 5 on the frame
  CHECK(JointCircles(d).size() == 4);                         // A0, A, B0, D
  // A at the crank angle: A = l1 (cos φ, sin φ) (seed 001: φ against A0B0)
  const Eigen::Vector2d a = 0.5 * Eigen::Vector2d(std::cos(DegToRad(150)), std::sin(DegToRad(150)));
  CHECK((JointCircles(d).at("A") - d.ToPx(a)).norm() < kPxTolerance);
}

TEST_CASE("scheme of seed 003's crank-rocker: the coupler is a polygon, K where the independent four-bar puts it", "[plot]") {
  const double l1 = 1, l2 = 2.5 * std::sqrt(3.0), l4 = 4, k = 25.0 / 3, kappa = std::acos(5.0 / 9 * std::sqrt(3.0));
  const Mechanism m = test::FourBar(l1, l2, l2, l4, k, kappa, +1);
  plot::SchemeScene scene;
  scene.trace = {{{0, 7}, {1, 8}}};
  const Drawn d = Draw(m, DegToRad(100), scene);
  const auto polygons = test::Find(d.doc, "polygon", "polygon");
  REQUIRE(polygons.size() == 1);
  CHECK(test::Find(d.doc, "path", "trace").size() == 1);
  const Eigen::Vector2d K = test::FourBarCouplerPoint(l1, l2, l2, l4, k, kappa, DegToRad(100), +1);
  for (const auto& t : test::Find(d.doc, "text", "label"))
    if (std::string(t.attribute("data-point").as_string()) == "K")
      CHECK((Eigen::Vector2d(t.attribute("x").as_double(), t.attribute("y").as_double()) - d.ToPx(K) - Eigen::Vector2d(7, -7)).norm() <
            kPxTolerance);
}

TEST_CASE("dead-centre overlays: labels with suffixes, frame pivots not repeated", "[plot]") {
  const Mechanism m = test::SliderCrank(1, 2.6, 0.8);
  const plot::SampledRun run = FullTurn(m);
  plot::SchemeScene scene;
  const double phi_a = test::SliderCrankPhiA(1, 2.6, 0.8), phi_i = test::SliderCrankPhiI(1, 2.6, 0.8);
  scene.overlays.resize(2);
  scene.overlays[0].suffix = "a";
  scene.overlays[1].suffix = "i";
  const Expected<Eigen::VectorXd> extended = plot::PoseAt(m, run, phi_a), folded = plot::PoseAt(m, run, phi_i);
  REQUIRE(extended);
  REQUIRE(folded);
  scene.overlays[0].q = *extended;
  scene.overlays[1].q = *folded;
  const Drawn d = Draw(m, DegToRad(120), scene);
  std::vector<std::string> names;
  std::map<std::string, Eigen::Vector2d> at;
  for (const auto& g : test::Find(d.doc, "g", "overlay-labels"))
    for (const auto& t : g.children("text")) {
      names.push_back(t.child_value());
      at[t.child_value()] = {t.attribute("x").as_double(), t.attribute("y").as_double()};
    }
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<std::string>{"A_a", "A_i", "B_a", "B_i"});
  // extended: A_a on the line A0 B_a beyond... between A0 and B_a; folded: A0 between A_i and B_i
  const Eigen::Vector2d a0 = d.ToPx({0, -0.8}) + Eigen::Vector2d(7, -7);
  auto cross = [](Eigen::Vector2d u, Eigen::Vector2d v) { return u.x() * v.y() - u.y() * v.x(); };
  CHECK(std::abs(cross(at["A_a"] - a0, at["B_a"] - a0)) / ((at["A_a"] - a0).norm() * (at["B_a"] - a0).norm()) < 1e-3);
  CHECK((at["A_a"] - a0).dot(at["B_a"] - a0) > 0);
  CHECK((at["A_i"] - a0).dot(at["B_i"] - a0) < 0);
}

}  // namespace koppel
