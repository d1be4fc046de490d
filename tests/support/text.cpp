#include "support/text.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>

namespace koppel::test {

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  REQUIRE(pos != std::string::npos);
  return text.replace(pos, from.size(), to);
}

int LineOf(const std::string& text, const std::string& needle) {
  const auto pos = text.find(needle);
  REQUIRE(pos != std::string::npos);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

std::map<std::string, double> ParseSummary(const std::string& csv) {
  std::map<std::string, double> values;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "quantity,value,unit");
  while (std::getline(in, line)) {
    const auto a = line.find(','), b = line.rfind(',');
    values[line.substr(0, a)] = std::stod(line.substr(a + 1, b - a - 1));
  }
  return values;
}

std::vector<std::vector<std::string>> CsvCells(const std::string& csv) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(csv);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string>& cells = rows.emplace_back();
    std::istringstream l(line);
    for (std::string cell; std::getline(l, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
  }
  return rows;
}

}  // namespace koppel::test
