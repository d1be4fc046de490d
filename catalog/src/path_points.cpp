#include "koppel/catalog/path_points.hpp"

#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/core/angles.hpp"
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

TimedPathPoints ReadTimedPathPoints(const std::string& path) { return ParseTimedPathPoints(ReadInputText(path), path); }

TimedPathPoints ParseTimedPathPoints(const std::string& text, const std::string& path) {
  const std::vector<TextLine> lines = SplitLines(text);
  std::vector<Diagnostic> problems;
  auto problem = [&](int line, int column, const std::string& message) { problems.push_back(Diagnostic{path, line, column, "", message}); };
  TimedPathPoints out;
  auto blank = [](const std::vector<TextField>& fields) { return fields.size() == 1 && fields[0].text.empty(); };
  std::size_t first = 0;  // the header: the first line that is not blank
  while (first < lines.size() && blank(SplitFields(lines[first].text, ','))) ++first;
  if (first == lines.size()) {
    problem(1, 1, "expected the header x,y (or x,y,phi), found nothing");
    throw InputError(problems);
  }
  const std::vector<TextField> header = SplitFields(lines[first].text, ',');
  const bool timed = header.size() == 3 && header[2].text == "phi";
  if ((header.size() != 2 && !timed) || header[0].text != "x" || header[1].text != "y")
    problem(lines[first].number, 1, "expected the header x,y (or x,y,phi: each point's crank angle in degrees)");
  const std::size_t width = timed ? 3 : 2;
  int previous_line = 0;
  for (std::size_t i = first + 1; i < lines.size() && problems.size() <= kMaxReportedProblems; ++i) {
    const std::vector<TextField> fields = SplitFields(lines[i].text, ',');
    if (blank(fields)) continue;
    if (fields.size() != width) {
      problem(lines[i].number, 1, "expected " + std::string(timed ? "three finite numbers x,y,phi" : "two finite numbers x,y") + ", found " +
                                      std::to_string(fields.size()) + " fields in '" + lines[i].text + "' (a decimal comma? write 2.6)");
      continue;
    }
    std::optional<double> values[3];
    bool ok = true;
    for (std::size_t f = 0; f < width && ok; ++f) {
      values[f] = Number(fields[f].text);
      if (!values[f]) {
        problem(lines[i].number, fields[f].column, "expected a finite number, found '" + fields[f].text + "'");
        ok = false;
      }
    }
    if (!ok) continue;
    if (timed) {
      const double phi = DegToRad(*values[2]);
      // each point's crank angle reached once, in order: rising (or falling) from line to line
      if (out.phi.size() >= 1) {
        const double step = phi - out.phi.back();
        const double sense = out.phi.size() >= 2 ? (out.phi[1] > out.phi[0] ? 1 : -1) : (step >= 0 ? 1 : -1);
        if (!(sense * step > 0))
          problem(lines[i].number, fields[2].column,
                  "phi: " + fields[2].text + " deg " + (step == 0 ? "repeats" : "turns back from") + " the angle of line " +
                      std::to_string(previous_line) + "; the crank angles must rise (or fall) from point to point");
      }
      out.phi.push_back(phi);
    }
    previous_line = lines[i].number;
    out.points.emplace_back(*values[0], *values[1]);
  }
  if (!problems.empty()) throw InputError(problems);
  return out;
}

}  // namespace koppel
