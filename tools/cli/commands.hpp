// One function per koppel subcommand; each lives in its own <name>_command.cpp.
#pragma once

#include <CLI/CLI.hpp>

namespace koppel::cli {

void AddAnalyzeCommand(CLI::App& app);
void AddCatalogCommand(CLI::App& app);
void AddDeadCentresCommand(CLI::App& app);
void AddCurveCommand(CLI::App& app);
void AddProportionalCommand(CLI::App& app);
void AddCognatesCommand(CLI::App& app);
void AddSynthCommand(CLI::App& app);
void AddRangeCommand(CLI::App& app);
void AddClassifyCommand(CLI::App& app);
void AddFitSubcommand(CLI::App& synth);  // koppel synth fit
void AddMotionSubcommand(CLI::App& synth);    // koppel synth motion
void AddFunctionSubcommand(CLI::App& synth);  // koppel synth function
void AddPathSubcommand(CLI::App& synth);      // koppel synth path
void AddAtlasCommand(CLI::App& app);          // koppel atlas build|merge
void AddPlotCommand(CLI::App& app);  // plot, draw, view: tools/plot
void AddDrawCommand(CLI::App& app);
void AddViewCommand(CLI::App& app);
void AddEditCommand(CLI::App& app);
void AddForcesCommand(CLI::App& app);    // forces_command.cpp
void AddSimulateCommand(CLI::App& app);  // simulate_command.cpp
void AddBenchCommand(CLI::App& app);     // bench_command.cpp, benchmarks in tools/bench
void AddExportCommand(CLI::App& app);    // export_command.cpp: DXF (tools/export)
void AddAnimateCommand(CLI::App& app);   // animate_command.cpp: GIF (tools/export)
void AddCurvatureCommand(CLI::App& app);  // curvature_command.cpp
void AddPolesCommand(CLI::App& app);      // poles_command.cpp
void AddToleranceCommand(CLI::App& app);  // tolerance_command.cpp

}  // namespace koppel::cli
