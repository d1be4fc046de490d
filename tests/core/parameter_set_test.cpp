// The plain values of a ParameterSet (core/src/parameter_set.cpp, apart from the formulas of
// expression.cpp): the naming rule, values defined exactly, in definition order, a redefinition in
// place, and copies that own their values. References: the rule as expression.hpp states it (a
// letter or '_', then letters, digits, '_'; not pi or deg), applied by hand to each name below;
// the bit patterns of the values stored (no formula round trip may change a bit); the order in
// which this test defines the names.
#include "koppel/core/expression.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace koppel::parameter_set_test {
namespace {

// Same bits: -0.0 and 0.0 (and two NaNs) compare equal or unequal where a stored value must not change.
bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("parameter names: a letter or '_' first, then letters, digits and '_'; pi and deg are taken", "[core][parameter-set]") {
  for (const char* name : {"a", "_", "_1", "l2", "L_2b", "Pi", "DEG", "pi2", "degree", "x__y"}) {
    INFO(name);
    CHECK(ParameterSet::ValidName(name));
  }
  // empty; a digit first; a sign, dot, space, hyphen, bracket; a non-ASCII letter (UTF-8 bytes of
  // 'φ' and 'ä'); the two constants
  for (const char* name : {"", "2l", "9", "a-b", "a.b", "a b", " a", "a ", "l[1]", "+a", "\xCF\x86", "l\xC3\xA4nge", "pi", "deg"}) {
    INFO("'" << name << "'");
    CHECK_FALSE(ParameterSet::ValidName(name));
  }
}

TEST_CASE("DefineValue keeps each value exactly, in the order first defined; a redefinition replaces in place", "[core][parameter-set]") {
  ParameterSet p;
  CHECK(p.Values().empty());
  CHECK_FALSE(p.Has("x"));
  // values no decimal text of 15 digits gives back: the next double after 1, 0.1 + 0.2, the
  // smallest subnormal, negative zero, the largest double
  const double after_one = std::nextafter(1.0, 2.0), sum = 0.1 + 0.2, tiny = std::numeric_limits<double>::denorm_min();
  const double huge = std::numeric_limits<double>::max();
  p.DefineValue("c", after_one);
  p.DefineValue("a", sum);
  p.DefineValue("b", tiny);
  p.DefineValue("z", -0.0);
  p.DefineValue("h", huge);
  REQUIRE(p.Values().size() == 5);
  const std::vector<std::string> order = {"c", "a", "b", "z", "h"};
  const std::vector<double> values = {after_one, sum, tiny, -0.0, huge};
  for (size_t i = 0; i < order.size(); ++i) {
    INFO(order[i]);
    CHECK(p.Values()[i].first == order[i]);
    CHECK(SameBits(p.Values()[i].second, values[i]));
    CHECK(p.Has(order[i]));
    CHECK(SameBits(p.Value(order[i]), values[i]));
  }
  CHECK(std::signbit(p.Value("z")));
  // a redefinition: the same place, the new value, no second entry
  p.DefineValue("a", -7.25);
  REQUIRE(p.Values().size() == 5);
  CHECK(p.Values()[1].first == "a");
  CHECK(p.Values()[1].second == -7.25);
  CHECK(p.Value("a") == -7.25);
  // names are case-sensitive; an unknown name has no value (NaN, never another parameter's)
  CHECK_FALSE(p.Has("A"));
  CHECK(std::isnan(p.Value("A")));
  // formulas see the exact value (a name alone is read as it is, not through text)
  CHECK(SameBits(p.Evaluate("c").value(), after_one));
  CHECK(p.Evaluate("-a").value() == 7.25);
}

TEST_CASE("a copied or assigned set owns its values and its index", "[core][parameter-set]") {
  ParameterSet a;
  a.DefineValue("l1", 1.0);
  a.DefineValue("l2", 2.0);
  ParameterSet copy(a);
  copy.DefineValue("l1", 10.0);  // replaced in the copy only
  copy.DefineValue("l3", 3.0);   // added to the copy only
  CHECK(a.Value("l1") == 1.0);
  CHECK_FALSE(a.Has("l3"));
  CHECK(a.Values().size() == 2);
  CHECK(copy.Values().size() == 3);
  CHECK(copy.Values()[0].first == "l1");
  CHECK(copy.Values()[0].second == 10.0);

  // assignment replaces every name of the target: its own names are gone, and its index points
  // into its own list (a redefinition there lands on the right entry, not a new one)
  ParameterSet b;
  b.DefineValue("only_b", 5.0);
  b.DefineValue("l2", -1.0);
  b = a;
  CHECK_FALSE(b.Has("only_b"));
  REQUIRE(b.Values().size() == 2);
  b.DefineValue("l2", 20.0);
  REQUIRE(b.Values().size() == 2);
  CHECK(b.Values()[1].first == "l2");
  CHECK(b.Values()[1].second == 20.0);
  CHECK(a.Value("l2") == 2.0);
  CHECK(b.Evaluate("l1 + l2").value() == 21.0);
  CHECK(a.Evaluate("l1 + l2").value() == 3.0);
}

}  // namespace koppel::parameter_set_test
