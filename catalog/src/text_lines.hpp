// The lines and comma-separated fields of the catalog's small CSV inputs (points, motor curves):
// a UTF-8 byte-order mark at the start and CR line ends are dropped, fields are trimmed of
// spaces and tabs and keep their 1-based column for diagnostics. Private to the catalog.
#pragma once

#include <string>
#include <vector>

namespace koppel {

struct TextLine {
  int number = 0;  // 1-based
  std::string text;
};
std::vector<TextLine> SplitLines(const std::string& text);

struct TextField {
  std::string text;
  int column = 0;  // 1-based, of the field's first character
};
std::vector<TextField> SplitFields(const std::string& line, char separator);

}  // namespace koppel
