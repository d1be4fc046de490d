// What the plot builders share (tools/plot/src/plot_support.cpp, private to the pictures): the
// units and labels shown, runs of samples as subpaths, the range check and the convex hull
// (checked against its definition: every point inside, every vertex a strict left turn).
#include "plot_support.hpp"

#include "koppel/core/angles.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <random>

namespace koppel::plot_support_test {
namespace {

// Degrees of a few radians, and cross products of coordinates below 10: a few ulps.
constexpr double kRoundoff = 1e-12;

// Outputs K (point), psi (rocker angle), phi (joint angle), mu (transmission angle); driven at A0.
Mechanism FourBar() { return test::FourBar(1, 3, 2.5, 3.2, 1.5, 0.4, 1); }

double Cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

TEST_CASE("labels say the unit of each order", "[plot_support]") {
  const Mechanism m = FourBar();
  CHECK(plot::InputLabel(m, "length") == "φ [deg]");
  CHECK(plot::DerivativeLabel(m, 0, "_x", 0, "length") == "K_x [length]");
  CHECK(plot::DerivativeLabel(m, 0, "_y", 2, "length") == "K_y'' [length/rad²]");
  CHECK(plot::DerivativeLabel(m, 0, "_y", 2, "mm") == "K_y'' [mm/rad²]");  // the file's unit where it names one
  CHECK(plot::DerivativeLabel(m, 1, "", 0, "length") == "ψ [deg]");
  CHECK(plot::DerivativeLabel(m, 1, "", 1, "length") == "ψ' [rad/rad]");
  CHECK(plot::DerivativeLabel(m, 1, "", 3, "length") == "ψ''' [rad/rad³]");
  CHECK(plot::DerivativeLabel(m, 1, "", 4, "length") == "ψ^(4) [rad/rad^4]");
  CHECK(plot::DerivativeLabel(m, 3, "", 0, "length") == "μ [deg]");
}

TEST_CASE("angles at order 0 and R-drive inputs are shown in degrees, nothing else", "[plot_support]") {
  const Mechanism m = FourBar();
  CHECK_THAT(plot::ShownInput(m, kPi / 4), Catch::Matchers::WithinAbs(45, kRoundoff));
  CHECK_THAT(plot::ShownOutput(m, 1, 0, kPi), Catch::Matchers::WithinAbs(180, kRoundoff));
  CHECK(plot::ShownOutput(m, 1, 1, 0.5) == 0.5);  // rad/rad stays
  CHECK(plot::ShownOutput(m, 0, 0, 0.5) == 0.5);  // a length stays
}

TEST_CASE("runs become one subpath per stretch; the y range spans them all", "[plot_support]") {
  const Mechanism m = FourBar();
  plot::SampledRun run;
  run.order = 0;
  run.inputs = {0.0, 0.1, 0.2, 1.0, 1.1};
  run.outputs = Table(5, 5);  // K_x, K_y, psi, phi, mu at order 0
  for (int i = 0; i < 5; ++i)
    for (int c = 0; c < 5; ++c) run.outputs(i, c) = 10 * i + c;
  run.stretches = {{0, 3}, {3, 5}};
  const int psi = run.Column(m, 1, 0, 0);
  const auto runs = plot::InputRuns(m, run, psi, 1, 0);
  REQUIRE(runs.size() == 2);
  REQUIRE(runs[0].size() == 3);
  REQUIRE(runs[1].size() == 2);
  CHECK_THAT(runs[1][1].x(), Catch::Matchers::WithinAbs(RadToDeg(1.1), kRoundoff));
  CHECK_THAT(runs[1][1].y(), Catch::Matchers::WithinAbs(RadToDeg(40 + psi), kRoundoff));
  double low = 0, high = 0;
  REQUIRE(plot::YRange(runs, &low, &high));
  CHECK(low == runs[0][0].y());
  CHECK(high == runs[1][1].y());
  CHECK_FALSE(plot::YRange({}, &low, &high));
}

TEST_CASE("a range must be finite, stepped and not too long", "[plot_support]") {
  SweepOptions r;
  std::string why;
  r.from = 0;
  r.to = 10;
  r.step = 1;
  CHECK(plot::RangeIsValid(r, 11, &why));    // 0, 1, ..., 10: 11 samples
  CHECK_FALSE(plot::RangeIsValid(r, 10, &why));
  CHECK_THAT(why, Catch::Contains("asks for 11 samples, more than 9"));
  r.step = 0;
  CHECK_FALSE(plot::RangeIsValid(r, 1000, &why));
  r.step = 1;
  r.to = std::nan("");
  CHECK_FALSE(plot::RangeIsValid(r, 1000, &why));
  CHECK_THAT(why, Catch::Contains("finite"));
}

TEST_CASE("the convex hull: a square with points inside and on its sides is its four corners", "[plot_support]") {
  const std::vector<Eigen::Vector2d> points = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 0}, {2, 1}, {1, 1}, {0.5, 1.5}, {0, 2}};
  const auto hull = plot::ConvexHull(points);
  REQUIRE(hull.size() == 4);
  // counter-clockwise from the lowest-leftmost point
  CHECK(hull[0] == Eigen::Vector2d(0, 0));
  CHECK(hull[1] == Eigen::Vector2d(2, 0));
  CHECK(hull[2] == Eigen::Vector2d(2, 2));
  CHECK(hull[3] == Eigen::Vector2d(0, 2));
  CHECK(plot::ConvexHull({{1, 1}, {1, 1}, {1, 1}}).size() == 1);
  CHECK(plot::ConvexHull({{0, 0}, {1, 1}, {2, 2}, {3, 3}}).size() == 2);  // on one line: its ends
}

TEST_CASE("the convex hull of random points holds them all and turns left at every vertex", "[plot_support]") {
  std::mt19937 rng(2403);
  std::normal_distribution<double> g(0, 1);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Eigen::Vector2d> points(10 + trial);
    for (auto& p : points) p = {g(rng), g(rng)};
    const auto hull = plot::ConvexHull(points);
    REQUIRE(hull.size() >= 3);
    const size_t n = hull.size();
    for (size_t i = 0; i < n; ++i) {
      // a vertex of the hull is one of the points
      CHECK(std::find(points.begin(), points.end(), hull[i]) != points.end());
      // strictly convex, counter-clockwise
      CHECK(Cross(hull[i], hull[(i + 1) % n], hull[(i + 2) % n]) > 0);
      // every point on or left of every edge
      for (const auto& p : points) CHECK(Cross(hull[i], hull[(i + 1) % n], p) >= -kRoundoff);
    }
  }
}

TEST_CASE("JSON in a page's script: no <, > or &, the same JSON read back", "[plot_support]") {
  // the HTML parser's script data state (HTML Living Standard 13.2.5.4 ff.): "</script" ends the
  // script, "<!--" then "<script" makes it swallow the page's next </script>; both the names of
  // tests/data/hostile-names.yaml and the title of the repro
  const nlohmann::json data = {{"title", "offset <!--<script>"},
                               {"names", {"s<img src=x onerror=\"document.title+='[X]'\">", "</script><b>x</b> & y", "a\u2028b\u2029c"}}};
  const std::string embedded = plot::ScriptSafe(data.dump());
  CHECK(embedded.find_first_of("<>&") == std::string::npos);
  CHECK(embedded.find("\u2028") == std::string::npos);  // the raw line separator (U+2028 in UTF-8)
  CHECK(embedded.find("\\u003c!--\\u003cscript\\u003e") != std::string::npos);
  CHECK(embedded.find("\\u2028") != std::string::npos);
  // reference: nlohmann's parser reads the embedded text back to the same value
  CHECK(nlohmann::json::parse(embedded) == data);
}

}  // namespace
}  // namespace koppel::plot_support_test

namespace koppel::plot_support_fill_test {

TEST_CASE("Fill: each {{KEY}} its value, an unknown key kept, an unclosed {{ left as it is", "[plot_support]") {
  using plot::Fill;
  CHECK(Fill("<p>{{A}} and {{B}}</p>", {{"A", "1"}, {"B", "{{A}}"}}) == "<p>1 and {{A}}</p>");  // a value is not filled again
  CHECK(Fill("{{C}}", {{"A", "1"}}) == "{{C}}");
  CHECK(Fill("a {{A}} b {{A", {{"A", "1"}}) == "a 1 b {{A");  // once looped forever
}

}  // namespace koppel::plot_support_fill_test
