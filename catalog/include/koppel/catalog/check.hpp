// `koppel catalog check`: recomputes an entry's access features and classes from its joint
// graph and its document's equations and figures from the generic solver, and says, per check,
// the worst deviation against the tolerance.
#pragma once

#include "koppel/catalog/card.hpp"
#include "koppel/catalog/mechanism_file.hpp"

#include <string>
#include <vector>

namespace koppel {

// Access features computed from the mechanism graph; `output_names` are the Abtrieb outputs.
AccessFeatures ComputeFeatures(const Mechanism& mechanism, const std::vector<std::string>& output_names);

// Declared-vs-computed differences, one line each ("links: declared 6, computed 5"); a feature
// the card does not declare is not compared.
std::vector<std::string> CompareFeatures(const AccessFeatures& declared, const AccessFeatures& computed);

enum class CheckKind { kFeatures, kEquation, kFigure };
const char* ToString(CheckKind kind);  // "features", "equation", "figure"

enum class CheckStatus {
  kNotRun,       // default: nothing computed yet
  kPassed,       // within tolerance
  kFailed,       // computed, outside the tolerance (or a declared feature differs)
  kNotComputed,  // the solver could not produce the value (a sweep stopped ...): a failure too
};
const char* ToString(CheckStatus status);  // "not run", "pass", "FAIL", "not computed"

struct CheckOutcome {
  std::string variant;   // parameter set, empty for the file's own
  std::string name;      // the check's name
  CheckKind kind = CheckKind::kFeatures;
  CheckStatus status = CheckStatus::kNotRun;
  double worst = 0;      // worst |deviation| (equations) or |koppel - document| (figures)
  double tolerance = 0;
  double value = 0;      // figures: koppel's value in the figure's unit
  double where = 0;      // equations: input of the worst deviation (deg for R drives)
  std::string detail;    // failure reason or note
  bool passed() const { return status == CheckStatus::kPassed; }
  // worst / tolerance: <= 1 passes; 0 for an exact match at tolerance 0, infinity otherwise
  double Ratio() const;
};

struct EntryReport {
  std::string id;
  std::vector<CheckOutcome> checks;
  bool passed() const;
  int Count(CheckStatus status) const;
  // The check with the largest Ratio() (nullptr when there are no checks).
  const CheckOutcome* Worst() const;
  // "slider-crank-offset: 45/45 passed, worst 0.31 of tolerance (mu_min ...)"
  std::string Brief() const;
};

// Runs every check of the entry at `path`. Bad input (a malformed card, a formula naming an
// unknown name, a formula that has no value under a variant) throws InputError like the reader.
EntryReport CheckEntry(const std::string& path);
// The same with `card` instead of the file's own (e.g. a mutated copy in a test); the variants
// re-read the file at `path` with their overrides.
EntryReport CheckCard(const std::string& path, const CatalogCard& card);

}  // namespace koppel
