// What `koppel export` and `koppel animate` share: the points traced (--trace), the plate width
// and pin diameter (--plate, --pin), read into the picture library's CycleOptions with the file's
// sweep (the range where a drive meets no limit); and how their result is written and told.
#pragma once

#include "koppel/api/model.hpp"
#include "koppel/export/export.hpp"
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
// (default: plot::DefaultPartSizes), the file's sweep (plot::CycleOptionsOf). Exit{2} for an
// unknown point or sizes that are not valid.
plot::CycleOptions ReadCycleFlags(const Model& model, const CycleFlags& flags);

// Writes the result's file to `out` (WriteOutput) unless it failed; its message on stderr,
// prefixed by `file`. Exit{1} when it failed (no file) or is partial (the file holds what was
// computed).
void WriteExportResult(const std::string& file, const std::string& out, const plot::ExportResult& result);

}  // namespace koppel::cli
