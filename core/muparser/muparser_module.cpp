// The module libkoppel_muparser.so (core/src/formula_parser.hpp): muparser behind the
// FormulaParser interface, its errors passed on as FormulaParseError.
#include "formula_parser.hpp"

#include <muParser.h>

namespace koppel::detail {
namespace {

[[noreturn]] void PassOn(const mu::Parser::exception_type& e) {
  throw FormulaParseError{e.GetMsg(), e.GetToken(), e.GetCode() == mu::ecUNASSIGNABLE_TOKEN};
}

class Muparser final : public FormulaParser {
 public:
  void DefineConst(const std::string& name, double value) override {
    try {
      parser_.DefineConst(name, value);
    } catch (const mu::Parser::exception_type& e) {
      PassOn(e);
    }
  }
  void DefineVar(const std::string& name, double* address) override {
    try {
      parser_.DefineVar(name, address);
    } catch (const mu::Parser::exception_type& e) {
      PassOn(e);
    }
  }
  void SetVarFactory(VariableFactory factory, void* data) override { parser_.SetVarFactory(factory, data); }
  void ClearVar() override { parser_.ClearVar(); }
  void SetExpr(const std::string& formula) override {
    try {
      parser_.SetExpr(formula);
    } catch (const mu::Parser::exception_type& e) {
      PassOn(e);
    }
  }
  double Eval() override {
    try {
      return parser_.Eval();
    } catch (const mu::Parser::exception_type& e) {
      PassOn(e);
    }
  }
  int GetNumResults() const override { return parser_.GetNumResults(); }

 private:
  mu::Parser parser_;
};

FormulaParser* Create() { return new Muparser(); }

const MuparserModuleTable kTable{{KOPPEL_MODULE_VERSION}, &Create};

}  // namespace
}  // namespace koppel::detail

extern "C" __attribute__((visibility("default"))) const koppel::ModuleTable* koppel_muparser_module() { return &koppel::detail::kTable; }
