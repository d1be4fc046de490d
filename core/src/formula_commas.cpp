#include "formula_commas.hpp"

#include <cctype>

namespace koppel::detail {
namespace {

bool IsDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// The comma at `at` between digits read as a decimal point: the number around it, "2,6" -> "2.6".
std::string DecimalReading(const std::string& text, std::size_t at) {
  if (at == 0 || at + 1 >= text.size() || !IsDigit(text[at - 1]) || !IsDigit(text[at + 1])) return "";
  std::size_t begin = at, end = at + 1;
  while (begin > 0 && (IsDigit(text[begin - 1]) || text[begin - 1] == '.')) --begin;
  while (end < text.size() && IsDigit(text[end])) ++end;
  // "1.5,25" has its point already: whatever the comma is, it is not a decimal one
  if (text.substr(begin, at - begin).find('.') != std::string::npos) return "";
  return text.substr(begin, at - begin) + "." + text.substr(at + 1, end - at - 1);
}

}  // namespace

std::size_t TopLevelComma(const std::string& formula) {
  const std::vector<std::string> items = SplitAtTopLevelCommas(formula);
  return items.size() == 1 ? std::string::npos : items[0].size();
}

std::vector<std::string> SplitAtTopLevelCommas(const std::string& text) {
  std::vector<std::string> items(1);
  int depth = 0;
  for (const char c : text) {
    if (c == '(') ++depth;
    if (c == ')' && depth > 0) --depth;
    if (c == ',' && depth == 0) {
      items.emplace_back();
    } else {
      items.back() += c;
    }
  }
  return items;
}

std::string CommaOperatorError(const std::string& formula, std::size_t at) {
  std::string message = "formula '" + formula + "' has a comma at character " + std::to_string(at + 1) +
                        " that would make it a list of values; a number is one value";
  const std::string decimal = DecimalReading(formula, at);
  message += decimal.empty() ? " (a decimal comma? write a decimal point: 2.6, not 2,6)" : ": a decimal comma? write " + decimal;
  return message;
}

std::string DecimalCommaHint(const std::string& formula) {
  for (std::size_t i = formula.find(','); i != std::string::npos; i = formula.find(',', i + 1)) {
    if (const std::string decimal = DecimalReading(formula, i); !decimal.empty()) return " (a decimal comma? write " + decimal + ")";
  }
  return "";
}

}  // namespace koppel::detail
