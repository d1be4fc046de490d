// The comma rule of formulas (formula_commas.hpp) on hand-worked examples: where the top-level
// comma is (brackets counted by hand), how a text is cut there, and the decimal reading the
// messages offer ("2,6" -> "2.6", none when the number already has its point).
#include "formula_commas.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace koppel::formula_commas_test {

using detail::CommaOperatorError;
using detail::DecimalCommaHint;
using detail::SplitAtTopLevelCommas;
using detail::TopLevelComma;

TEST_CASE("SplitAtTopLevelCommas cuts only outside brackets", "[formula_commas]") {
  // hand-worked: the header's example, a nested call, no comma, an empty item at either end
  CHECK(SplitAtTopLevelCommas("1,min(2,3)") == std::vector<std::string>{"1", "min(2,3)"});
  CHECK(SplitAtTopLevelCommas("atan2(min(a,b),x),2") == std::vector<std::string>{"atan2(min(a,b),x)", "2"});
  CHECK(SplitAtTopLevelCommas("l1*2") == std::vector<std::string>{"l1*2"});
  CHECK(SplitAtTopLevelCommas("") == std::vector<std::string>{""});
  CHECK(SplitAtTopLevelCommas(",a,") == std::vector<std::string>{"", "a", ""});
  // a stray closing bracket does not drive the depth negative: the next comma is still top level
  CHECK(SplitAtTopLevelCommas("a),b") == std::vector<std::string>{"a)", "b"});
  // an unclosed bracket hides every later comma
  CHECK(SplitAtTopLevelCommas("min(a,b") == std::vector<std::string>{"min(a,b"});
}

TEST_CASE("TopLevelComma is the 0-based index of the first top-level comma", "[formula_commas]") {
  // hand-counted indices
  CHECK(TopLevelComma("2,6") == 1);
  CHECK(TopLevelComma("min(a,b),c,d") == 8);
  CHECK(TopLevelComma("min(a,b)") == std::string::npos);
  CHECK(TopLevelComma("atan2(y,x) + 1") == std::string::npos);
  CHECK(TopLevelComma("") == std::string::npos);
  // by definition: the character there is the comma, and what precedes it is the first item
  const std::string formula = "sin(phi)*min(1,2) , 3";
  const std::size_t at = TopLevelComma(formula);
  REQUIRE(at != std::string::npos);
  CHECK(formula[at] == ',');
  CHECK(formula.substr(0, at) == SplitAtTopLevelCommas(formula)[0]);
}

TEST_CASE("CommaOperatorError names the 1-based character and the decimal reading", "[formula_commas]") {
  // "2,6": comma at index 1, character 2; digits on both sides read as 2.6
  const std::string decimal = CommaOperatorError("2,6", 1);
  CHECK(decimal.find("'2,6'") != std::string::npos);
  CHECK(decimal.find("at character 2 ") != std::string::npos);
  CHECK(decimal.find(": a decimal comma? write 2.6") != std::string::npos);
  // the whole number around the comma: "l1*12,50" -> 12.50 (not 2.5)
  CHECK(CommaOperatorError("l1*12,50", 5).find("write 12.50") != std::string::npos);
  // "1.5,25" has its point already: no decimal reading, the general hint
  const std::string pointed = CommaOperatorError("1.5,25", 3);
  CHECK(pointed.find("write 1.5.25") == std::string::npos);
  CHECK(pointed.find("(a decimal comma? write a decimal point: 2.6, not 2,6)") != std::string::npos);
  // a comma not between digits: the general hint, at its character
  const std::string names = CommaOperatorError("a,b", 1);
  CHECK(names.find("at character 2 ") != std::string::npos);
  CHECK(names.find("(a decimal comma? write a decimal point") != std::string::npos);
  // a comma at either end of the text has no digit on one side
  CHECK(CommaOperatorError(",5", 0).find("write a decimal point") != std::string::npos);
  CHECK(CommaOperatorError("5,", 1).find("write a decimal point") != std::string::npos);
}

TEST_CASE("DecimalCommaHint gives the first comma between digits, else nothing", "[formula_commas]") {
  // hand-worked readings
  CHECK(DecimalCommaHint("min(2,6") == " (a decimal comma? write 2.6)");
  CHECK(DecimalCommaHint("0.5+1,25") == " (a decimal comma? write 1.25)");
  // the first comma has names around it, the second digits: the second is the one
  CHECK(DecimalCommaHint("min(a,b)+2,5") == " (a decimal comma? write 2.5)");
  CHECK(DecimalCommaHint("min(a,b)") == "");
  CHECK(DecimalCommaHint("1.5,25") == "");
  CHECK(DecimalCommaHint("2 ,6") == "");
  CHECK(DecimalCommaHint("") == "");
}

}  // namespace koppel::formula_commas_test
