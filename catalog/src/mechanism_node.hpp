// ParseMechanismText on YAML already parsed: the fit's builder parses its mechanism once and
// reads a copy of the tree for every set of parameter values (yaml-cpp stays private to the
// catalog's sources).
#pragma once

#include "koppel/catalog/mechanism_file.hpp"

#include <yaml-cpp/yaml.h>

#include <string>

namespace koppel {

MechanismFile ParseMechanismNode(const YAML::Node& root, const std::string& file_name, const Overrides& overrides,
                                 CardReading card = CardReading::kRead);

// The text of the mechanism file `name`, or of the catalog entry when `name` is no file but a
// catalog id; `resolved` receives the path read. InputError naming both when it is neither.
std::string ReadMechanismFileText(const std::string& name, std::string* resolved);

}  // namespace koppel
