// The plain values of a ParameterSet (expression.hpp): apart from expression.cpp, which evaluates
// formulas with muparser, so that the editor page's WebAssembly module (tools/edit), which has no
// muparser, keeps the same set of values.
#include "koppel/core/expression.hpp"

#include <cctype>
#include <cmath>

namespace koppel {

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

bool ParameterSet::Has(const std::string& name) const { return index_.count(name) > 0; }

double ParameterSet::Value(const std::string& name) const {
  const auto it = index_.find(name);
  return it == index_.end() ? std::nan("") : values_[it->second].second;
}

void ParameterSet::DefineValue(const std::string& name, double value) {
  const auto [it, added] = index_.emplace(name, values_.size());
  if (added) {
    values_.emplace_back(name, value);
  } else {
    values_[it->second].second = value;
  }
}

}  // namespace koppel
