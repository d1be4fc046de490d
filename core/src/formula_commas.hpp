// The one rule on commas in a formula (expression.cpp, formula.cpp): muparser reads "2,6" as two
// results and returns the last (6), so a decimal comma would pass silently as another number. A
// formula has one value: a comma outside a function's arguments (min(a,b), atan2(y,x)) is refused,
// and a formula that does not parse and has a comma between digits gets the same hint.
#pragma once

#include <string>
#include <vector>

namespace koppel::detail {

// Where the first comma outside any brackets is (0-based), or std::string::npos.
std::size_t TopLevelComma(const std::string& formula);

// `text` cut at its top-level commas: "1,min(2,3)" -> {"1", "min(2,3)"}; no comma: {text}.
std::vector<std::string> SplitAtTopLevelCommas(const std::string& text);

// The message for a formula with a top-level comma at `at`: which character, and when digits
// surround it the decimal reading ("a decimal comma? write 2.6").
std::string CommaOperatorError(const std::string& formula, std::size_t at);

// " (a decimal comma? write 2.6)" when `formula` has a comma between two digits, else "".
std::string DecimalCommaHint(const std::string& formula);

}  // namespace koppel::detail
