// What the page's module leaves out, said where a call would need it: muparser (formulas are
// evaluated by the page, editor.js), yaml-cpp (the page holds the mechanism as JSON; no file text
// to edit) and SuiteSparse's BTF. The API's Model refers to them; in the page no call reaches them.
#include "koppel/catalog/document_edit.hpp"
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/catalog/mechanism_source.hpp"
#include "koppel/core/expression.hpp"

#include <stdexcept>

namespace koppel {

namespace {
[[noreturn]] void Absent(const std::string& what) {
  throw InputError({Diagnostic{"editor page", 0, 0, "", what + " is not part of the page's module"}});
}
}  // namespace

// The parameter set's values are core/src/parameter_set.cpp's; evaluating a formula is the page's.
Expected<double> ParameterSet::Evaluate(const std::string&) const {
  return Expected<double>::Error("formulas are evaluated by the page, not by its module");
}

MechanismSource MechanismSource::Read(const std::string&) { Absent("reading a mechanism file"); }
MechanismSource MechanismSource::Parse(const std::string&, const std::string&) { Absent("reading YAML"); }
MechanismFile MechanismSource::Evaluate(const Overrides&) const { Absent("evaluating a mechanism file"); }
MechanismFile ReadMechanismFile(const std::string&, const Overrides&) { Absent("reading a mechanism file"); }
// the page's models are made from its JSON: they have no file text to edit (Model::ToYaml)
std::string EditMechanismText(const std::string&, const std::string&, const DocumentChanges&) { Absent("editing a mechanism file"); }

}  // namespace koppel

// SuiteSparse's BTF orders the Jacobian into blocks (solver/kernel/src/block_lu.cpp). Without it,
// no column is matched: BlockLU::Analyse declines, and every Newton step takes the dense path
// (NewtonOptions::dense), the kernel's reference path.
extern "C" int btf_order(int n, int*, int*, double, double*, int*, int*, int*, int* matched, int*) {
  *matched = 0;
  (void)n;
  return 0;
}
