// `koppel catalog check`: recomputes an entry's access features from its joint graph and its
// document's equations and figures from the generic solver, and says, per check, the worst
// deviation against the tolerance.
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

struct CheckOutcome {
  std::string variant;   // parameter set, empty for the file's own
  std::string name;      // the check's name
  std::string kind;      // "features", "equation", "figure"
  double worst = 0;      // worst |deviation| (equations) or |koppel - document| (figures)
  double tolerance = 0;
  double value = 0;      // figures: koppel's value in the figure's unit
  double where = 0;      // equations: input of the worst deviation (deg for R drives)
  bool passed = false;
  bool pending = false;  // needs an analysis koppel does not have yet: reported, not failed
  std::string detail;    // failure reason or note
};

struct EntryReport {
  std::string id;
  std::vector<CheckOutcome> checks;
  bool passed() const;
};

// Runs every check of the entry at `path`. Bad input (a malformed card, a formula naming an
// unknown name) throws InputError like the reader.
EntryReport CheckEntry(const std::string& path);

}  // namespace koppel
