#include "koppel/core/expression.hpp"
#include "koppel/core/angles.hpp"

#include <muParser.h>

#include <cctype>
#include <cmath>

namespace koppel {
namespace {
constexpr double kPiValue = kPi;
}

ParameterSet::ParameterSet() = default;
ParameterSet::~ParameterSet() = default;
ParameterSet::ParameterSet(const ParameterSet& other) = default;
ParameterSet& ParameterSet::operator=(const ParameterSet& other) = default;

bool ParameterSet::ValidName(const std::string& name) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  for (char c : name) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  }
  return name != "pi" && name != "deg";
}

bool ParameterSet::Has(const std::string& name) const {
  for (const auto& [n, v] : values_) {
    if (n == name) return true;
  }
  return false;
}

double ParameterSet::Value(const std::string& name) const {
  for (const auto& [n, v] : values_) {
    if (n == name) return v;
  }
  return std::nan("");
}

std::optional<double> ParameterSet::Evaluate(const std::string& formula, std::string* error) const {
  // A fresh parser per formula: muparser binds variables by address, and formulas are few.
  mu::Parser parser;
  std::vector<double> storage;
  storage.reserve(values_.size());
  try {
    parser.DefineConst("pi", kPiValue);
    parser.DefineConst("deg", kPiValue / 180.0);
    for (const auto& [n, v] : values_) {
      storage.push_back(v);
      parser.DefineVar(n, &storage.back());
    }
    parser.SetExpr(formula);
    const double value = parser.Eval();
    if (!std::isfinite(value)) {
      if (error) *error = "formula '" + formula + "' does not give a finite number";
      return std::nullopt;
    }
    return value;
  } catch (const mu::Parser::exception_type& e) {
    if (error) {
      std::string msg = e.GetMsg();
      if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN && !e.GetToken().empty())
        msg = "unknown name '" + e.GetToken() + "'";
      *error = "formula '" + formula + "' does not parse: " + msg;
    }
    return std::nullopt;
  }
}

void ParameterSet::DefineValue(const std::string& name, double value) {
  for (auto& [n, v] : values_) {
    if (n == name) {
      v = value;
      return;
    }
  }
  values_.emplace_back(name, value);
}

bool ParameterSet::Define(const std::string& name, const std::string& formula, std::string* error) {
  const std::optional<double> value = Evaluate(formula, error);
  if (!value) return false;
  DefineValue(name, *value);
  return true;
}

}  // namespace koppel
