#include "koppel/catalog/path_points.hpp"

#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/core/limits.hpp"
#include "input_file.hpp"
#include "text_lines.hpp"

#include <charconv>
#include <cmath>
#include <optional>

namespace koppel {
namespace {


// A finite decimal number, the whole field (a leading '+' allowed); empty otherwise.
std::optional<double> Number(const std::string& field) {
  const char* begin = field.data();
  const char* end = begin + field.size();
  if (begin != end && *begin == '+') ++begin;
  double value = 0;
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error != std::errc() || stop != end || begin == end || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

std::vector<Eigen::Vector2d> ReadPathPoints(const std::string& path) { return ParsePathPoints(ReadInputText(path), path); }

std::vector<Eigen::Vector2d> ParsePathPoints(const std::string& text, const std::string& path) {
  const std::vector<TextLine> lines = SplitLines(text);
  std::vector<Diagnostic> problems;
  auto problem = [&](int line, int column, const std::string& message) { problems.push_back(Diagnostic{path, line, column, "", message}); };
  std::vector<Eigen::Vector2d> points;
  auto blank = [](const std::vector<TextField>& fields) { return fields.size() == 1 && fields[0].text.empty(); };
  std::size_t first = 0;  // the header: the first line that is not blank
  while (first < lines.size() && blank(SplitFields(lines[first].text, ','))) ++first;
  if (first == lines.size()) {
    problem(1, 1, "expected the header x,y, found nothing");
    throw InputError(problems);
  }
  const std::vector<TextField> header = SplitFields(lines[first].text, ',');
  if (header.size() != 2 || header[0].text != "x" || header[1].text != "y") problem(lines[first].number, 1, "expected the header x,y");
  for (std::size_t i = first + 1; i < lines.size() && problems.size() <= kMaxReportedProblems; ++i) {
    const std::vector<TextField> fields = SplitFields(lines[i].text, ',');
    if (blank(fields)) continue;
    if (fields.size() != 2) {
      problem(lines[i].number, 1, "expected two finite numbers x,y, found " + std::to_string(fields.size()) + " fields in '" + lines[i].text +
                                      "' (a decimal comma? write 2.6)");
      continue;
    }
    const std::optional<double> x = Number(fields[0].text), y = Number(fields[1].text);
    if (!x || !y) {
      const TextField& bad = x ? fields[1] : fields[0];
      problem(lines[i].number, bad.column, "expected a finite number, found '" + bad.text + "'");
      continue;
    }
    points.emplace_back(*x, *y);
  }
  if (!problems.empty()) throw InputError(problems);
  return points;
}

}  // namespace koppel
