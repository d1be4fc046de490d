// Changing a mechanism file by editing the user's own text, not by writing the mechanism anew:
// only the values that change are rewritten, in place; every other byte (formulas, the other
// parameters, comments, key order, flow or block style, units, masses, gravity, loads and the
// catalog card) stays as the user wrote it. A change names a parameter (its formula is replaced)
// or the key path of a number of the model part (MechanismFile::formulas), e.g. a point of a
// derived mechanism that no parameter writes.
#pragma once

#include "koppel/catalog/document_splice.hpp"  // TextSpan, ScalarPlace, NumberText
#include "koppel/core/diagnostic.hpp"

#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace koppel {

struct DocumentChanges {
  // parameter name -> its new formula (a number's text, NumberText, or any formula); the span
  // of `parameters.NAME` is rewritten
  std::vector<std::pair<std::string, std::string>> parameters;
  // key path as MechanismFile::formulas names it ("links.frame.points.B0[0]") -> the number
  // that replaces the formula written there [the file's units: degrees for an angle]
  std::vector<std::pair<std::string, double>> numbers;
};

// Where the scalar at `key_path` is written in `text` (a mechanism file named `file_name` in
// messages). A key path joins map keys with '.' and list indices as [i]; a key that holds a '.'
// or '[' is matched as written. InputError when the text is no YAML, no scalar stands at the
// path, or it is written over several lines (there is no one span to replace).
TextSpan ScalarSpan(const std::string& text, const std::string& file_name, const std::string& key_path);
// The same with the quote that stays around the span (what SpliceScalars needs).
ScalarPlace ScalarPlaceAt(const std::string& text, const std::string& file_name, const std::string& key_path);
// The place of every scalar of the text written on one line, by key path, from one reading of the
// text (a file of 10^5 parameters is read once, not once per value). InputError for no YAML.
std::unordered_map<std::string, ScalarPlace> ScalarPlaces(const std::string& text, const std::string& file_name);

// `text` with `changes` made in place: each changed value's span rewritten (a formula that is no
// plain YAML scalar in its place, e.g. holds ", " or ": ", double-quoted), nothing else. No
// changes: `text` itself, byte for byte. InputError naming the change for a parameter the text
// does not have, a path with no scalar, or two changes of the same span. The result is not read
// here: the caller reads it (ParseMechanismText) to learn whether the changed mechanism checks.
std::string EditMechanismText(const std::string& text, const std::string& file_name, const DocumentChanges& changes);

}  // namespace koppel
