// Writes a Mechanism as a mechanism file that ReadMechanismFile reads back to the same model
// (numbers with 17 significant digits; angles in degrees as the format wants).
#pragma once

#include "koppel/catalog/mechanism_file.hpp"

#include <string>

namespace koppel {

// `comment` goes on top as '#' lines; `parameters` (name, value) are written as the file's
// parameters (informational: the geometry is written as numbers). `loads`, when given, adds the
// masses, units, gravity and loads (formulas written as they are: they may name the parameters).
std::string WriteMechanismYaml(const Mechanism& mechanism, const std::string& comment, const SweepDefaults& sweep,
                               const std::vector<std::pair<std::string, double>>& parameters = {},
                               const Loads* loads = nullptr);

}  // namespace koppel
