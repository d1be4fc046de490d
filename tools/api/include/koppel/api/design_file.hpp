// What a synthesis command reads besides its targets: the design space an engineer states in a
// design file (--design FILE.yaml; its keys: koppel/catalog/design_space_file.hpp and
// docs/synthesis.md), and the length unit the mechanisms it writes carry. The shells (the CLI, the
// Python module) read both here, so the file's rules are the catalog reader's, written once.
#pragma once

#include "koppel/synthesis/design_space.hpp"

#include <string>

namespace koppel {

// The design space of `path`. InputError with file:line:column for a key koppel does not know, a
// contradiction (an empty interval, a ratio below 1) or a number that is not finite.
DesignSpace ReadDesignFile(const std::string& path);

// Nothing when `unit` names a length unit koppel knows (m, dm, cm, mm, um, km, in, ft); InputError
// naming `field` and listing them otherwise.
void CheckLengthUnit(const std::string& unit, const std::string& field);

}  // namespace koppel
