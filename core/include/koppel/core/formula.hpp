// A formula compiled once over named variables and evaluated many times: the magnitude of a load
// along a sweep or a simulation (expression.hpp's ParameterSet parses a formula per evaluation,
// which suits the few parameters of a file, not a formula per integration step).
#pragma once

#include "koppel/core/expression.hpp"

#include <memory>
#include <string>
#include <vector>

namespace koppel {

class CompiledFormula {
 public:
  CompiledFormula();
  ~CompiledFormula();
  CompiledFormula(CompiledFormula&&) noexcept;
  CompiledFormula& operator=(CompiledFormula&&) noexcept;

  // Compiles `formula` over the constants of `parameters` and the variables `variables` (later
  // names shadow earlier ones and the parameters). The error says why when it does not parse or
  // names something unknown; a non-finite value at some point is not a compile error.
  static Expected<CompiledFormula> Compile(const std::string& formula, const ParameterSet& parameters,
                                           const std::vector<std::string>& variables);

  // The value for `values` (one per variable of Compile, in its order); NaN when the formula
  // has no finite value there (the caller reports it). Precondition: made by Compile.
  double Evaluate(const double* values) const;

  const std::string& text() const { return text_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string text_;
};

}  // namespace koppel
