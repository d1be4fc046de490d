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

// A bound, from the characters alone, on how deep the maps and lists of `text` can nest: where it
// is within kMaxYamlDepth, ParseYamlText does not parse the text a first time to count the depth
// (that pass was a quarter of `koppel analyze`'s start-up on a catalog entry; issue 25). Block
// collections nest at strictly growing columns, except a list that is a map's value, which may
// start at the map's column: at most two per column, and a block collection starts on its line
// no later than the first character that is not a space, tab, '-', '?' or ':' (p). Flow
// collections hold no block ones and each opens with its own '[' or '{'. So the depth is at most
// 2 (max p + 1) + 2 (a map after an anchor or tag on its line, "- &x a: 1", starts after p)
// + the number of '[' and '{' in the text, wherever they stand.
int YamlNestingBound(const std::string& text);

}  // namespace koppel
