// A mechanism file's text with its `catalog` card blanked out, for a reading of the mechanism
// alone (MechanismSource: koppel::Model). yaml-cpp's scanner spent three quarters of a catalog
// entry's parse on the card's prose and formulas, which the mechanism does not use (issue 25).
// Private to the catalog.
#pragma once

#include <optional>
#include <string>

namespace koppel {

struct BlankedCard {
  std::string text;  // the file's text, the card's value emptied (`catalog:` stays, with no value): every line in its place
  int key_line = 0;   // 1-based line of `catalog:`
  int next_line = 0;  // 1-based line of the first top-level key after the card; 0: the card ends the text
};

// The card is blanked only where its extent is plain from the characters: a line `catalog:`
// (a comment may follow) at column 0, the only one; then lines that are empty, comments or
// indented by spaces (a tab there: not blanked), up to the first line that starts at column 0 (it must not be `---` or `...`), on
// each of which every quoted scalar and flow collection closes (the card's value cannot run on
// past that line, as yaml-cpp lets a quoted scalar or a flow collection continue at column 0).
// A quote counts as opening wherever yaml-cpp may start a token (at a line's start, after a
// blank, one of []{},:, a quoted scalar or a tag; elsewhere it is a character of a plain scalar:
// "Grashof's", x''), a bracket wherever it stands: when unsure, the card is not blanked.
// nullopt: no such card.
// What the caller still owes: that the text before the card ended its last value and the card
// ended before next_line, shown by yaml-cpp finding top-level keys at key_line and next_line,
// column 1 (yaml-cpp takes a quote left open at the end of the text as closed there).
std::optional<BlankedCard> BlankCard(const std::string& text);

}  // namespace koppel
