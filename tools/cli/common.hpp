// What every koppel command shares: loading a mechanism file with --set overrides, numbers
// given as formulas on the command line, atomic output files, CSV/JSON tables and exit codes
// (0 ok, 1 a check or solve failed, 2 bad input; diagnostics always on stderr).
#pragma once

#include "koppel/core/diagnostic.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/core/output_file.hpp"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace CLI {
class Option;
}  // namespace CLI

namespace koppel::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;
inline constexpr int kExitBadInput = 2;

// Thrown by a command to end the program with `code`, after it printed its diagnostics.
struct Exit {
  int code;
};

// A number given on the command line as a formula ("5/6", "2*sqrt(3)"). Exit{2} on error.
double ParseNumberFlag(const std::string& flag, const std::string& text);

// A count (--samples, --threads, --seed, --order): a formula like every number ("1e3", "2^10"),
// whole, from lo to hi. Exit{2} naming the flag, the range and what was given otherwise. Seeds
// go up to 2^53, the whole numbers a formula holds exactly.
long ParseCountFlag(const std::string& flag, const std::string& text, long lo, long hi);
inline constexpr long kMaxSeed = 9'007'199'254'740'992;  // 2^53

// The same for a flag that may be left out: nothing when `text` is empty (the command's default,
// e.g. the file's sweep through Model::Span, applies).
std::optional<double> OptionalNumberFlag(const std::string& flag, const std::string& text);

// `count` numbers separated by commas ("X,Y"), each a formula; `form` names them ("X,Y").
// Exit{2} when the count differs (a decimal comma among them is named) or one does not evaluate.
std::vector<double> ParseNumberListFlag(const std::string& flag, const std::string& text, size_t count, const std::string& form);

// Marks a command-line option as naming an output file (-o FILE, --yaml, --curves) or a
// directory that files are written into (-o DIR); returns it. Once the command line is parsed,
// before a command reads any input or begins its work, main() claims every target given
// (ClaimOutputs): koppel/core/output_file.hpp says what is refused (exit 2).
CLI::Option* OutputFile(CLI::Option* option);
CLI::Option* OutputDirectory(CLI::Option* option);
void ClaimOutputs();

// Writes `text` to `path` atomically (io::WriteFileAtomically: io::FileError, which main() turns
// into exit 2 for a refused target and 1 for a failed write), or to stdout when path is empty or
// "-" (Exit{1} when stdout is closed or full).
void WriteOutput(const std::string& path, const std::string& text);
// The same text written as it is made, for outputs of tens of megabytes (analyze): append to
// text() and call Flush() now and then; to a file, every megabyte goes to the temporary file of
// an io::AtomicFileWriter (the target is replaced at Finish(), or left as it was when an
// exception ends the command first), so the whole text is never held and each piece is copied
// while it is still in the cache. To stdout the text is held and written at Finish(), as
// WriteOutput does, so that a failure half-way prints nothing.
class StreamedOutput {
 public:
  explicit StreamedOutput(const std::string& path);
  ~StreamedOutput();
  std::string& text() { return text_; }
  void Flush() {
    if (file_ && text_.size() >= kPiece) WritePiece();
  }
  void Finish();

 private:
  static constexpr size_t kPiece = size_t{1} << 20;  // bytes: fits the cache, few system calls
  void WritePiece();
  std::string path_, text_;
  std::unique_ptr<io::AtomicFileWriter> file_;
};
// Makes the directory of -o DIR and its missing parents (io::MakeOutputDirectory).
void MakeOutputDirectory(const std::string& path);

// Flushes and closes stdout at the end of a run; a failed write that was not yet reported is
// reported and turns exit code 0 into 1. Returns the exit code to use.
int FinishStandardOutput(int code);

// The JSON text of an output: `j` with a "version" field (koppel's version, when j is an
// object), indented, with a final newline.
std::string JsonText(nlohmann::json j);

// A limit on how many samples or cells a command may ask for (koppel/core/limits.hpp).
struct CountLimit {
  double value;
  const char* name;  // the constant, e.g. "kMaxSweepSamples"
  const char* what;  // "samples per sweep"
};
inline constexpr CountLimit kSweepSamples{static_cast<double>(kMaxSweepSamples), "kMaxSweepSamples", "samples per sweep"};
inline constexpr CountLimit kStraightSearchSamples{static_cast<double>(kMaxStraightSearchSamples), "kMaxStraightSearchSamples",
                                                   "samples per straight-line search"};
inline constexpr CountLimit kMotionFourBars{static_cast<double>(kMaxMotionFourBars), "kMaxMotionFourBars", "four-bars per motion synthesis"};
inline constexpr CountLimit kToleranceValues{static_cast<double>(kMaxToleranceValues), "kMaxToleranceValues",
                                             "Monte Carlo values (samples x inputs)"};
inline constexpr CountLimit kChartCells{static_cast<double>(kMaxChartCells), "kMaxChartCells", "cells per chart"};

// The one sample-count check of every sweeping command, before anything is allocated: a range
// from..to by step (any one unit) must be finite, its step non-zero and not lost in the
// rounding of from/to, and its count (counted in double, so no step overflows) within `limit`.
// Exit{2} naming the limit and `options`, the flags that change the count.
void CheckSampleCount(double from, double to, double step, const std::string& options, const CountLimit& limit = kSweepSamples);
// The same for a count already known (e.g. the cells of a chart).
void CheckCount(double count, const std::string& options, const CountLimit& limit);

// %.12g: enough digits for a paper, short enough for a spreadsheet. Refuses non-finite numbers
// (a bug upstream, never silently printed).
std::string FormatNumber(double value);
// The same appended to `out`.
void AppendNumber(std::string& out, double value);
// The same written at `out`, which has room for koppel::kG12Chars (number_text.hpp); returns the end.
char* WriteNumber(char* out, double value);

// The one writer of a CSV cell of text (a name, a column head, a word), for every command's CSV:
// RFC 4180, quoted (a quote doubled) when it holds a comma, a quote or a line break; a cell a
// spreadsheet would take for a formula (=, +, -, @ first, and not a number such as -1.5) gets a
// leading ' (OWASP's "CSV injection"); a character that is not printable
// (koppel/core/printable_text.hpp: a control character, a byte that is not UTF-8) becomes U+FFFD,
// so that a table written to a terminal holds no escape sequence. The file reader refuses such
// names; the API and the Python module may still pass one.
std::string CsvField(std::string_view text);
// Text cells (a header) as one CSV line: each a CsvField, commas between, a newline.
std::string CsvLine(const std::vector<std::string>& cells);

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  std::string ToCsv() const;
  nlohmann::json ToJson() const;  // {"columns": [...], "rows": [[...], ...]}
};

// A table whose cells are numbers, words or empty (synth motion and synth path: the Grashof type,
// the rank a cognate repeats). CSV as Table; JSON as Table's {"columns", "rows"}, a word as a
// string and an empty cell as null (as analyze's cells that cannot be computed).
struct MixedTable {
  using Cell = std::variant<std::monostate, double, std::string>;
  std::vector<std::string> columns;
  std::vector<std::vector<Cell>> rows;
  std::string ToCsv() const;
  nlohmann::json ToJson() const;
  // ToJson()'s JsonText for "json", ToCsv() otherwise
  std::string Text(const std::string& format) const;
};

// Prints "koppel: message" on stderr, a control character in it (but a line end) escaped ("\x1B").
void Complain(const std::string& message);
// "koppel: PATH: note: ..." on stderr for each of a mechanism's admission notes.
void PrintNotes(const std::string& path, const std::vector<std::string>& notes);

// A point of the mechanism named on the command line by `flag` (--point K): a point output
// (`K`), `link.point`, or a point name that only one link has. Exit{2} naming the flag and the
// candidates otherwise.
PointRef ResolvePoint(const Mechanism& mechanism, const std::string& text, const std::string& flag);

// A scalar output by name (given by `flag`); empty: the first scalar output of the mechanism file
// `path`. Exit{2} naming the file or the flag otherwise.
int ResolveScalarOutput(const Mechanism& mechanism, const std::string& name, const std::string& flag, const std::string& path);

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
