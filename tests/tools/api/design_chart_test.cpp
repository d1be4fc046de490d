// Design charts (tools/api/src/design_chart.cpp): the grid of a range, the default charts, and
// rows designed on several threads that equal the designs made one at a time by the API's
// syntheses (synthesis.hpp: an independent path through the same closed forms).
#include "koppel/api/design_chart.hpp"
#include "koppel/api/synthesis.hpp"
#include "koppel/core/diagnostic.hpp"

#include <catch2/catch.hpp>

#include <chrono>

using namespace koppel;
using Catch::Matchers::WithinAbs;

namespace design_chart_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

// a chart cell against the same design made alone: the same computation, on another thread, and
// both passed through degrees
constexpr double kSameDesign = 1e-12;

double Number(const ChartCell& c) {
  REQUIRE(c.number);
  return *c.number;
}

}  // namespace

TEST_CASE("ChartRange: from, from + step, ... up to `to` despite the rounding of the steps", "[api]") {
  // 0.3 * 3 = 0.8999999999999999 < 0.9: the last value is still in
  const std::vector<double> v = ChartRange{0, 0.9, 0.3}.Values("phi0");
  REQUIRE(v.size() == 4);
  CHECK_THAT(v.back(), WithinAbs(0.9, 1e-15));
  CHECK(ChartRange{160, 170, 2}.Values("phi0").size() == 6);
  CHECK(ChartRange{164, 164, 1}.Values("phi0") == std::vector<double>{164});
  CHECK(ChartRange{160, 171, 2}.Count("phi0") == 6);  // 170 is the last below 171
  CHECK_THROWS_AS(ChartRange({170, 160, 1}).Count("phi0"), InputError);
  CHECK_THROWS_AS(ChartRange({160, 170, 0}).Count("phi0"), InputError);
  // a billion values are refused before they are made
  CHECK_THROWS_AS(ChartRange({0, 1e9, 1}).Values("phi0"), InputError);
}

TEST_CASE("DefaultChart: the default crank-rocker chart has the 1 271 cells of limits.hpp", "[api]") {
  const ChartSpec spec = DefaultChart("crank-rocker");
  CHECK(spec.phi0.Count("phi0") * spec.psi0.Count("psi0") == 1271);
  CHECK(DefaultChart("slider-crank").phi0.Count("phi0") == 46);  // 90..180 by 2
  CHECK_THROWS_AS(DefaultChart("cam"), InputError);
}

TEST_CASE("SynthesiseChart: a slider-crank row is the design SynthesiseSliderCrank makes; phi0 = 180 is a boundary", "[api]") {
  ChartSpec spec = DefaultChart("slider-crank");
  spec.phi0 = {170, 180, 10};
  spec.threads = 2;
  const DesignChart chart = SynthesiseChart(spec);
  REQUIRE(chart.rows.size() == 2);
  CHECK(chart.designs == 2);
  CHECK(chart.columns == std::vector<std::string>{"phi0", "status", "e_s0", "l1_s0", "l2_s0", "mu_min", "beta"});
  const std::vector<ChartCell>& ok = chart.rows[0];
  CHECK(ok[1].word == "ok");
  SliderCrankSpec alone;
  alone.phi0 = 170;
  alone.stroke = 1;
  const Design d = SynthesiseSliderCrank(alone);
  REQUIRE(d.ok());
  CHECK_THAT(Number(ok[0]), WithinAbs(170, kSameDesign));
  CHECK_THAT(Number(ok[2]), WithinAbs(d.Get("e"), kSameDesign));
  CHECK_THAT(Number(ok[3]), WithinAbs(d.Get("l1"), kSameDesign));
  CHECK_THAT(Number(ok[5]), WithinAbs(d.Get("mu_min"), kSameDesign));
  // the centric slider-crank has no best offset: the row says so and has no numbers
  const std::vector<ChartCell>& boundary = chart.rows[1];
  CHECK(boundary[1].word == "boundary");
  for (size_t i = 2; i < boundary.size(); ++i) CHECK_FALSE(boundary[i].number);
}

TEST_CASE("SynthesiseChart: both rocker senses, each row the best crank-rocker of its request", "[api]") {
  ChartSpec spec = DefaultChart("crank-rocker");
  spec.phi0 = {164, 164, 1};
  spec.psi0 = {60, 60, 1};
  spec.rocker_sense = "both";
  const DesignChart chart = SynthesiseChart(spec);
  REQUIRE(chart.rows.size() == 2);
  for (const auto& [row, same] : {std::pair{0, true}, {1, false}}) {
    const std::vector<ChartCell>& r = chart.rows[static_cast<size_t>(row)];
    CHECK(r[2].word == (same ? "same" : "opposite"));
    REQUIRE(r[3].word == "ok");
    CrankRockerSpec alone;
    alone.phi0 = 164;
    alone.psi0 = 60;
    alone.same_sense = same;
    const Design d = SynthesiseCrankRocker(alone);
    REQUIRE(d.ok());
    CHECK_THAT(Number(r[4]), WithinAbs(d.Get("beta"), kSameDesign));
    CHECK_THAT(Number(r[5]), WithinAbs(d.Get("mu_min"), kSameDesign));
    CHECK_THAT(Number(r[6]), WithinAbs(d.Get("l1"), kSameDesign));
  }
  // where no crank-rocker exists the row stays, with status none
  spec.phi0 = {120, 120, 1};
  spec.rocker_sense = "same";
  const DesignChart gap = SynthesiseChart(spec);
  REQUIRE(gap.rows.size() == 1);
  CHECK(gap.rows[0][3].word == "none");
  CHECK_FALSE(gap.rows[0][4].number);
}

TEST_CASE("SynthesiseChart: malformed charts throw before any design", "[api]") {
  ChartSpec spec = DefaultChart("crank-rocker");
  spec.rocker_sense = "sideways";
  CHECK_THROWS_AS(SynthesiseChart(spec), InputError);
  // 160 001 x 90 001 cells: far over kMaxChartCells, refused at once
  spec = DefaultChart("crank-rocker");
  spec.phi0 = {100, 260, 1e-3};
  spec.psi0 = {10, 100, 1e-3};
  const auto start = std::chrono::steady_clock::now();
  CHECK_THROWS_AS(SynthesiseChart(spec), InputError);
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 5);
  spec = DefaultChart("crank-rocker");
  spec.threads = -1;
  CHECK_THROWS_AS(SynthesiseChart(spec), InputError);
}

}  // namespace design_chart_test
