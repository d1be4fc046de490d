// Formulas compiled once and evaluated over variables.
#include "koppel/core/formula.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel::formula_test {

// relative: a compiled formula against the same arithmetic in C++: a few ulps
constexpr double kUlps = 1e-15;

TEST_CASE("a compiled formula reads its variables and the parameters", "[formula]") {
  ParameterSet parameters;
  REQUIRE(parameters.Define("F0", "100"));
  REQUIRE(parameters.Define("s", "1000"));  // shadowed by the variable s below
  Expected<CompiledFormula> compiled = CompiledFormula::Compile("F0*sin(phi) + s/2 + 30*deg", parameters, {"phi", "s"});
  REQUIRE(compiled);
  CompiledFormula& f = *compiled;
  const double values[] = {0.5, 4.0};
  CHECK(f.Evaluate(values) == Approx(100 * std::sin(0.5) + 2.0 + kPi / 6).epsilon(kUlps));
  const double others[] = {-1.0, 0.0};
  CHECK(f.Evaluate(others) == Approx(100 * std::sin(-1.0) + kPi / 6).epsilon(kUlps));
  // moved, it still evaluates (the variables live with it)
  CompiledFormula moved = std::move(f);
  CHECK(moved.Evaluate(values) == Approx(100 * std::sin(0.5) + 2.0 + kPi / 6).epsilon(kUlps));
  CHECK(moved.text() == "F0*sin(phi) + s/2 + 30*deg");
}

TEST_CASE("a formula that does not parse is refused; one without a value gives NaN", "[formula]") {
  const Expected<CompiledFormula> unknown = CompiledFormula::Compile("2*omega", ParameterSet(), {"phi"});
  CHECK_FALSE(unknown);
  CHECK_THAT(unknown.error(), Catch::Contains("unknown name 'omega'"));
  CHECK_FALSE(CompiledFormula::Compile("2*(phi", ParameterSet(), {"phi"}));
  const Expected<CompiledFormula> root = CompiledFormula::Compile("sqrt(phi)", ParameterSet(), {"phi"});
  REQUIRE(root);  // compiles although sqrt(0 - ...) has no value
  const double negative[] = {-1.0};
  CHECK(std::isnan(root->Evaluate(negative)));
  const double zero[] = {0.0};
  const Expected<CompiledFormula> reciprocal = CompiledFormula::Compile("1/phi", ParameterSet(), {"phi"});
  REQUIRE(reciprocal);
  CHECK(std::isnan(reciprocal->Evaluate(zero)));
}

}  // namespace koppel::formula_test

namespace koppel::formula_test {

// Issue 23 item 1: a torque formula "2,5*phi_dot" compiled to 5*phi_dot.
TEST_CASE("a compiled formula refuses a comma outside a function's arguments", "[formula]") {
  const ParameterSet none;
  const Expected<CompiledFormula> f = CompiledFormula::Compile("2,5*x", none, {"x"});
  REQUIRE_FALSE(f);
  CHECK_THAT(f.error(), Catch::Contains("a decimal comma? write 2.5"));
  const Expected<CompiledFormula> g = CompiledFormula::Compile("max(x,1)", none, {"x"});
  REQUIRE(g);
  const double x = 3;
  CHECK(g->Evaluate(&x) == 3.0);
}

}  // namespace koppel::formula_test
