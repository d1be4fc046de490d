#include "koppel/core/expression.hpp"
#include "koppel/core/angles.hpp"

#include "koppel/core/limits.hpp"

#include "formula_commas.hpp"
#include "formula_parser.hpp"

#include <atomic>
#include <cctype>
#include <charconv>
#include <cfloat>
#include <cmath>

namespace koppel {
namespace {
constexpr double kPiValue = kPi;

std::atomic<long long> parameter_reads{0};

// Thrown by the variable factory for a name that is not a parameter.
struct UnknownName {
  std::string name;
};

// One parser per thread, built once (its built-in functions and constants cost more than a
// formula); each formula binds only its own names and unbinds them afterwards.
detail::FormulaParser& SharedParser() {
  thread_local std::unique_ptr<detail::FormulaParser> parser = [] {
    std::unique_ptr<detail::FormulaParser> p = detail::NewFormulaParser();
    p->DefineConst("pi", kPiValue);
    p->DefineConst("deg", kPiValue / 180.0);
    return p;
  }();
  return *parser;
}

// A plain decimal number: an optional '-', digits, optionally '.' and digits, optionally an
// exponent; nothing else (no spaces, no '+', no ".5" or "2."). Its value as muparser gives it:
// the nearest double, as std::from_chars gives it; a leading '-' is muparser's sign change,
// exact (expression_test.cpp checks both bit for bit). nullopt for anything else, and for what
// overflows or lands among the subnormals (muparser decides those).
std::optional<double> PlainNumber(const std::string& text) {
  size_t i = text.empty() || text[0] != '-' ? 0 : 1;
  const auto digits = [&] {
    const size_t start = i;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
    return i > start;
  };
  if (!digits()) return std::nullopt;
  if (i < text.size() && text[i] == '.' && (++i, !digits())) return std::nullopt;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (!digits()) return std::nullopt;
  }
  if (i != text.size()) return std::nullopt;
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  if (value != 0 && std::abs(value) < DBL_MIN) return std::nullopt;
  return value;
}

// A bare name, optionally negated ("d", "-e"): a letter then letters, digits, '_' — not a name
// muparser would read as its own constant (pi, deg, and _pi, _e, which begin with '_').
bool PlainName(const std::string& text, size_t start) {
  if (start >= text.size() || !std::isalpha(static_cast<unsigned char>(text[start]))) return false;
  for (size_t i = start; i < text.size(); ++i) {
    if (!(std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_')) return false;
  }
  return text.compare(start, std::string::npos, "pi") != 0 && text.compare(start, std::string::npos, "deg") != 0;
}

}  // namespace

// A number or a parameter's name alone, without muparser: most of a mechanism file's values are
// one or the other ("a: 1", "[d, 0]"), and muparser is a module loaded by its first formula
// (formula_parser.hpp), with libgomp, about a millisecond of `koppel analyze`'s start-up (issue
// 25). The value is muparser's own, bit for bit (tests/core/expression_test.cpp compares them);
// anything else, or a name with no finite value, goes to muparser for its value or its message.
std::optional<double> ParameterSet::PlainValue(const std::string& formula) const {
  if (std::optional<double> number = PlainNumber(formula)) return number;
  const size_t start = !formula.empty() && formula[0] == '-' ? 1 : 0;
  if (!PlainName(formula, start)) return std::nullopt;
  const auto it = index_.find(start ? formula.substr(1) : formula);
  if (it == index_.end() || !std::isfinite(values_[it->second].second)) return std::nullopt;
  parameter_reads.fetch_add(1, std::memory_order_relaxed);
  const double value = values_[it->second].second;
  return start ? -value : value;
}

// muparser asks for each name a formula uses, once per formula: the cost of a formula is its
// own length, never the number of parameters defined before it.
double* ParameterSet::BindName(const char* name, void* data) {
  auto* set = static_cast<ParameterSet*>(data);
  const auto it = set->index_.find(name);
  if (it == set->index_.end()) throw UnknownName{name};
  parameter_reads.fetch_add(1, std::memory_order_relaxed);
  return &set->values_[it->second].second;
}

long long ParameterSet::ParameterReads() { return parameter_reads.load(std::memory_order_relaxed); }

Expected<double> ParameterSet::Evaluate(const std::string& formula) const {
  if (formula.size() > kMaxFormulaLength) {
    return Expected<double>::Error("formula of " + std::to_string(formula.size()) +
                                   " characters is longer than the limit of " + std::to_string(kMaxFormulaLength) +
                                   " (kMaxFormulaLength)");
  }
  if (const std::optional<double> plain = PlainValue(formula)) return *plain;
  detail::FormulaParser& parser = SharedParser();
  // muparser only reads through the bound addresses
  parser.SetVarFactory(BindName, const_cast<ParameterSet*>(this));
  Expected<double> result = Expected<double>::Error("formula '" + formula + "' does not give a finite number");
  try {
    parser.SetExpr(formula);
    const double value = parser.Eval();
    // "2,6" gives two results, the last returned: one value or none (formula_commas.hpp)
    if (parser.GetNumResults() > 1) {
      result = Expected<double>::Error(detail::CommaOperatorError(formula, detail::TopLevelComma(formula)));
    } else if (std::isfinite(value)) {
      result = value;
    }
  } catch (const UnknownName& unknown) {
    result = Expected<double>::Error("formula '" + formula + "' does not parse: unknown name '" + unknown.name + "'");
  } catch (const detail::FormulaParseError& e) {
    std::string msg = e.message;
    if (e.unknown_name && !e.token.empty()) msg = "unknown name '" + e.token + "'";
    result = Expected<double>::Error("formula '" + formula + "' does not parse: " + msg + detail::DecimalCommaHint(formula));
  }
  // the bound addresses belong to this set: never leave them in the shared parser
  parser.ClearVar();
  parser.SetVarFactory(nullptr, nullptr);
  return result;
}

Expected<std::vector<double>> ParameterSet::EvaluateList(const std::string& text, size_t count, const std::string& form) const {
  const std::vector<std::string> items = detail::SplitAtTopLevelCommas(text);
  if (items.size() != count) {
    std::string why = "expected " + std::to_string(count) + " values " + form + ", found " + std::to_string(items.size()) + " in '" + text + "'";
    if (items.size() > count) why += " (a decimal comma? write a decimal point: 2.6, not 2,6)";
    return Expected<std::vector<double>>::Error(why);
  }
  std::vector<double> values;
  for (const std::string& item : items) {
    const Expected<double> value = Evaluate(item);
    if (!value) return Expected<std::vector<double>>::Error(value.error());
    values.push_back(*value);
  }
  return values;
}

Expected<double> ParameterSet::Define(const std::string& name, const std::string& formula) {
  Expected<double> value = Evaluate(formula);
  if (value) DefineValue(name, *value);
  return value;
}

}  // namespace koppel
