// Reading mechanism files (YAML, format in README.md "Mechanism files"). Every problem of a
// file is collected and reported at once, each with file:line:column, the key path and what was
// expected; yaml-cpp stays inside the catalog's .cpp files.
#pragma once

#include "koppel/catalog/card.hpp"
#include "koppel/core/diagnostic.hpp"  // Diagnostic, InputError (every reader throws them)
#include "koppel/core/expression.hpp"
#include "koppel/core/loads.hpp"
#include "koppel/core/mechanism.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace koppel {

// The default sweep of a file, in the drive's YAML units (degrees for an R drive).
struct SweepDefaults {
  double from = 0;
  double to = 360;
  double step = 1;
};

struct MechanismFile {
  std::string path;
  std::string id;     // `name`
  std::string title;  // `title`
  std::string description;
  ParameterSet parameters;  // after overrides
  Mechanism mechanism;      // consistent, angles in radians
  SweepDefaults sweep;
  std::optional<CatalogCard> card;  // the `catalog` section, when present (CardReading::kRead)
  Loads loads;  // masses, units, gravity and loads (loads.hpp); none when the file gives none
  // The text of every number of the model part (parameters, links .. sweep) as it was evaluated,
  // by key path in reading order: {"parameters.e", "0.3"} (the override when one was given),
  // {"links.frame.points.A0[1]", "-e"}, {"joints.S.angle", "90"} [the file's units, degrees for
  // angles]. The editor page (koppel edit) re-evaluates them after a parameter changes.
  std::vector<std::pair<std::string, std::string>> formulas;
};

using Overrides = std::vector<std::pair<std::string, std::string>>;

// Whether a reading reads the file's `catalog` card. The card does not make the mechanism: the
// catalog's commands, which evaluate it (`koppel catalog list|find|show|check`: Catalog::Load,
// CheckEntry), read it in full (kRead: its keys, words, counts and formulas, each problem with
// its line); a koppel::Model (analyze, curve, ...: the mechanism alone) does not (kSkipped: card
// stays empty), and MechanismSource does not even parse its YAML where its lines are plainly
// its own. Reading a catalog entry's card was two thirds of `koppel analyze`'s start-up
// (yaml-cpp scanning its prose, muparser parsing its formulas; issue 25).
enum class CardReading { kRead, kSkipped };

// Reads and checks a mechanism file: `path`, or the catalog entry when `path` is no file but a
// catalog id (ResolveMechanismName in catalog.hpp; MechanismFile::path is then the entry's
// file). `overrides` (NAME -> formula, from --set) replace parameter formulas before
// evaluation; overriding a name that is not a parameter, or a parameter that no formula of the
// model reads (ParametersRead, parameter_use.hpp: it would change nothing), is an error. Throws
// InputError.
MechanismFile ReadMechanismFile(const std::string& path, const Overrides& overrides = {});
MechanismFile ParseMechanismText(const std::string& text, const std::string& file_name, const Overrides& overrides = {},
                                 CardReading card = CardReading::kRead);

// "NAME=VALUE" -> {NAME, VALUE}; throws InputError for a malformed argument.
std::pair<std::string, std::string> ParseAssignment(const std::string& name_eq_value);

}  // namespace koppel
