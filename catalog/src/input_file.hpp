// Reading an input file (a mechanism, a fit problem) with the limits of koppel/core/limits.hpp:
// at most kMaxInputBytes are read, whatever the file is (a regular file, a pipe, a device such
// as /dev/zero), and a YAML text is parsed only after its nesting depth was found within
// kMaxYamlDepth. Private to the catalog.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace koppel {

// The whole file. Throws InputError ("cannot open", "is a directory", larger than the limit).
std::string ReadInputText(const std::string& path);

// The first YAML document of `text`. Throws InputError with file:line:column for a syntax error
// or a nesting deeper than kMaxYamlDepth.
YAML::Node ParseYamlText(const std::string& text, const std::string& file_name);

}  // namespace koppel
