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

// ScalarPlaces reads the text once and names every scalar on one line by its key path, as
// ScalarPlaceAt finds it path by path (the reference); a file of 20 000 parameters included (the
// editor document asks for the place of each).
TEST_CASE("ScalarPlaces gives every value's place from one reading", "[catalog][document_splice]") {
  const std::string text = "parameters: {a: 1, b: '2'}  # flow\nlinks:\n  f: {points: {A: [a, \"0\"]}}\nname: |\n  two\n  lines\n";
  const auto places = ScalarPlaces(text, "t.yaml");
  for (const std::string path : {"parameters.a", "parameters.b", "links.f.points.A[0]", "links.f.points.A[1]"}) {
    INFO(path);
    REQUIRE(places.count(path) == 1);
    const ScalarPlace one = ScalarPlaceAt(text, "t.yaml", path);
    CHECK((places.at(path).span.begin == one.span.begin && places.at(path).span.end == one.span.end && places.at(path).quote == one.quote));
  }
  CHECK(places.count("name") == 0);  // over several lines: no place
  std::string many = "parameters:\n";
  for (int i = 0; i < 20000; ++i) many += "  p" + std::to_string(i) + ": " + std::to_string(i) + "\n";
  const auto all = ScalarPlaces(many, "many.yaml");
  REQUIRE(all.count("parameters.p19999") == 1);
  const TextSpan last = all.at("parameters.p19999").span;
  CHECK(many.substr(last.begin, last.end - last.begin) == "19999");
  CHECK(all.size() == 20000);
}

}  // namespace koppel::document_splice_test
