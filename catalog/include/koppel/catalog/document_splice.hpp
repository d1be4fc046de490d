// The text half of editing a mechanism file in place (koppel/catalog/document_edit.hpp finds the
// places with the YAML reader): new values written into given scalar spans of the user's text,
// quoted as the place needs, every other byte kept. It reads no YAML, so the editor page's
// WebAssembly module (which has no YAML reader) writes its export with the same rule, from
// places the CLI found for it.
#pragma once

#include "koppel/core/diagnostic.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace koppel {

// The bytes [begin, end) of the text that hold one scalar's value: inside the quotes of a quoted
// scalar that holds no escape, else the whole scalar as written.
struct TextSpan {
  std::size_t begin = 0;
  std::size_t end = 0;
};

// A scalar's place: its span and the quote that stays around it ('\0': none, the span is the
// whole scalar; '"' or '\'': the span is inside those quotes).
struct ScalarPlace {
  TextSpan span;
  char quote = '\0';
};

// One value to write: the formula (or a number's text, NumberText) for the place; `what` names
// it in messages ("parameter 'l2'").
struct ScalarEdit {
  ScalarPlace place;
  std::string formula;
  std::string what;
};

// The shortest text that reads back to exactly `value` ("150", "0.1", "1.5e-07"). InputError
// for a value that is not finite (a file must not hold one).
std::string NumberText(double value);

// `text` with each edit's span replaced by its formula, written as its place needs (bare where
// YAML reads it back as written, in a block or a flow collection alike; else double-quoted, or
// escaped inside the quotes already there). InputError (in `file_name`) for a span outside the
// text or two edits of overlapping spans. No edits: `text` itself.
std::string SpliceScalars(const std::string& text, const std::string& file_name, std::vector<ScalarEdit> edits);

}  // namespace koppel
