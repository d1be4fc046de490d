// Reading an input file of the catalog's formats (a mechanism, a fit problem, a spec, poses,
// points, a motor curve) through the one file reader (koppel/core/input_file.hpp: at most
// kMaxInputBytes, registered as an input of the run), its problems as InputError; and a YAML text
// parsed only after its nesting depth was found within kMaxYamlDepth. Private to the catalog.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace koppel {

// The whole file. Throws InputError ("cannot open", "is a directory", larger than the limit, an
// output of this run).
std::string ReadInputText(const std::string& path);

// The first YAML document of `text`. Throws InputError with file:line:column for a syntax error
// or a nesting deeper than kMaxYamlDepth.
YAML::Node ParseYamlText(const std::string& text, const std::string& file_name);

}  // namespace koppel
