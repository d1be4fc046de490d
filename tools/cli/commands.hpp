// One function per koppel subcommand; each lives in its own <name>_command.cpp.
#pragma once

#include <CLI/CLI.hpp>

namespace koppel::cli {

void AddAnalyzeCommand(CLI::App& app);
void AddCatalogCommand(CLI::App& app);

}  // namespace koppel::cli
