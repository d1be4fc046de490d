// Parameter formulas through muparser: values, constants, order, errors.
#include "koppel/core/expression.hpp"
#include "koppel/core/limits.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace koppel::expression_test {

// relative: a formula of a few operations evaluated by muparser against the same in C++: a few ulps
constexpr double kUlps = 1e-15;

TEST_CASE("formulas name earlier parameters; pi and deg are constants", "[expression]") {
  ParameterSet p;
  REQUIRE(p.Define("l2", "5/2*sqrt(3)"));
  REQUIRE(p.Define("kappa", "acos(5/9*sqrt(3))"));
  REQUIRE(p.Define("k", "2*l2*cos(kappa)"));
  CHECK(p.Value("k") == Approx(25.0 / 3).epsilon(kUlps));  // seed 003: AK = 2 l2 cos kappa = 25/3
  CHECK(p.Evaluate("90*deg").value() == Approx(M_PI / 2).epsilon(kUlps));
  CHECK(p.Evaluate("pi").value() == Approx(M_PI).epsilon(kUlps));
  // redefinition replaces the value
  REQUIRE(p.Define("l2", "1"));
  CHECK(p.Value("l2") == 1.0);
  p.DefineValue("phi", 0.25);
  CHECK(p.Value("phi") == 0.25);
}

TEST_CASE("formula errors say what is wrong", "[expression]") {
  ParameterSet p;
  CHECK_FALSE(p.Evaluate("2*(3"));
  CHECK_THAT(p.Evaluate("2*(3").error(), Catch::Contains("does not parse"));
  CHECK_FALSE(p.Evaluate("l9 + 1"));
  CHECK_THAT(p.Evaluate("l9 + 1").error(), Catch::Contains("l9"));
  CHECK_FALSE(p.Evaluate("sqrt(-1)"));
  CHECK_THAT(p.Evaluate("sqrt(-1)").error(), Catch::Contains("finite"));
  CHECK_FALSE(p.Evaluate("1/0"));
  CHECK(ParameterSet::ValidName("l_2"));
  CHECK_FALSE(ParameterSet::ValidName("2l"));
  CHECK_FALSE(ParameterSet::ValidName("pi"));
}

}  // namespace koppel::expression_test

namespace koppel::expression_test {

TEST_CASE("a formula costs the same whatever came before it: 20 000 parameters read linearly", "[expression][limits]") {
  // each formula names one earlier parameter: the work (parameter values bound into formulas)
  // is one per formula, where binding the whole set per formula cost n^2/2 = 2e8
  constexpr int kCount = 20'000;
  ParameterSet p;
  const long long reads_before = ParameterSet::ParameterReads();
  REQUIRE(p.Define("p0", "1"));
  for (int i = 1; i < kCount; ++i) {
    REQUIRE(p.Define("p" + std::to_string(i), "p" + std::to_string(i - 1) + " + 1"));
  }
  CHECK(ParameterSet::ParameterReads() - reads_before == kCount - 1);
  CHECK(p.Value("p19999") == 20'000.0);  // 1 + 19 999 ones, exact in doubles
  CHECK(p.Values().size() == kCount);
  // a formula naming two parameters reads two, however many are defined
  const long long before_two = ParameterSet::ParameterReads();
  CHECK(p.Evaluate("p0 + p19999").value() == 20'001.0);
  CHECK(ParameterSet::ParameterReads() - before_two == 2);
}

TEST_CASE("a formula longer than kMaxFormulaLength is refused before it is parsed", "[expression][limits]") {
  ParameterSet p;
  std::string formula = "1";
  while (formula.size() <= kMaxFormulaLength) formula += "+1";
  CHECK_FALSE(p.Evaluate(formula));
  CHECK_THAT(p.Evaluate(formula).error(), Catch::Contains("kMaxFormulaLength"));
  CHECK(p.Evaluate(formula.substr(0, kMaxFormulaLength - 1)).has_value());  // just under it: fine
}

TEST_CASE("sets do not see each other's parameters through the shared parser", "[expression]") {
  ParameterSet a, b;
  REQUIRE(a.Define("x", "2"));
  REQUIRE(b.Define("y", "3"));
  CHECK(a.Evaluate("x*10").value() == 20.0);
  CHECK_FALSE(b.Evaluate("x*10"));  // x belongs to a only
  CHECK_THAT(b.Evaluate("x*10").error(), Catch::Contains("unknown name 'x'"));
  CHECK(b.Evaluate("y*10").value() == 30.0);
  ParameterSet copy = a;  // a copy evaluates with its own values
  copy.DefineValue("x", 5);
  CHECK(copy.Evaluate("x").value() == 5.0);
  CHECK(a.Evaluate("x").value() == 2.0);
}

}  // namespace koppel::expression_test

namespace koppel::expression_test {

// Issue 23 item 1: muparser reads "2,6" as two results and returned the last (6), so a decimal
// comma passed silently as another number. The reference is the text itself: 2,6 is not 6.
TEST_CASE("a comma outside a function's arguments is refused, with the decimal reading", "[expression]") {
  ParameterSet p;
  for (const char* text : {"2,6", "1,0.2,5", "max(1,2),3", "2,6+min(1,2)"}) {
    INFO(text);
    CHECK_FALSE(p.Evaluate(text));
  }
  CHECK_THAT(p.Evaluate("2,6").error(), Catch::Contains("a decimal comma? write 2.6"));
  CHECK_THAT(p.Evaluate("2,6").error(), Catch::Contains("character 2"));
  CHECK_THAT(p.Evaluate("1500,0").error(), Catch::Contains("write 1500.0"));
  // a number that has its point already is no decimal comma's: the general hint, no reading
  CHECK_THAT(p.Evaluate("1.5,25").error(), !Catch::Contains("1.5.25") && Catch::Contains("decimal comma"));
  // a comma between a function's arguments is its own: the values are those of the function
  CHECK(p.Evaluate("min(2,6)").value() == 2.0);
  CHECK(p.Evaluate("atan2(1,0)").value() == Approx(M_PI / 2).epsilon(kUlps));
  // a comma that makes a function call wrong gets the hint too
  CHECK_THAT(p.Evaluate("sin(2,6)").error(), Catch::Contains("a decimal comma? write 2.6"));
  // Define refuses the same: nothing is defined
  CHECK_FALSE(p.Define("l2", "2,6"));
  CHECK_FALSE(p.Has("l2"));
}

TEST_CASE("a list of values is cut at its top-level commas and its count checked", "[expression]") {
  const ParameterSet p;
  const Expected<std::vector<double>> xy = p.EvaluateList("1, min(0.2,5)", 2, "X,Y");
  REQUIRE(xy);
  CHECK((*xy)[0] == 1.0);
  CHECK((*xy)[1] == 0.2);
  // --circle-point 1,0.2,5 was read as (1, 5): three values for two
  const Expected<std::vector<double>> three = p.EvaluateList("1,0.2,5", 2, "X,Y");
  REQUIRE_FALSE(three);
  CHECK_THAT(three.error(), Catch::Contains("expected 2 values X,Y, found 3"));
  CHECK_THAT(three.error(), Catch::Contains("decimal comma"));
  CHECK_FALSE(p.EvaluateList("1", 2, "X,Y"));
  CHECK_THAT(p.EvaluateList("1,zz", 2, "X,Y").error(), Catch::Contains("unknown name 'zz'"));
}

}  // namespace koppel::expression_test

namespace koppel::expression_test {

// The bits of a result, or "none" with no value: a plain number or name (valued without muparser,
// issue 25) must give what muparser gives for the same text in brackets, bit for bit, sign of
// zero included, and fail where muparser fails.
std::string Bits(const Expected<double>& value) {
  if (!value) return "none";
  uint64_t bits = 0;
  std::memcpy(&bits, &*value, sizeof bits);
  return std::to_string(bits);
}

TEST_CASE("a plain number or name is valued without muparser, as muparser values it", "[expression]") {
  ParameterSet p;
  // names muparser might read otherwise: functions without brackets, number-like words, 'e'
  for (const char* name : {"a", "e", "E", "sin", "min", "inf", "nan", "x1e5", "d_2", "zero"}) p.DefineValue(name, 0);
  p.DefineValue("a", 1.5);
  p.DefineValue("e", 0.3);
  p.DefineValue("E", -2.25);
  p.DefineValue("x1e5", 1e-300);
  p.DefineValue("d_2", 4.0 / 3);
  std::vector<std::string> texts = {"0", "-0", "1", "-1", "3.5", "007", "0.1", "1e5", "1E-9", "1e+3", "-2.5e-3",
                                    "123456789012345678901234567890", "0.30000000000000004", "1.7976931348623157e308",
                                    "2.2250738585072014e-308", "1e400", "1e-400", "4.9e-324", "1.", ".5", "+1", "1e", "1.e5",
                                    "- 1", "--1", "0x10", " 1", "1 "};
  for (const char* name : {"a", "e", "E", "sin", "min", "inf", "nan", "x1e5", "d_2", "zero", "pi", "deg", "_pi", "_e", "q"}) {
    texts.push_back(name);
    texts.push_back(std::string("-") + name);
  }
  // numbers of every magnitude as people and programs write them
  std::mt19937_64 random(25);
  std::uniform_real_distribution<double> mantissa(-10, 10);
  std::uniform_int_distribution<int> exponent(-320, 308), digits(1, 17);
  for (int i = 0; i < 3000; ++i) {
    char text[64];
    std::snprintf(text, sizeof text, i % 3 ? "%.*g" : "%.*f", digits(random), mantissa(random) * std::pow(10.0, i % 2 ? exponent(random) : exponent(random) % 6));
    texts.push_back(text);
  }
  for (const std::string& text : texts) {
    INFO(text);
    CHECK(Bits(p.Evaluate(text)) == Bits(p.Evaluate("(" + text + ")")));
  }
  CHECK(Bits(p.Evaluate("d_2")) == Bits(4.0 / 3));
  CHECK_THAT(p.Evaluate("q").error(), Catch::Contains("unknown name 'q'"));
  CHECK_FALSE(p.Evaluate("1e400"));  // muparser's answer: no number it reads ("unknown name")
}

}  // namespace koppel::expression_test
