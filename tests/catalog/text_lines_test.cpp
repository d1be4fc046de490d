// The lines and fields of the catalog's small CSV inputs (text_lines.hpp) on hand-worked texts:
// numbering from 1, the byte-order mark and CR line ends dropped, no line after a final newline,
// fields trimmed of spaces and tabs with the 1-based column of their first character.
#include "text_lines.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace koppel::text_lines_test {
namespace {

std::vector<std::string> Texts(const std::vector<TextLine>& lines) {
  std::vector<std::string> texts;
  for (const TextLine& l : lines) texts.push_back(l.text);
  return texts;
}
std::vector<int> Numbers(const std::vector<TextLine>& lines) {
  std::vector<int> numbers;
  for (const TextLine& l : lines) numbers.push_back(l.number);
  return numbers;
}
std::vector<std::string> Texts(const std::vector<TextField>& fields) {
  std::vector<std::string> texts;
  for (const TextField& f : fields) texts.push_back(f.text);
  return texts;
}
std::vector<int> Columns(const std::vector<TextField>& fields) {
  std::vector<int> columns;
  for (const TextField& f : fields) columns.push_back(f.column);
  return columns;
}

}  // namespace

TEST_CASE("SplitLines numbers lines from 1 and keeps empty ones in the middle", "[text_lines]") {
  const auto lines = SplitLines("x,y\n\n1,2\n3,4");
  CHECK(Texts(lines) == std::vector<std::string>{"x,y", "", "1,2", "3,4"});
  CHECK(Numbers(lines) == std::vector<int>{1, 2, 3, 4});
  // a final newline ends the last line; it does not start an empty one
  CHECK(Texts(SplitLines("a\nb\n")) == std::vector<std::string>{"a", "b"});
  // but an empty line before it is a line
  CHECK(Numbers(SplitLines("a\n\n")) == std::vector<int>{1, 2});
  CHECK(SplitLines("").empty());
  CHECK(Texts(SplitLines("\n")) == std::vector<std::string>{""});
}

TEST_CASE("SplitLines drops a UTF-8 byte-order mark and CR line ends", "[text_lines]") {
  const auto lines = SplitLines("\xEF\xBB\xBFphi,s\r\n0,1\r\n");
  CHECK(Texts(lines) == std::vector<std::string>{"phi,s", "0,1"});
  CHECK(Numbers(lines) == std::vector<int>{1, 2});
  // the mark only at the start; a lone CR inside a line stays
  CHECK(Texts(SplitLines("a\n\xEF\xBB\xBF" "b")) == std::vector<std::string>{"a", "\xEF\xBB\xBF" "b"});
  CHECK(Texts(SplitLines("a\rb\r")) == std::vector<std::string>{"a\rb"});
  CHECK(SplitLines("\xEF\xBB\xBF").empty());
}

TEST_CASE("SplitFields trims each field and gives its first character's column", "[text_lines]") {
  // hand-counted columns: "1.5" at 1, "2" at 7 (after "1.5,  "), "x y" at 11 (after "1.5,  2, \t")
  const auto fields = SplitFields("1.5,  2, \tx y ", ',');
  CHECK(Texts(fields) == std::vector<std::string>{"1.5", "2", "x y"});
  CHECK(Columns(fields) == std::vector<int>{1, 7, 11});
  // empty fields: between two separators, at either end
  const auto empty = SplitFields(",a,,", ',');
  CHECK(Texts(empty) == std::vector<std::string>{"", "a", "", ""});
  CHECK(Columns(empty) == std::vector<int>{1, 2, 4, 5});
  // a blank field: empty, at the column after its blanks
  const auto blank = SplitFields("a,  ,b", ',');
  CHECK(Texts(blank) == std::vector<std::string>{"a", "", "b"});
  CHECK(Columns(blank) == std::vector<int>{1, 5, 6});
  // an empty line is one empty field; another separator cuts elsewhere
  CHECK(Texts(SplitFields("", ',')) == std::vector<std::string>{""});
  CHECK(Texts(SplitFields("1;2,3", ';')) == std::vector<std::string>{"1", "2,3"});
}

}  // namespace koppel::text_lines_test
