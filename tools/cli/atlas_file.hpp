// Reading an atlas file for the CLI (atlas build/merge, synth path): its size checked against
// the header before anything else is read. Bad file: the reason on stderr, then Exit{2}.
#pragma once

#include "koppel/synthesis/atlas.hpp"

#include <string>
#include <vector>

namespace koppel::cli {

std::vector<AtlasEntry> ReadAtlasFile(const std::string& path);

}  // namespace koppel::cli
