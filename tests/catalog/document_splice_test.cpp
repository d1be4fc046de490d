// Writing values into scalar spans without a YAML reader (the editor page's export). References:
// spans counted by hand in the texts below, and EditMechanismText (which finds its spans with the
// YAML reader) for the same changes.
#include "koppel/catalog/document_edit.hpp"
#include "koppel/catalog/document_splice.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace koppel::document_splice_test {

TEST_CASE("SpliceScalars writes each value as its place needs and keeps every other byte", "[catalog][document_splice]") {
  const std::string text = "parameters: {a: 1, b: '2'}  # flow\n";
  // a: bytes 16..17; b: inside its quotes, bytes 23..24
  CHECK(SpliceScalars(text, "t.yaml", {{{{16, 17}, '\0'}, "3*b", "a"}}) == "parameters: {a: 3*b, b: '2'}  # flow\n");
  CHECK(SpliceScalars(text, "t.yaml", {{{{16, 17}, '\0'}, "min(b, 2)", "a"}}) == "parameters: {a: \"min(b, 2)\", b: '2'}  # flow\n");
  CHECK(SpliceScalars(text, "t.yaml", {{{{23, 24}, '\''}, "it's", "b"}}) == "parameters: {a: 1, b: 'it''s'}  # flow\n");
  // in any order; none: the text itself
  CHECK(SpliceScalars(text, "t.yaml", {{{{23, 24}, '\''}, "5", "b"}, {{{16, 17}, '\0'}, "4", "a"}}) == "parameters: {a: 4, b: '5'}  # flow\n");
  CHECK(SpliceScalars(text, "t.yaml", {}) == text);
  // the same as EditMechanismText, which found the places itself
  DocumentChanges changes;
  changes.parameters = {{"a", "min(b, 2)"}, {"b", "it's"}};
  CHECK(EditMechanismText(text, "t.yaml", changes) == "parameters: {a: \"min(b, 2)\", b: 'it''s'}  # flow\n");
  const ScalarPlace b = ScalarPlaceAt(text, "t.yaml", "parameters.b");
  CHECK((b.span.begin == 23 && b.span.end == 24 && b.quote == '\''));
}

TEST_CASE("SpliceScalars refuses a place outside the text and two edits of one value", "[catalog][document_splice]") {
  const std::string text = "a: 1\n";
  CHECK_THROWS_WITH(SpliceScalars(text, "t.yaml", {{{{3, 40}, '\0'}, "2", "parameter 'a'"}}), Catch::Contains("parameter 'a': its place is not in the text"));
  CHECK_THROWS_WITH(SpliceScalars(text, "t.yaml", {{{{3, 4}, '\0'}, "2", "x"}, {{{3, 4}, '\0'}, "3", "y"}}), Catch::Contains("two changes of the same value: x and y"));
}

}  // namespace koppel::document_splice_test
