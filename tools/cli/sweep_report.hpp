// What every sweeping command (analyze, curve, deadcentres, proportional, range) tells about the
// walk along the drive: the --at-branch-point flag, the singular points met, the flagged rows,
// the gaps of the requested range, as stderr lines and as JSON.
#pragma once

#include "koppel/api/model.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace koppel::cli {

// Adds --at-branch-point continue|stop|switch to a command; `value` receives the text.
void AddBranchPointOption(CLI::App* command, std::string& value);
// The action named by the flag's text. Exit{2} with the choices otherwise.
AtBranchPoint ParseBranchPointFlag(const std::string& text);

// An input value for people, `shown` in the model's units: "phi = 180 deg" for an R drive, a
// length for a P drive.
std::string FormatInput(const Model& model, double shown);

// Prints on stderr, prefixed by the file: the notes, every singular point (input, kind, joints,
// reciprocal condition, what the sweep did), the rows flagged singular, and the gaps.
void ReportSweep(const std::string& file, const Model& model, const SweepRecord& sweep);
void ReportSingularPoints(const std::string& file, const Model& model, const std::vector<SingularPosition>& points);

// The same as JSON: {"singular_points": [...], "gaps": [...], "notes": [...], "reached": {...}},
// inputs in the model's units (deg or length).
nlohmann::json SweepEventsJson(const SweepRecord& sweep);
nlohmann::json SingularPointsJson(const std::vector<SingularPosition>& points);

}  // namespace koppel::cli
