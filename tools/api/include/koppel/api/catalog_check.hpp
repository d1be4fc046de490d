// The catalog's entries checked against their documents (koppel catalog check) and shown as a page
// (koppel catalog show): every access feature, equation and figure of an entry's card recomputed
// with the generic solver (koppel/catalog/check.hpp), the outcome per check. Angles and inputs in
// the card's units (degrees for an R drive).
#pragma once

#include "koppel/api/catalog.hpp"
#include "koppel/core/mechanism.hpp"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace koppel {

// What a check compares: the access features and classes with the joint graph, one of the
// document's equations over the card's sweep, or one of its figures.
enum class CatalogCheckKind { kFeatures, kEquation, kFigure };
const char* ToString(CatalogCheckKind kind);  // "features", "equation", "figure"

enum class CatalogCheckStatus {
  kNotRun,
  kPassed,       // within tolerance
  kFailed,       // outside the tolerance (or a declared feature differs)
  kNotComputed,  // the solver could not produce the value (detail says why): a failure too
};
const char* ToString(CatalogCheckStatus status);  // "not run", "pass", "FAIL", "not computed"

// One check of one variant (parameter set) of an entry.
struct CatalogCheck {
  std::string variant;  // empty for the file's own parameters
  std::string name;
  CatalogCheckKind kind = CatalogCheckKind::kFeatures;
  CatalogCheckStatus status = CatalogCheckStatus::kNotRun;
  bool passed() const { return status == CatalogCheckStatus::kPassed; }
  bool computed() const { return status != CatalogCheckStatus::kNotComputed; }
  double worst = 0;      // worst |deviation| (equations) or |koppel - document| (figures)
  double tolerance = 0;
  double ratio = 0;      // worst / tolerance: <= 1 passes
  double value = 0;      // figures: koppel's value in the figure's unit
  double where = 0;      // equations: input of the worst deviation
  std::string detail;    // failure reason or note
};

struct CatalogCheckReport {
  std::string id;
  std::vector<CatalogCheck> checks;
  bool passed = false;
  int passed_checks = 0;
  int worst = -1;     // index of the check with the largest ratio; -1 when there is none
  std::string brief;  // "slider-crank-offset: 45/45 passed, worst 0.31 of tolerance (...)"
};

// `refused`: an id the catalog lacks ("no catalog entry 'x' (did you mean 'y'?)"); then nothing
// was checked.
struct CatalogChecks {
  std::string refused;
  std::vector<CatalogCheckReport> reports;
};

// Checks the entries `ids` (empty: every entry, in file order) of the catalog in `directory`
// (empty: CatalogDirectory()). InputError for an unreadable catalog or a card whose checks cannot
// be run (a formula naming an unknown name ...).
CatalogChecks CheckCatalog(const std::vector<std::string>& ids, const std::string& directory = "");

// The card's texts, for the page. `output_shown` names a point output's component ("P_x", "P_y").
struct CatalogEquation {
  std::string name, output, output_shown;
  int order = 0;
  std::string formula, printed, note;
  double tolerance = 0;
};
struct CatalogFigure {
  std::string name, quantity, output, output_shown;
  std::map<std::string, std::string> arguments;
  std::string expected;  // the document's value, a formula over the parameters
  bool degrees = false;
  double tolerance = 0;
  std::string printed, note, variant;
};
struct CatalogVariant {
  std::string name;
  std::vector<std::pair<std::string, std::string>> overrides;
};

// An entry as `koppel catalog show` prints it, with its checks run.
struct CatalogPage {
  std::string refused;  // as CatalogChecks::refused; then nothing else is set
  CatalogHit entry;
  std::vector<std::string> applications, literature, outputs;  // outputs: the Abtrieb
  std::string document, author;
  std::string structure;  // the joint graph's formula, one joint a line
  int gruebler_mobility = 0;
  std::vector<std::pair<std::string, std::string>> output_links;  // (Abtrieb output, its link)
  std::vector<std::pair<std::string, double>> parameters;
  std::vector<CatalogVariant> variants;
  std::string input_name, drive_joint;
  bool input_is_angle = true;
  double from = 0, to = 360, step = 1;  // the card's sweep of its equations [deg | length]
  std::vector<std::pair<std::string, std::string>> where;
  std::vector<CatalogEquation> equations;
  std::vector<CatalogFigure> figures;
  CatalogCheckReport report;
  Mechanism mechanism;  // for the page's pictures
  std::string length_unit = "length";  // the file's ("mm"), for the pictures' labels
};

// The entry `id` of the catalog in `directory`, its checks run. InputError as CheckCatalog.
CatalogPage ShowCatalogEntry(const std::string& id, const std::string& directory = "");

}  // namespace koppel
