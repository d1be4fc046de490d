// Formulas compiled once and evaluated over variables.
#include "koppel/core/formula.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel {

TEST_CASE("a compiled formula reads its variables and the parameters", "[formula]") {
  ParameterSet parameters;
  std::string error;
  REQUIRE(parameters.Define("F0", "100", &error));
  REQUIRE(parameters.Define("s", "1000", &error));  // shadowed by the variable s below
  CompiledFormula f;
  REQUIRE(f.Compile("F0*sin(phi) + s/2 + 30*deg", parameters, {"phi", "s"}, &error));
  const double values[] = {0.5, 4.0};
  CHECK(f.Evaluate(values) == Approx(100 * std::sin(0.5) + 2.0 + kPi / 6).epsilon(1e-15));
  const double others[] = {-1.0, 0.0};
  CHECK(f.Evaluate(others) == Approx(100 * std::sin(-1.0) + kPi / 6).epsilon(1e-15));
  // moved, it still evaluates (the variables live with it)
  CompiledFormula moved = std::move(f);
  CHECK(moved.Evaluate(values) == Approx(100 * std::sin(0.5) + 2.0 + kPi / 6).epsilon(1e-15));
  CHECK(moved.text() == "F0*sin(phi) + s/2 + 30*deg");
}

TEST_CASE("a formula that does not parse is refused; one without a value gives NaN", "[formula]") {
  CompiledFormula f;
  std::string error;
  CHECK_FALSE(f.Compile("2*omega", ParameterSet(), {"phi"}, &error));
  CHECK_THAT(error, Catch::Contains("unknown name 'omega'"));
  CHECK_FALSE(f.Compile("2*(phi", ParameterSet(), {"phi"}, &error));
  REQUIRE(f.Compile("sqrt(phi)", ParameterSet(), {"phi"}, &error));  // compiles although sqrt(0 - ...) has no value
  const double negative[] = {-1.0};
  CHECK(std::isnan(f.Evaluate(negative)));
  const double zero[] = {0.0};
  REQUIRE(f.Compile("1/phi", ParameterSet(), {"phi"}, &error));
  CHECK(std::isnan(f.Evaluate(zero)));
}

}  // namespace koppel
