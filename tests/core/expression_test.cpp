// Parameter formulas through muparser: values, constants, order, errors.
#include "koppel/core/expression.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace koppel {

TEST_CASE("formulas name earlier parameters; pi and deg are constants", "[expression]") {
  ParameterSet p;
  std::string error;
  REQUIRE(p.Define("l2", "5/2*sqrt(3)", &error));
  REQUIRE(p.Define("kappa", "acos(5/9*sqrt(3))", &error));
  REQUIRE(p.Define("k", "2*l2*cos(kappa)", &error));
  CHECK(p.Value("k") == Approx(25.0 / 3).epsilon(1e-15));  // seed 003: AK = 2 l2 cos kappa = 25/3
  CHECK(p.Evaluate("90*deg", &error).value() == Approx(M_PI / 2).epsilon(1e-15));
  CHECK(p.Evaluate("pi", &error).value() == Approx(M_PI).epsilon(1e-15));
  // redefinition replaces the value
  REQUIRE(p.Define("l2", "1", &error));
  CHECK(p.Value("l2") == 1.0);
  p.DefineValue("phi", 0.25);
  CHECK(p.Value("phi") == 0.25);
}

TEST_CASE("formula errors say what is wrong", "[expression]") {
  ParameterSet p;
  std::string error;
  CHECK_FALSE(p.Evaluate("2*(3", &error));
  CHECK_THAT(error, Catch::Contains("does not parse"));
  CHECK_FALSE(p.Evaluate("l9 + 1", &error));
  CHECK_THAT(error, Catch::Contains("l9"));
  CHECK_FALSE(p.Evaluate("sqrt(-1)", &error));
  CHECK_THAT(error, Catch::Contains("finite"));
  CHECK_FALSE(p.Evaluate("1/0", &error));
  CHECK(ParameterSet::ValidName("l_2"));
  CHECK_FALSE(ParameterSet::ValidName("2l"));
  CHECK_FALSE(ParameterSet::ValidName("pi"));
}

}  // namespace koppel
