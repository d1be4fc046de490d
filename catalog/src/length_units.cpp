#include "koppel/catalog/length_units.hpp"

#include "koppel/core/diagnostic.hpp"

namespace koppel {

const std::vector<std::pair<std::string, double>>& NamedLengthUnits() {
  static const std::vector<std::pair<std::string, double>> units = {{"m", 1.0},     {"dm", 0.1},    {"cm", 0.01},
                                                                    {"mm", 0.001},  {"um", 1e-6},   {"km", 1000.0},
                                                                    {"in", 0.0254}, {"ft", 0.3048}};
  return units;
}

std::string NamedLengthUnitList() {
  std::string list;
  for (const auto& [name, metres] : NamedLengthUnits()) list += (list.empty() ? "" : ", ") + name;
  return list;
}

Loads UnitOnlyLoads(const std::string& name, const std::string& flag) {
  for (const auto& [known, metres] : NamedLengthUnits()) {
    if (known != name) continue;
    Loads loads;
    loads.metres_per_unit = metres;
    loads.length_unit_given = true;
    loads.length_unit_name = known;
    return loads;
  }
  throw InputError({Diagnostic{flag, 0, 0, "", "unknown length unit '" + name + "' (the units known: " + NamedLengthUnitList() + ")"}});
}

}  // namespace koppel
