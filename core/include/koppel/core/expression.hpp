// Parameters given as formulas (muparser syntax: + - * / ^, sqrt, sin, cos, tan, asin, acos,
// atan, atan2, exp, log, abs, min, max ...), each able to name the parameters defined before it.
// Trigonometric functions work in radians; the constants `pi` and `deg` (= pi/180) are defined,
// so `30*deg` is thirty degrees in radians. A formula is one value: a comma outside a function's
// arguments ("2,6", a decimal comma) is refused, never read as muparser's list of results.
#pragma once

#include "koppel/core/expected.hpp"

#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace koppel {

class ParameterSet {
 public:
  ParameterSet();
  ~ParameterSet();
  ParameterSet(const ParameterSet& other);
  ParameterSet& operator=(const ParameterSet& other);

  // Evaluates `formula` with the parameters defined so far and defines `name` with its value
  // (returned). Redefining a name replaces its value. On failure nothing is defined.
  Expected<double> Define(const std::string& name, const std::string& formula);

  // Evaluates a formula over the defined parameters. The error says why there is no value: a
  // parse error ("does not parse" in the text), an unknown name, a non-finite result or a
  // formula longer than kMaxFormulaLength. The cost is that of the formula alone, whatever the
  // number of parameters (names are looked up by hash). Not for concurrent use of the same set
  // from several threads.
  Expected<double> Evaluate(const std::string& formula) const;

  // A list of `count` formulas separated by commas ("X,Y"; commas inside a function's brackets
  // belong to it: "min(1,2),3" is two values), each evaluated as by Evaluate. The error names the
  // count found against `form` (e.g. "X,Y") and hints at a decimal comma when there are too many.
  Expected<std::vector<double>> EvaluateList(const std::string& text, size_t count, const std::string& form) const;

  // Defines `name` with an exact value (no formula round trip), e.g. the input of a sample.
  void DefineValue(const std::string& name, double value);

  bool Has(const std::string& name) const;
  double Value(const std::string& name) const;  // precondition: Has(name)
  const std::vector<std::pair<std::string, double>>& Values() const { return values_; }

  // True when `name` can be a parameter: a letter or '_' then letters, digits, '_'; not pi or deg.
  static bool ValidName(const std::string& name);

  // How many parameter values formulas have read in this process: each formula reads the names
  // it uses, never the whole set. A count of evaluation work for tests.
  static long long ParameterReads();

 private:
  // A formula that is a plain number or a parameter's name (either negated), valued without
  // muparser, as muparser values it; nullopt for any other formula.
  std::optional<double> PlainValue(const std::string& formula) const;
  // muparser's variable factory: the address of a parameter's value for the formula being parsed.
  static double* BindName(const char* name, void* set);

  std::vector<std::pair<std::string, double>> values_;
  std::unordered_map<std::string, size_t> index_;  // name -> position in values_
};

}  // namespace koppel
