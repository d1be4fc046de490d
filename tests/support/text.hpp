// Small text helpers for tests that mutate files and read CLI output.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace koppel::test {

// `text` with the first occurrence of `from` (which must exist: a test failure otherwise)
// replaced by `to`.
std::string Replace(std::string text, const std::string& from, const std::string& to);
// 1-based line of the first occurrence of `needle` (which must exist).
int LineOf(const std::string& text, const std::string& needle);
// A "quantity,value,unit" CSV as a map quantity -> value.
std::map<std::string, double> ParseSummary(const std::string& csv);
// A CSV as rows of cells, an empty cell kept where it is (also the last one: "1,,").
std::vector<std::vector<std::string>> CsvCells(const std::string& csv);

}  // namespace koppel::test
