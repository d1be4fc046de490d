// What every koppel command shares: loading a mechanism file with --set overrides, numbers
// given as formulas on the command line, atomic output files, CSV/JSON tables and exit codes
// (0 ok, 1 a check or solve failed, 2 bad input; diagnostics always on stderr).
#pragma once

#include "koppel/catalog/mechanism_file.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace koppel::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;
inline constexpr int kExitBadInput = 2;

// Thrown by a command to end the program with `code`, after it printed its diagnostics.
struct Exit {
  int code;
};

// Reads a mechanism file; `sets` are "NAME=VALUE" overrides. Bad input: diagnostics on stderr,
// then Exit{2}.
MechanismFile LoadMechanism(const std::string& path, const std::vector<std::string>& sets);

// A number given on the command line as a formula ("5/6", "2*sqrt(3)"). Exit{2} on error.
double ParseNumberFlag(const std::string& flag, const std::string& text);

// Writes `text` to `path` atomically (a temporary file beside it, then rename), or to stdout
// when path is empty or "-". Exit{2} when the file cannot be written.
void WriteOutput(const std::string& path, const std::string& text);

// %.12g: enough digits for a paper, short enough for a spreadsheet. Refuses non-finite numbers
// (a bug upstream, never silently printed).
std::string FormatNumber(double value);

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  std::string ToCsv() const;
  nlohmann::json ToJson() const;  // {"columns": [...], "rows": [[...], ...]}
};

// Prints "koppel: message" on stderr.
void Complain(const std::string& message);

// A point of the mechanism named on the command line: a point output (`K`), `link.point`, or a
// point name that only one link has. Exit{2} with the candidates otherwise.
PointRef ResolvePoint(const Mechanism& mechanism, const std::string& text);

// A scalar output by name; empty: the first scalar output. Exit{2} otherwise.
int ResolveScalarOutput(const Mechanism& mechanism, const std::string& name);

// A one-column-of-names table for summaries: quantity, value, unit.
struct Summary {
  std::vector<std::string> quantity, unit;
  std::vector<double> value;
  void Add(const std::string& q, double v, const std::string& u) {
    quantity.push_back(q);
    value.push_back(v);
    unit.push_back(u);
  }
  std::string ToCsv() const;
  nlohmann::json ToJson() const;  // {"quantity": {"value": v, "unit": u}, ...}
};

// Validates --format: "csv" or "json". Exit{2} otherwise.
void CheckFormat(const std::string& format);

}  // namespace koppel::cli
