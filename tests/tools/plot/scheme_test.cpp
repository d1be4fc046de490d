// The kinematic scheme read back with an XML parser: the symbols a mechanism needs (pivots,
// joints, blocks, guides, bars, polygons, labels, drive arrow), each at the place the
// mechanism's geometry puts it. References: seed 000's crank position A = A0 + l1 (sin φ, -cos φ)
// and the independent circle-intersection four-bar of tests/support/closed_forms.
#include "koppel/plot/scheme.hpp"

#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"
#include "tools/plot/scheme_reading.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/plot/sampled_run.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace koppel::scheme_test {
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

// animatable: as the page of `koppel view` draws it (labels keep their nearest ring); else as
// `koppel draw` does.
Drawn Draw(const Mechanism& m, double phi, plot::SchemeScene scene = {}, bool animatable = true) {
  const plot::SampledRun run = FullTurn(m);
  REQUIRE(run.complete);
  const Expected<Eigen::VectorXd> pose = plot::PoseAt(m, run, phi);
  REQUIRE(pose);
  scene.q = *pose;
  for (int i = 0; i < run.size(); ++i) scene.extent.push_back(run.poses.row(i).transpose());
  scene.animatable = animatable;
  Drawn d{test::ParseSvg(plot::DrawScheme(m, scene)), 0, 0, 0};
  const auto root = d.doc.document_element();
  d.scale = root.attribute("data-scale").as_double();
  d.ox = root.attribute("data-ox").as_double();
  d.oy = root.attribute("data-oy").as_double();
  REQUIRE(d.scale > 0);
  return d;
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
  const auto joints = test::JointCircles(d.doc);
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
  // labels: one per point name, naming the point where it is
  std::map<std::string, Eigen::Vector2d> labels;
  for (const test::ReadLabel& l : test::ReadLabels(d.doc)) labels[l.name] = l.anchor;
  CHECK(labels.size() == 4);  // A0, F, A, B
  CHECK((labels.at("A") - d.ToPx(a)).norm() < kPxTolerance);
  CHECK((labels.at("F") - d.ToPx({0, 0})).norm() < kPxTolerance);
  test::CheckLabelsLegible(d.doc);
  // the foot point F (0, 0) lies on the slide line y = 0, which is drawn through it
  const auto axes = test::Find(d.doc, "line", "guide-axis");
  REQUIRE(axes.size() == 1);
  const Eigen::Vector2d from(axes[0].attribute("x1").as_double(), axes[0].attribute("y1").as_double()),
      to(axes[0].attribute("x2").as_double(), axes[0].attribute("y2").as_double()), f = d.ToPx({0, 0});
  const double t = (f - from).dot(to - from) / (to - from).squaredNorm();
  CHECK(t >= 0);
  CHECK(t <= 1);
  CHECK((from + t * (to - from) - f).norm() < kPxTolerance);
}

TEST_CASE("scheme of the six-link proportional linkage: two pivots, three blocks, two slots", "[plot]") {
  const Mechanism m = test::ProportionalLinkage(1, 0.5, 1.83);
  const Drawn d = Draw(m, DegToRad(150));
  CHECK(test::Find(d.doc, "polygon", "pivot").size() == 2);   // A0, B0
  CHECK(test::Find(d.doc, "polygon", "block").size() == 3);   // block 2, block 4, slider 5
  CHECK(test::Find(d.doc, "line", "slot").size() == 2);       // the slot of link 3 guides blocks 2 and 4
  CHECK(test::Find(d.doc, "line", "guide").size() == 1);      // slider 5 on the frame
  CHECK(test::JointCircles(d.doc).size() == 4);                         // A0, A, B0, D
  // A at the crank angle: A = l1 (cos φ, sin φ) (seed 001: φ against A0B0)
  const Eigen::Vector2d a = 0.5 * Eigen::Vector2d(std::cos(DegToRad(150)), std::sin(DegToRad(150)));
  CHECK((test::JointCircles(d.doc).at("A") - d.ToPx(a)).norm() < kPxTolerance);
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
  for (const test::ReadLabel& l : test::ReadLabels(d.doc))
    if (l.name == "K") CHECK((l.anchor - d.ToPx(K)).norm() < kPxTolerance);
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
  const Drawn d = Draw(m, DegToRad(120), scene, false);
  std::vector<std::string> names;
  std::map<std::string, Eigen::Vector2d> at;
  for (const test::ReadLabel& l : test::ReadLabels(d.doc))
    if (l.overlay) {
      names.push_back(l.text);
      at[l.text] = l.anchor;
    }
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<std::string>{"A_a", "A_i", "B_a", "B_i"});
  // seed 000: B_a at s_a = sqrt((l1 + l2)^2 - e^2) on the slide line, B_i at s_i = sqrt((l2 - l1)^2 - e^2)
  CHECK((at["B_a"] - d.ToPx({std::sqrt(3.6 * 3.6 - 0.64), 0})).norm() < kPxTolerance);
  CHECK((at["B_i"] - d.ToPx({std::sqrt(1.6 * 1.6 - 0.64), 0})).norm() < kPxTolerance);
  // extended: A_a on the line A0 B_a between A0 and B_a; folded: A0 between A_i and B_i
  const Eigen::Vector2d a0 = d.ToPx({0, -0.8});
  auto cross = [](Eigen::Vector2d u, Eigen::Vector2d v) { return u.x() * v.y() - u.y() * v.x(); };
  CHECK(std::abs(cross(at["A_a"] - a0, at["B_a"] - a0)) / ((at["A_a"] - a0).norm() * (at["B_a"] - a0).norm()) < 1e-3);
  CHECK((at["A_a"] - a0).dot(at["B_a"] - a0) > 0);
  CHECK((at["A_i"] - a0).dot(at["B_i"] - a0) < 0);
}

// Issue 22 item 15: `draw --deadcentres` printed "B" and "B_a" on top of each other ("BB_a")
// and F without the line it lies on. The scene of that command (seed 000 at 120 deg with both
// dead centres), and seed 003's crank-rocker, whose dead centre of B0K at 180 deg coincides with
// the pose drawn (every overlay label on a main one).
TEST_CASE("dead-centre overlays: no label covers another, each has its symbol or a leader", "[plot]") {
  const Mechanism slider_crank = test::SliderCrank(1, 2.6, 0.8);
  const plot::SampledRun run = FullTurn(slider_crank);
  plot::SchemeScene scene;
  for (const auto& [suffix, phi] : {std::pair<std::string, double>{"a", test::SliderCrankPhiA(1, 2.6, 0.8)}, {"i", test::SliderCrankPhiI(1, 2.6, 0.8)}}) {
    const Expected<Eigen::VectorXd> q = plot::PoseAt(slider_crank, run, phi);
    REQUIRE(q);
    scene.overlays.push_back({*q, suffix});
  }
  test::CheckLabelsLegible(Draw(slider_crank, DegToRad(120), scene, false).doc);

  const double l2 = 2.5 * std::sqrt(3.0);
  const Mechanism crank_rocker = test::FourBar(1, l2, l2, 4, 25.0 / 3, std::acos(5.0 / 9 * std::sqrt(3.0)), +1);
  const plot::SampledRun turn = FullTurn(crank_rocker);
  plot::SchemeScene same;
  for (const auto& [suffix, phi] : {std::pair<std::string, double>{"1", kPi}, {"2", 0.0}}) {
    const Expected<Eigen::VectorXd> q = plot::PoseAt(crank_rocker, turn, phi);
    REQUIRE(q);
    same.overlays.push_back({*q, suffix});
  }
  test::CheckLabelsLegible(Draw(crank_rocker, kPi, same, false).doc);
}

}  // namespace koppel::scheme_test
