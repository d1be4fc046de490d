// The length unit a user names for a design made from no mechanism file (the synthesis commands'
// --units): its file says `units: {length: UNIT}`, its length figures carry the unit's name.
#pragma once

#include "koppel/api/synthesis.hpp"
#include "koppel/core/loads.hpp"

#include <optional>
#include <string>
#include <vector>

namespace koppel {

// The unit as the writer takes it; nullopt for "" (no unit); InputError listing the known units
// for another name (koppel/catalog/length_units.hpp).
std::optional<Loads> UnitsOf(const std::string& units);
// The figures whose unit is "length" labelled with the unit's name.
void LabelLengths(const std::optional<Loads>& units, std::vector<DesignFigure>& figures);
// nullptr or the unit, as WriteMechanismYaml takes it.
inline const Loads* UnitsFor(const std::optional<Loads>& units) { return units ? &*units : nullptr; }

}  // namespace koppel
