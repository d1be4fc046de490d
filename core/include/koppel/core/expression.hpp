// Parameters given as formulas (muparser syntax: + - * / ^, sqrt, sin, cos, tan, asin, acos,
// atan, atan2, exp, log, abs, min, max ...), each able to name the parameters defined before it.
// Trigonometric functions work in radians; the constants `pi` and `deg` (= pi/180) are defined,
// so `30*deg` is thirty degrees in radians.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace koppel {

class ParameterSet {
 public:
  ParameterSet();
  ~ParameterSet();
  ParameterSet(const ParameterSet& other);
  ParameterSet& operator=(const ParameterSet& other);

  // Evaluates `formula` with the parameters defined so far and defines `name` with its value.
  // Redefining a name replaces its value. On failure returns false and sets *error.
  bool Define(const std::string& name, const std::string& formula, std::string* error);

  // Evaluates a formula over the defined parameters. nullopt and *error on a parse error, an
  // unknown name or a non-finite result.
  std::optional<double> Evaluate(const std::string& formula, std::string* error) const;

  // Defines `name` with an exact value (no formula round trip), e.g. the input of a sample.
  void DefineValue(const std::string& name, double value);

  bool Has(const std::string& name) const;
  double Value(const std::string& name) const;  // precondition: Has(name)
  const std::vector<std::pair<std::string, double>>& Values() const { return values_; }

  // True when `name` can be a parameter: a letter or '_' then letters, digits, '_'; not pi or deg.
  static bool ValidName(const std::string& name);

 private:
  std::vector<std::pair<std::string, double>> values_;
};

}  // namespace koppel
