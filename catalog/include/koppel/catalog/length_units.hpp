// The length units a mechanism file (`units: {length: mm}`) or a flag (`--units mm`) may name.
#pragma once

#include "koppel/core/loads.hpp"

#include <string>
#include <utility>
#include <vector>

namespace koppel {

// Each named unit with its length in metres: m, dm, cm, mm, um, km, in, ft.
const std::vector<std::pair<std::string, double>>& NamedLengthUnits();

// "m, dm, cm, mm, um, km, in, ft": the names, for messages.
std::string NamedLengthUnitList();

// Loads that carry only the unit `name` (no gravity, masses or loads): what a mechanism designed
// from no file is written with when the user names its unit. InputError naming `flag` and listing
// the known units for a name that is none of them.
Loads UnitOnlyLoads(const std::string& name, const std::string& flag);

}  // namespace koppel
