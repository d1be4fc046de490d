// The flags that `koppel export` and `koppel animate` share: the points traced (--trace), the
// plate width and pin diameter (--plate, --pin), read into the picture library's CycleOptions
// with the file's sweep (the range where a drive meets no limit).
#pragma once

#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/plot/cycle.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace koppel::cli {

struct CycleFlags {
  std::vector<std::string> trace;
  std::string plate, pin;
};

// Adds --trace, --plate and --pin to `command`.
void AddCycleFlags(CLI::App* command, CycleFlags& flags);

// The options of the flags: the named points (default: the file's point outputs), the sizes
// (default: plot::DefaultPartSizes). Exit{2} for an unknown point or sizes that are not valid.
plot::CycleOptions ReadCycleFlags(const MechanismFile& file, const CycleFlags& flags);

}  // namespace koppel::cli
