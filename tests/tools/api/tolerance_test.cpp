// Model::Tolerances (tools/api/src/tolerance.cpp): the tolerance stack-up in the API's units
// (degrees for an angle output and for an R drive's input), a point output's component, the
// table's columns and rows, and every request the API refuses. References: seed 000's closed
// form of the slider-crank (tests/support/closed_forms; the catalog entry's l1 = 1, l2 = 2.6,
// e = 0.8) and of the crank-rocker's point B (circle intersection), their central differences for
// the sensitivities, c / cos psi for the crank pin's play (as tests/solver/analysis/tolerance_test),
// the uniform distribution's sigma = T / sqrt(3), and the column order tolerance.hpp documents.
#include "koppel/api/model.hpp"

#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace koppel::tolerance_test {
namespace {

constexpr double kRadToDeg = 180 / M_PI;
// [length | rad] a solved pose against the closed form: the solver's convergence
constexpr double kNominal = 1e-12;
// a sensitivity against a central difference with h = 1e-5: truncation h^2 y''' ~ 1e-10, rounding 1e-16 / h ~ 1e-11
constexpr double kSensitivity = 1e-8;
// relative: the same few products summed again here
constexpr double kSameSum = 1e-14;

// seed 000's s and mu at (l1, l2, e) = p, crank angle phi [rad]
double S(const std::vector<double>& p, double phi) { return test::SliderCrank(p[0], p[1], p[2], phi).s; }
double Mu(const std::vector<double>& p, double phi) { return test::SliderCrank(p[0], p[1], p[2], phi).mu; }
// d y / d p_j by central differences
double Central(const std::function<double(const std::vector<double>&)>& y, std::vector<double> p, int j) {
  std::vector<double> minus = p;
  p[j] += 1e-5, minus[j] -= 1e-5;
  return (y(p) - y(minus)) / 2e-5;
}

ToleranceRequest Request(const std::string& output, std::vector<double> inputs,
                         std::vector<std::pair<std::string, double>> tolerances = {{"l1", 0.01}, {"l2", 0.02}, {"e", 0.005}}) {
  ToleranceRequest r;
  r.output = output;
  r.inputs = std::move(inputs);
  r.tolerances = std::move(tolerances);
  return r;
}

const std::string kSliderCrank = test::CatalogEntryPath("slider-crank-offset");

}  // namespace

TEST_CASE("the slider's travel s: nominal and sensitivities of seed 000's closed form, inputs as asked", "[api][tolerance]") {
  const ToleranceResult r = Model::Load(kSliderCrank).Tolerances(Request("s", {0, 60, 135, 250}));
  REQUIRE(r.status == AnalysisStatus::kComplete);
  CHECK(r.input_name == "phi");
  CHECK(r.input_unit == "deg");
  CHECK(r.unit == "length");
  CHECK(r.parameters == std::vector<std::string>{"l1", "l2", "e"});
  const std::vector<double> p = {1, 2.6, 0.8}, t = {0.01, 0.02, 0.005};
  REQUIRE(r.rows.size() == 4);
  for (size_t i = 0; i < r.rows.size(); ++i) {
    const ToleranceRowReport& row = r.rows[i];
    const double phi = row.input / kRadToDeg;
    INFO("phi = " << row.input << " deg");
    REQUIRE(row.ok);
    CHECK(row.input == std::vector<double>{0, 60, 135, 250}[i]);  // as asked, not through radians
    CHECK_THAT(row.nominal, Catch::Matchers::WithinAbs(S(p, phi), kNominal));
    double worst = 0, square = 0;
    for (int j = 0; j < 3; ++j) {
      CHECK_THAT(row.sensitivity[j], Catch::Matchers::WithinAbs(Central([&](const auto& q) { return S(q, phi); }, p, j), kSensitivity));
      worst += std::abs(row.sensitivity[j]) * t[j];
      square += std::pow(row.sensitivity[j] * t[j], 2);
    }
    CHECK(row.worst_case == Approx(worst).epsilon(kSameSum));
    CHECK(row.rss == Approx(std::sqrt(square)).epsilon(kSameSum));
    CHECK(row.linear_std == Approx(std::sqrt(square / 3)).epsilon(kSameSum));  // uniform: sigma = T / sqrt(3)
  }
}

TEST_CASE("an angle output in degrees, its sensitivities in degrees per unit; the crank pin's play", "[api][tolerance]") {
  ToleranceRequest request = Request("mu", {30, 100, 250});
  request.clearances = {{"A", 0.003}};
  const ToleranceResult r = Model::Load(kSliderCrank).Tolerances(request);
  REQUIRE(r.status == AnalysisStatus::kComplete);
  CHECK(r.unit == "deg");
  const std::vector<double> p = {1, 2.6, 0.8};
  for (const ToleranceRowReport& row : r.rows) {
    const double phi = row.input / kRadToDeg;
    INFO("phi = " << row.input << " deg");
    CHECK_THAT(row.nominal, Catch::Matchers::WithinAbs(kRadToDeg * Mu(p, phi), kRadToDeg * kNominal));
    for (int j = 0; j < 3; ++j)
      CHECK_THAT(row.sensitivity[j], Catch::Matchers::WithinAbs(kRadToDeg * Central([&](const auto& q) { return Mu(q, phi); }, p, j),
                                                                kRadToDeg * kSensitivity));
  }
  // the same play on s: c / cos psi (seed 000: sin psi = -(l1 cos phi + e) / l2)
  request.output = "s";
  for (const ToleranceRowReport& row : Model::Load(kSliderCrank).Tolerances(request).rows) {
    const double sin_psi = -(std::cos(row.input / kRadToDeg) + 0.8) / 2.6;
    CHECK(row.clearance_worst_case == Approx(0.003 / std::sqrt(1 - sin_psi * sin_psi)).epsilon(1e-9));
  }
}

TEST_CASE("a point output by its component: B_x and B_y of the crank-rocker", "[api][tolerance]") {
  // the catalog's crank-rocker (a, b, c, d = 1, 3.5, 3, 4) with its coupler-rocker pin B as a point output
  const std::string text = test::Replace(test::ReadText(test::CatalogEntryPath("crank-rocker")), "  psi: {link: rocker}\n",
                                         "  psi: {link: rocker}\n  B: {point: coupler.B}\n");
  const Model model = Model::Parse(text, "crank-rocker-b.yaml");
  const std::vector<double> p = {1, 3.5, 3, 4};
  const auto b = [](const std::vector<double>& q, double phi) { return test::FourBarRocker(q[0], q[1], q[2], q[3], phi, +1)->b; };
  for (int component : {0, 1}) {
    const ToleranceRequest request = Request(component == 0 ? "B_x" : "B_y", {40, 200}, {{"a", 0.01}, {"d", 0.02}});
    const ToleranceResult r = model.Tolerances(request);
    REQUIRE(r.status == AnalysisStatus::kComplete);
    for (const ToleranceRowReport& row : r.rows) {
      const double phi = row.input / kRadToDeg;
      INFO(request.output << " at " << row.input << " deg");
      CHECK_THAT(row.nominal, Catch::Matchers::WithinAbs(b(p, phi)[component], kNominal));
      const auto y = [&](const std::vector<double>& q) { return b(q, phi)[component]; };
      for (int j : {0, 1})  // a and d: parameters 0 and 3
        CHECK_THAT(row.sensitivity[j], Catch::Matchers::WithinAbs(Central(y, p, 3 * j), kSensitivity));
    }
  }
  CHECK_THROWS_WITH(model.Tolerances(Request("B", {40}, {{"a", 0.01}})), Catch::Contains("name its component, B_x or B_y"));
}

TEST_CASE("the table: columns in the documented order, a row per input, empty cells where no pose", "[api][tolerance]") {
  ToleranceRequest request = Request("s", {180, 0}, {{"l1", 0.01}, {"e", 0.005}});
  request.clearances = {{"B", 0.002}};
  request.samples = 50;
  // e = 2 > l2 - l1: the crank does not turn round; at 0 deg |A_y| = e + l1 = 3 > l2, no pose
  const ToleranceResult r = Model::Load(kSliderCrank, {{"e", "2"}}).Tolerances(request);
  std::vector<std::string> expected = {"phi", "nominal", "sens_l1", "sens_e", "sens_clearance_B", "worst_case", "rss",
                                       "clearance_worst_case", "linear_std", "share_l1", "share_e", "share_clearance_B",
                                       "mc_samples", "mc_failed", "mc_min", "mc_max", "mc_mean", "mc_std"};
  for (const char* q : {"mc_q0.001", "mc_q0.01", "mc_q0.5", "mc_q0.99", "mc_q0.999"}) expected.push_back(q);
  CHECK(r.Columns() == expected);
  REQUIRE(r.rows.size() == 2);
  REQUIRE(r.rows[0].ok);
  CHECK_FALSE(r.rows[1].ok);
  CHECK(r.status != AnalysisStatus::kComplete);
  const std::vector<std::optional<double>> reached = r.Row(0), missed = r.Row(1);
  REQUIRE(reached.size() == expected.size());
  REQUIRE(missed.size() == expected.size());
  const ToleranceRowReport& row = r.rows[0];
  const std::vector<double> values = {180, row.nominal, row.sensitivity[0], row.sensitivity[1], row.clearance_gain[0], row.worst_case,
                                      row.rss, row.clearance_worst_case, row.linear_std, row.share[0], row.share[1], row.share[2],
                                      50, static_cast<double>(row.mc_failed), row.mc_min, row.mc_max, row.mc_mean, row.mc_std};
  for (size_t c = 0; c < values.size(); ++c) {
    INFO(expected[c]);
    REQUIRE(reached[c]);
    CHECK(*reached[c] == values[c]);
  }
  CHECK(missed[0] == 0.0);  // the input asked for stays
  for (size_t c = 1; c < missed.size(); ++c) CHECK_FALSE(missed[c]);
}

TEST_CASE("what the API refuses, at its field", "[api][tolerance]") {
  const Model model = Model::Load(kSliderCrank);
  const auto refused = [&](const std::function<void(ToleranceRequest&)>& change, const std::string& field, const std::string& phrase) {
    ToleranceRequest r = Request("s", {30});
    change(r);
    INFO(field << ": " << phrase);
    try {
      model.Tolerances(r);
      FAIL("not refused");
    } catch (const InputError& e) {
      CHECK(e.diagnostics()[0].path == field);
      CHECK_THAT(e.diagnostics()[0].message, Catch::Contains(phrase));
    }
  };
  refused([](auto& r) { r.output = std::string("velocity"); }, "output", "no output 'velocity'");
  refused([](auto& r) { r.inputs.clear(); }, "input", "no input");
  refused([](auto& r) { r.inputs = {NAN}; }, "input", "not a finite number");
  refused([](auto& r) { r.tolerances.push_back({"l9", 0.1}); }, "tol", "no parameter 'l9'");
  refused([](auto& r) { r.tolerances.push_back({"l1", 0.1}); }, "tol", "toleranced twice");
  refused([](auto& r) { r.tolerances[0].second = 0; }, "tol", "must be a positive number");
  refused([](auto& r) { r.tolerances.clear(); }, "tol", "at least one");
  refused([](auto& r) { r.clearances = {{"S", 0.01}}; }, "clearance", "is a slide");
  refused([](auto& r) { r.clearances = {{"Q", 0.01}}; }, "clearance", "no joint 'Q'");
  refused([](auto& r) { r.clearances = {{"A", 0.01}, {"A", 0.02}}; }, "clearance", "given twice");
  refused([](auto& r) { r.distribution = "gauss"; }, "distribution", "uniform or normal");
  CHECK_THROWS_WITH(Model::FromMechanism(test::SliderCrank(1, 2.6, 0.8)).Tolerances(Request("s", {30})),
                    Catch::Contains("built in code"));
}

}  // namespace koppel::tolerance_test
