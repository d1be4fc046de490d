// The formula parser behind ParameterSet::Evaluate and CompiledFormula: muparser, in the module
// libkoppel_muparser.so (core/muparser/muparser_module.cpp) loaded by the first formula
// (koppel/core/module.hpp), so that a program that reads no file (`koppel --version`) does not map
// muparser and the OpenMP runtime it links, libgomp (issue 25). The interface is muparser's own,
// reduced to what expression.cpp and formula.cpp call; its errors come as FormulaParseError.
#pragma once

#include "koppel/core/module.hpp"

#include <memory>
#include <string>

namespace koppel::detail {

// A muparser error (mu::ParserError), as the module passes it on.
struct FormulaParseError {
  std::string message;      // muparser's message
  std::string token;        // the token it names, if any
  bool unknown_name = false;  // muparser's ecUNASSIGNABLE_TOKEN: a name it does not know
};

// muparser's Parser; every call may throw FormulaParseError, or whatever a variable factory throws.
class FormulaParser {
 public:
  // muparser's variable factory: the address a name is bound to, asked once per name and formula
  using VariableFactory = double* (*)(const char* name, void* data);
  virtual ~FormulaParser() = default;
  virtual void DefineConst(const std::string& name, double value) = 0;
  virtual void DefineVar(const std::string& name, double* address) = 0;
  virtual void SetVarFactory(VariableFactory factory, void* data) = 0;
  virtual void ClearVar() = 0;
  virtual void SetExpr(const std::string& formula) = 0;
  virtual double Eval() = 0;
  virtual int GetNumResults() const = 0;
};

struct MuparserModuleTable : ModuleTable {
  FormulaParser* (*create)();  // a new parser, owned by the caller
};

// A new muparser parser: the module is loaded by the first call (std::runtime_error when it
// cannot be).
inline std::unique_ptr<FormulaParser> NewFormulaParser() {
  return std::unique_ptr<FormulaParser>(static_cast<const MuparserModuleTable&>(LoadModule("muparser")).create());
}

}  // namespace koppel::detail
