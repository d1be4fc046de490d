#include "koppel/api/design_file.hpp"

#include "koppel/catalog/design_space_file.hpp"
#include "koppel/catalog/length_units.hpp"

namespace koppel {

DesignSpace ReadDesignFile(const std::string& path) { return ReadDesignSpace(path); }

void CheckLengthUnit(const std::string& unit, const std::string& field) { UnitOnlyLoads(unit, field); }

}  // namespace koppel
