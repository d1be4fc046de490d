// The catalog card of a mechanism: the `catalog:` section of its YAML file. It says what the
// mechanism is (titles, kind, motion, applications, source), declares its access features
// (Zugriffsmerkmale) exactly as its document lists them, and carries the document's equations
// and figures as checks that `koppel catalog check` recomputes with the generic solver.
#pragma once

#include <map>
#include <optional>
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

// A scalar figure of the document, recomputed from the solver.
//   quantity: min, max, argmin, argmax (of `output` over the sweep; arg in input units),
//             value (of `output` at `at`), derivative (order `order` of `output` at `at`),
//             stroke (max - min of `output`), and the kinds the analysis modules add
//             (deadcentre, straightline, proportionality, cognate ...).
struct FigureCheck {
  std::string name;
  std::string quantity;
  std::string output;
  int component = 0;
  int order = 0;
  std::map<std::string, std::string> args;  // further arguments by name, as formulas or words
  std::string expected;  // the document's value, as a formula (degrees for angles: see unit)
  std::string unit;      // "deg" when expected is an angle in degrees; empty otherwise
  double tolerance = 0;  // absolute, in the unit of `expected`; the document's rounding
  std::string printed;   // the printed figure when koppel's differs, and why (note)
  std::string note;
  bool pending = false;  // declared, checked by a later analysis (reported, not failed)
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
  std::string kind;    // "transfer" (Übertragungsgetriebe) or "guidance" (Führungsgetriebe)
  std::string motion;  // e.g. "full rotation -> oscillating translation"
  std::vector<std::string> applications;
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
