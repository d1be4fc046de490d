// A mechanism file as a function of some of its parameters: the builder (MechanismBuilder,
// koppel/analysis/sensitivity.hpp) the fit and the tolerance analysis call with parameter values.
#pragma once

#include "koppel/analysis/sensitivity.hpp"
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/catalog/mechanism_source.hpp"

#include <string>
#include <vector>

namespace koppel {

// The mechanism file's text without its catalog card (the card does not make the mechanism and
// is a third to two thirds of a catalog entry). `text` must read without problems.
std::string MechanismTextWithoutCard(const std::string& text, const std::string& file_name);

// Evaluates `source` for every call, with `overrides` and then `names[j]` set to values[j]; a
// parameter whose formula uses a changed one follows it. The text is parsed once; every call
// reads its own deep copy of the tree (which keeps no line numbers: errors are text here), so the
// builder may run on several threads at once. An InputError of the reader becomes the Expected's
// error.
MechanismBuilder ParameterBuilder(const MechanismSource& source, const Overrides& overrides, const std::vector<std::string>& names);
// The same for `text`, a mechanism file named `file_name` in messages.
MechanismBuilder ParameterBuilder(const std::string& text, const std::string& file_name, const Overrides& overrides,
                                  const std::vector<std::string>& names);

}  // namespace koppel
