#include "common.hpp"

#include "koppel/core/number_text.hpp"
#include "koppel/core/printable_text.hpp"

#include "koppel/core/expression.hpp"
#include "koppel/koppel.hpp"  // Version

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>

namespace koppel::cli {

// a name from a flag or a caller with ESC or BEL in it is shown escaped, never sent to the terminal
void Complain(const std::string& message) { std::cerr << "koppel: " << PrintableText(message, Replacement::kEscape, "\n") << "\n"; }

void PrintNotes(const std::string& path, const std::vector<std::string>& notes) {
  for (const std::string& note : notes) Complain(path + ": note: " + note);
}

std::optional<double> OptionalNumberFlag(const std::string& flag, const std::string& text) {
  if (text.empty()) return std::nullopt;
  return ParseNumberFlag(flag, text);
}

double ParseNumberFlag(const std::string& flag, const std::string& text) {
  ParameterSet empty;
  const Expected<double> value = empty.Evaluate(text);
  if (!value) {
    Complain(flag + ": " + value.error());
    throw Exit{kExitBadInput};
  }
  return *value;
}

long ParseCountFlag(const std::string& flag, const std::string& text, long lo, long hi) {
  const double v = ParseNumberFlag(flag, text);
  if (!(v >= static_cast<double>(lo) && v <= static_cast<double>(hi)) || v != std::floor(v)) {
    Complain(fmt::format("{}: expected a whole number from {} to {}, found '{}'", flag, lo, hi, text));
    throw Exit{kExitBadInput};
  }
  return static_cast<long>(v);
}

std::vector<double> ParseNumberListFlag(const std::string& flag, const std::string& text, size_t count, const std::string& form) {
  ParameterSet empty;
  const Expected<std::vector<double>> values = empty.EvaluateList(text, count, "'" + form + "'");
  if (!values) {
    Complain(flag + ": " + values.error());
    throw Exit{kExitBadInput};
  }
  return *values;
}

void CheckCount(double count, const std::string& options, const CountLimit& limit) {
  if (count <= limit.value) return;
  Complain(fmt::format("{} ask for {:.3g}, more than the limit of {:.0f} {} ({}, see docs/limits.md); change {}", options, count,
                       limit.value, limit.what, limit.name, options));
  throw Exit{kExitBadInput};
}

void CheckSampleCount(double from, double to, double step, const std::string& options, const CountLimit& limit) {
  if (!std::isfinite(from) || !std::isfinite(to) || !std::isfinite(step) || step == 0.0) {
    Complain(options + ": the range and its step must be finite numbers, the step not 0");
    throw Exit{kExitBadInput};
  }
  CheckCount(std::floor(std::abs(to - from) / std::abs(step)) + 1, options, limit);
  // doubles keep about 16 digits: a step below 1e-9 of the magnitude would not move the input
  if (std::abs(step) < 1e-9 * std::max(std::abs(from), std::abs(to))) {
    Complain(fmt::format("{}: a step of {:g} is lost in the rounding of inputs as large as {:g}", options, std::abs(step),
                         std::max(std::abs(from), std::abs(to))));
    throw Exit{kExitBadInput};
  }
}

std::string JsonText(nlohmann::json j) {
  if (j.is_object()) j["version"] = Version();
  return j.dump(1) + "\n";
}


std::string FormatNumber(double value) {
  std::string text;
  AppendNumber(text, value);
  return text;
}

void AppendNumber(std::string& out, double value) {
  if (!std::isfinite(value)) throw std::logic_error("koppel: refusing to print a non-finite number");
  if (value == 0.0) {  // no "-0"
    out += '0';
    return;
  }
  char buffer[kG12Chars];  // printf's %.12g, written without a temporary string
  out.append(buffer, WriteG12(buffer, value));
}

char* WriteNumber(char* out, double value) {
  if (!std::isfinite(value)) throw std::logic_error("koppel: refusing to print a non-finite number");
  if (value == 0.0) {  // no "-0"
    *out = '0';
    return out + 1;
  }
  return WriteG12(out, value);
}

namespace {

// A decimal number as a spreadsheet reads one: sign, digits with at most one point, exponent.
bool IsDecimalNumber(std::string_view text) {
  size_t i = text.empty() || (text[0] != '+' && text[0] != '-') ? 0 : 1;
  const auto digits = [&] {
    const size_t start = i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
    return i - start;
  };
  size_t mantissa = digits();
  if (i < text.size() && text[i] == '.') ++i, mantissa += digits();
  if (mantissa == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == text.size();
}

}  // namespace

std::string CsvField(std::string_view text) {
  std::string cell = PrintableText(text, Replacement::kReplacementCharacter);
  if (!cell.empty() && std::string_view("=+-@").find(cell[0]) != std::string_view::npos && !IsDecimalNumber(cell)) cell.insert(0, 1, '\'');
  if (cell.find_first_of(",\"\r\n") == std::string::npos) return cell;
  std::string quoted = "\"";
  for (char c : cell) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string CsvLine(const std::vector<std::string>& cells) {
  std::string line;
  for (size_t i = 0; i < cells.size(); ++i) line += (i ? "," : "") + CsvField(cells[i]);
  return line + "\n";
}

std::string Table::ToCsv() const {
  std::string out = CsvLine(columns);
  for (const auto& row : rows) {
    for (size_t i = 0; i < row.size(); ++i) out += (i ? "," : "") + FormatNumber(row[i]);
    out += "\n";
  }
  return out;
}

nlohmann::json Table::ToJson() const {
  nlohmann::json j;
  j["columns"] = columns;
  nlohmann::json rows_json = nlohmann::json::array();
  for (const auto& row : rows) {
    for (double v : row) FormatNumber(v);  // the same refusal of non-finite numbers as CSV
    rows_json.push_back(row);
  }
  j["rows"] = rows_json;
  return j;
}

std::string MixedTable::ToCsv() const {
  std::string out = CsvLine(columns);
  for (const auto& row : rows) {
    for (size_t i = 0; i < row.size(); ++i) {
      if (i) out += ',';
      if (const double* v = std::get_if<double>(&row[i])) AppendNumber(out, *v);
      if (const std::string* w = std::get_if<std::string>(&row[i])) out += CsvField(*w);
    }
    out += "\n";
  }
  return out;
}

nlohmann::json MixedTable::ToJson() const {
  nlohmann::json rows_json = nlohmann::json::array();
  for (const auto& row : rows) {
    nlohmann::json r = nlohmann::json::array();
    for (const Cell& c : row) {
      if (const double* v = std::get_if<double>(&c)) {
        FormatNumber(*v);  // the same refusal of non-finite numbers as CSV
        r.push_back(*v);
      } else if (const std::string* w = std::get_if<std::string>(&c)) {
        r.push_back(*w);
      } else {
        r.push_back(nullptr);
      }
    }
    rows_json.push_back(std::move(r));
  }
  return {{"columns", columns}, {"rows", rows_json}};
}

std::string MixedTable::Text(const std::string& format) const { return format == "json" ? JsonText(ToJson()) : ToCsv(); }

PointRef ResolvePoint(const Mechanism& m, const std::string& text, const std::string& flag) {
  const Expected<PointRef> point = FindPointByText(m, text);
  if (point) return *point;
  Complain(flag + " " + text + ": " + point.error());
  throw Exit{kExitBadInput};
}

int ResolveScalarOutput(const Mechanism& m, const std::string& name, const std::string& flag, const std::string& path) {
  const Expected<int> output = FindScalarOutput(m, name);  // the rule: koppel/core/mechanism.hpp
  if (output) return *output;
  Complain(name.empty() ? path + ": " + output.error() : flag + " " + name + ": " + path + " " + output.error());
  throw Exit{kExitBadInput};
}

std::string Summary::ToCsv() const {
  std::string out = "quantity,value,unit\n";
  for (size_t i = 0; i < quantity.size(); ++i) out += CsvField(quantity[i]) + "," + FormatNumber(value[i]) + "," + CsvField(unit[i]) + "\n";
  return out;
}

nlohmann::json Summary::ToJson() const {
  nlohmann::json j = nlohmann::json::object();
  for (size_t i = 0; i < quantity.size(); ++i) {
    FormatNumber(value[i]);
    j[quantity[i]] = {{"value", value[i]}, {"unit", unit[i]}};
  }
  return j;
}

void CheckFormat(const std::string& format) {
  if (format != "csv" && format != "json") {
    Complain("--format must be csv or json, not '" + format + "'");
    throw Exit{kExitBadInput};
  }
}

}  // namespace koppel::cli
