// The catalog card of a mechanism: the `catalog:` section of its YAML file. It says what the
// mechanism is (titles, kind, classes, motion, applications, source), declares its access
// features (Zugriffsmerkmale) exactly as its document lists them, and carries the document's
// equations and figures as checks that `koppel catalog check` recomputes with the generic solver.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace koppel {

// Access features (Zugriffsmerkmale) of a mechanism description. A value of -1 means "not
// declared" (a computed feature always has every value).
struct AccessFeatures {
  int drive_joints = -1;
  int drive_joints_at_frame = -1;
  int output_links = -1;
  int output_links_at_frame = -1;
  int links = -1;
  std::map<int, int> links_by_degree;      // joints per link (2 binary, 3 ternary ...) -> count
  int joints = -1;
  std::map<std::string, int> joints_by_type;  // "D" revolute, "S" prismatic, "W" helical ...
};

// Übertragungsgetriebe (the output is a motion of a link: transfer function) or
// Führungsgetriebe (a point or a link is guided along a path or through poses).
enum class CardKind { kTransfer, kGuidance };
const char* ToString(CardKind kind);  // "transfer", "guidance"

// One of the document's equations, compared with a solver output over a sweep.
struct EquationCheck {
  std::string name;     // e.g. "s'' (Bild 2)"
  std::string output;   // output name in the mechanism file
  int component = 0;    // 0, or 1 for the y of a point output
  int order = 0;        // 0 value, 1 first-order transfer function, ...
  std::string formula;  // over the parameters, `phi` (input, radians or length) and `where` names
  double tolerance = 1e-9;  // absolute, in the output's internal unit (rad or length)
  std::string printed;  // the printed (OCR'd) formula when it differs from `formula`
  std::string note;     // why the formula was corrected, or what it is
  int line = 0;         // line in the file, for messages
};

// What a figure measures; the table in figure_quantities.hpp gives each one's name in the file,
// its arguments, its unit and its evaluator.
enum class FigureQuantity {
  kMin,                  // of an output over the sweep (or from..to)
  kMax,
  kArgMin,               // input where the output is least
  kArgMax,
  kStroke,               // max - min of an output
  kValue,                // output at an input
  kDerivative,           // order-k transfer function at an input
  kDeadCentreSpan,       // crank angle from the folded to the extended dead centre
  kDeadCentrePhiA,       // input of the extended dead centre (äußere Totlage)
  kDeadCentrePhiI,       // input of the folded dead centre (innere Totlage)
  kPhaseRatio,           // phase ratio phi_H / (360 deg - phi_H)
  kTimeRatio,            // time ratio: the slow stroke's crank angle over the fast one's, >= 1
  kProportionalityDs,    // seed 001: band width about the flat-point tangent
  kProportionalityQp,
  kStraightlinePhiG,     // seed 003: longest stretch with Q_G <= qg
  kStraightlinePhiA,
  kStraightlineLength,
  kStraightlineBand,     // band width of a given stretch from..to about the tangent at `at`
  kCognateFrame,         // Roberts cognate's frame length
  kInputLow,             // drivable range of the input: its lower limit position
  kInputHigh,            // ... and its upper one
  kRevolves,             // 1 when a joint can turn fully, 0 when it oscillates
  kTurns,                // full turns of an angle output over the sweep
  kBranchPoint,          // input of the branch point (change point) nearest `near`
  kRest,                 // a dwell (Rast): max - min of an output over from..to, expected 0 within the band
};

// A scalar figure of the document, recomputed from the solver. Every key is checked against
// the quantity's table entry when the card is read: an unknown quantity, an argument the
// quantity does not take or a malformed argument is an error with its line.
struct FigureCheck {
  std::string name;
  FigureQuantity quantity = FigureQuantity::kValue;
  std::string output;    // empty for quantities of the mechanism as a whole
  int component = 0;
  // the quantity's arguments by name (formulas, an order, or a joint name), as written
  std::map<std::string, std::string> args;
  std::string expected;  // the document's value, as a formula over the parameters
  bool degrees = false;  // `unit: deg`: expected is an angle in degrees (required for angles)
  double tolerance = 0;  // absolute, in the unit of `expected`; the document's rounding
  std::string printed;   // the printed figure when koppel's differs, and why (note)
  std::string note;
  std::string variant;   // the CheckVariant it belongs to; empty: every variant
  int line = 0;
};

// A set of parameter overrides under which all checks run (e.g. e = 0 and e = 0.8).
struct CheckVariant {
  std::string name;
  std::vector<std::pair<std::string, std::string>> overrides;
};

struct CatalogCard {
  std::string title_de;
  std::string title_en;
  CardKind kind = CardKind::kTransfer;
  std::vector<std::string> classes;  // e.g. four-bar, crank-rocker (catalog_classes.hpp)
  std::string motion;  // "<input motion> -> <output motion>[ ...]", e.g. "full rotation -> oscillating translation"
  std::vector<std::string> applications;
  std::vector<std::string> keywords;  // more words the search finds it by (text_search.hpp), English and German
  std::string document;  // the source description
  std::string author;
  std::vector<std::string> literature;
  std::vector<std::string> outputs;  // names of the outputs that are the Abtrieb
  AccessFeatures declared;
  std::vector<std::pair<std::string, std::string>> where;  // intermediate definitions, in order
  std::vector<EquationCheck> equations;
  std::vector<FigureCheck> figures;
  std::vector<CheckVariant> variants;  // empty: the file's own parameters only
  // the sweep for equation checks, in the drive's YAML units (degrees for R)
  double from = 0, to = 360, step = 1;
};

}  // namespace koppel
