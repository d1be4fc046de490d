#include "koppel/core/formula.hpp"

#include "koppel/core/angles.hpp"

#include "formula_commas.hpp"
#include "formula_parser.hpp"

#include <cmath>
#include <limits>
#include <map>

namespace koppel {

struct CompiledFormula::Impl {
  std::unique_ptr<detail::FormulaParser> parser = detail::NewFormulaParser();
  // muparser binds variables by address: the constants and the variables live here, at fixed
  // addresses for the formula's lifetime (the Impl never moves, only its owner's pointer does).
  std::vector<double> constants;
  std::vector<double> variables;
};

CompiledFormula::CompiledFormula() = default;
CompiledFormula::~CompiledFormula() = default;
CompiledFormula::CompiledFormula(CompiledFormula&&) noexcept = default;
CompiledFormula& CompiledFormula::operator=(CompiledFormula&&) noexcept = default;

Expected<CompiledFormula> CompiledFormula::Compile(const std::string& formula, const ParameterSet& parameters,
                                                   const std::vector<std::string>& variables) {
  auto impl = std::make_unique<Impl>();
  impl->constants.reserve(parameters.Values().size());
  impl->variables.assign(variables.size(), 0.0);
  // the address each name ends up bound to: variables shadow parameters, later variables earlier ones
  std::map<std::string, double*> bound;
  for (const auto& [name, value] : parameters.Values()) {
    impl->constants.push_back(value);
    bound[name] = &impl->constants.back();
  }
  for (size_t i = 0; i < variables.size(); ++i) bound[variables[i]] = &impl->variables[i];
  try {
    impl->parser->DefineConst("pi", kPi);
    impl->parser->DefineConst("deg", kPi / 180.0);
    for (const auto& [name, address] : bound) impl->parser->DefineVar(name, address);
    impl->parser->SetExpr(formula);
    impl->parser->Eval();  // parses now, so that an unknown name is a compile error
    // "2,6" gives two results, the last returned: one value or none (formula_commas.hpp)
    if (impl->parser->GetNumResults() > 1)
      return Expected<CompiledFormula>::Error(detail::CommaOperatorError(formula, detail::TopLevelComma(formula)));
  } catch (const detail::FormulaParseError& e) {
    std::string message = e.message;
    if (e.unknown_name && !e.token.empty()) message = "unknown name '" + e.token + "'";
    return Expected<CompiledFormula>::Error("formula '" + formula + "' does not parse: " + message + detail::DecimalCommaHint(formula));
  }
  CompiledFormula compiled;
  compiled.impl_ = std::move(impl);
  compiled.text_ = formula;
  return compiled;
}

double CompiledFormula::Evaluate(const double* values) const {
  std::copy(values, values + impl_->variables.size(), impl_->variables.begin());
  try {
    const double value = impl_->parser->Eval();
    return std::isfinite(value) ? value : std::numeric_limits<double>::quiet_NaN();
  } catch (const detail::FormulaParseError&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace koppel
