#include "design_units.hpp"

#include "koppel/catalog/length_units.hpp"

namespace koppel {

std::optional<Loads> UnitsOf(const std::string& units) {
  if (units.empty()) return std::nullopt;
  return UnitOnlyLoads(units, "units");
}

void LabelLengths(const std::optional<Loads>& units, std::vector<DesignFigure>& figures) {
  if (!units) return;
  for (DesignFigure& f : figures)
    if (f.unit == "length") f.unit = units->LengthUnit();
}

}  // namespace koppel
