// Editing a mechanism file in place. References: for ScalarSpan, the byte offsets counted by hand
// in the texts below; for EditMechanismText over every catalog entry and tests/data mechanism,
// the text itself (no change: byte-identical; a parameter changed: the text with only that
// value's span replaced) and ReadMechanismFile of the original with --set of the same value.
#include "koppel/catalog/document_edit.hpp"
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/catalog/parameter_use.hpp"

#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>

namespace koppel::document_edit_test {
namespace {

// The edited text and the --set reading evaluate the same formulas from the same number text:
// equal to rounding of the last bits, far below any length of a file.
constexpr double kSame = 1e-12;

std::vector<std::string> MechanismFiles() {
  std::vector<std::string> files;
  for (const std::string& dir : {std::string(KOPPEL_CATALOG_DIR), std::filesystem::path(test::TestDataPath("x")).parent_path().string()}) {
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      if (e.path().extension() == ".yaml") files.push_back(e.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

void SamePoints(const Mechanism& a, const Mechanism& b) {
  REQUIRE(a.links.size() == b.links.size());
  for (size_t l = 0; l < a.links.size(); ++l) {
    REQUIRE(a.links[l].points.size() == b.links[l].points.size());
    for (size_t p = 0; p < a.links[l].points.size(); ++p) {
      INFO(a.links[l].name << "." << a.links[l].points[p].name);
      CHECK((a.links[l].points[p].local - b.links[l].points[p].local).norm() <= kSame);
    }
  }
  REQUIRE(a.joints.size() == b.joints.size());
  for (size_t j = 0; j < a.joints.size(); ++j) {
    CHECK(std::abs(a.joints[j].angle - b.joints[j].angle) <= kSame);
    CHECK((a.joints[j].axis - b.joints[j].axis).norm() <= kSame);
  }
  CHECK(std::abs(a.drive.zero - b.drive.zero) <= kSame);
  CHECK(std::abs(a.hint.input - b.hint.input) <= kSame);
  REQUIRE(a.hint.points.size() == b.hint.points.size());
  for (size_t h = 0; h < a.hint.points.size(); ++h) CHECK((a.hint.points[h].global - b.hint.points[h].global).norm() <= kSame);
}

std::string Spanned(const std::string& text, const std::string& path) {
  const TextSpan s = ScalarSpan(text, "t.yaml", path);
  return text.substr(s.begin, s.end - s.begin);
}

}  // namespace

TEST_CASE("ScalarSpan finds a value in block and flow style, inside quotes, before a comment", "[catalog][document_edit]") {
  const std::string text =
      "parameters:\n"            // 0..11
      "  a: 1.5   # crank\n"     // 'a' value at 17
      "  b: \"2.5\"\n"
      "  c: '3'\n"
      "  d: \"1\\x41\"\n"
      "links: {frame: {points: {A0: [0, -a], B: [ 2 ,a*cos(30*deg) ]}}}\n"
      "joints:\n"
      "  S: {type: P, links: [frame, frame], axis: [1, 0], angle: 90}  # why\n";
  CHECK(ScalarSpan(text, "t.yaml", "parameters.a").begin == 17);
  CHECK(ScalarSpan(text, "t.yaml", "parameters.a").end == 20);
  CHECK(Spanned(text, "parameters.a") == "1.5");
  CHECK(Spanned(text, "parameters.b") == "2.5");  // inside the quotes: they stay
  CHECK(Spanned(text, "parameters.c") == "3");
  CHECK(Spanned(text, "parameters.d") == "\"1\\x41\"");  // an escape: the whole scalar
  CHECK(Spanned(text, "links.frame.points.A0[1]") == "-a");
  CHECK(Spanned(text, "links.frame.points.B[0]") == "2");
  CHECK(Spanned(text, "links.frame.points.B[1]") == "a*cos(30*deg)");
  CHECK(Spanned(text, "joints.S.angle") == "90");
}

TEST_CASE("ScalarSpan matches a key that holds a dot or a bracket as written", "[catalog][document_edit]") {
  const std::string text = "links:\n  arm: {points: {P: [9, 9]}}\n  arm.2:\n    points:\n      P[1]: [1, 2]\n";
  CHECK(Spanned(text, "links.arm.points.P[0]") == "9");
  CHECK(Spanned(text, "links.arm.2.points.P[1][1]") == "2");
}

TEST_CASE("ScalarSpan refuses a path with no single value and a value over several lines", "[catalog][document_edit]") {
  const std::string text = "parameters:\n  a: 1 +\n    2\n  b: [1, 2]\n";
  CHECK_THROWS_WITH(ScalarSpan(text, "t.yaml", "parameters.a"), Catch::Contains("not written on one line"));
  CHECK_THROWS_WITH(ScalarSpan(text, "t.yaml", "parameters.b"), Catch::Contains("no single value at 'parameters.b'"));
  CHECK_THROWS_WITH(ScalarSpan(text, "t.yaml", "parameters.c"), Catch::Contains("no single value"));
  CHECK_THROWS_AS(ScalarSpan(text, "t.yaml", "parameters.b[2]"), InputError);
}

TEST_CASE("EditMechanismText rewrites only the changed spans", "[catalog][document_edit]") {
  const std::string text = "parameters: {a: 1, b: '2'}  # flow\nlinks:\n  f: {points: {A: [a, 0]}}\n";
  DocumentChanges changes;
  changes.parameters = {{"b", "0.25"}, {"a", "3*b"}};
  changes.numbers = {{"links.f.points.A[1]", -1.5}};
  CHECK(EditMechanismText(text, "t.yaml", changes) == "parameters: {a: 3*b, b: '0.25'}  # flow\nlinks:\n  f: {points: {A: [a, -1.5]}}\n");
  // a formula that would end a flow scalar or start a comment is written double-quoted
  changes = {};
  changes.parameters = {{"a", "min(b, 2)"}};
  CHECK(EditMechanismText(text, "t.yaml", changes) == "parameters: {a: \"min(b, 2)\", b: '2'}  # flow\nlinks:\n  f: {points: {A: [a, 0]}}\n");
  changes.parameters = {{"b", "it's"}};
  CHECK(EditMechanismText(text, "t.yaml", changes) == "parameters: {a: 1, b: 'it''s'}  # flow\nlinks:\n  f: {points: {A: [a, 0]}}\n");
}

TEST_CASE("EditMechanismText refuses an unknown parameter and two changes of one value", "[catalog][document_edit]") {
  const std::string text = "parameters:\n  a: 1\nlinks: {f: {points: {A: [a, 0]}}}\n";
  DocumentChanges changes;
  changes.parameters = {{"z", "1"}};
  CHECK_THROWS_WITH(EditMechanismText(text, "t.yaml", changes), Catch::Contains("'z' is not a parameter"));
  changes.parameters = {{"a", "2"}};
  changes.numbers = {{"parameters.a", 3}};
  CHECK_THROWS_WITH(EditMechanismText(text, "t.yaml", changes), Catch::Contains("two changes of the same value"));
  changes = {};
  changes.numbers = {{"links.f.points.A[0]", std::nan("")}};
  CHECK_THROWS_AS(EditMechanismText(text, "t.yaml", changes), InputError);
}

TEST_CASE("NumberText is the shortest text that reads back to the same number", "[catalog][document_edit]") {
  CHECK(NumberText(150.0) == "150");
  CHECK(NumberText(0.1) == "0.1");
  CHECK(NumberText(-2.5e-7) == "-2.5e-07");
  const double third = 1.0 / 3;
  CHECK(std::stod(NumberText(third)) == third);
}

TEST_CASE("every mechanism file: no change is byte-identical, a parameter changed equals --set of it", "[catalog][document_edit]") {
  int files = 0, changes = 0;
  for (const std::string& path : MechanismFiles()) {
    INFO(path);
    const std::string text = test::ReadText(path);
    MechanismFile original;
    try {
      original = ParseMechanismText(text, path);
    } catch (const InputError&) {
      continue;  // a fit problem, a spec, poses: no mechanism file
    }
    ++files;
    CHECK(EditMechanismText(text, path, {}) == text);
    for (const std::string& name : ParametersRead(original)) {
      INFO("parameter " << name);
      const double value = 1.03 * original.parameters.Value(name) + 0.01;  // a small change, away from zero
      MechanismFile by_set;
      try {
        by_set = ReadMechanismFile(path, {{name, NumberText(value)}});
      } catch (const InputError&) {
        continue;  // the changed value does not make a mechanism (a formula's domain): nothing to compare
      }
      DocumentChanges change;
      change.parameters = {{name, NumberText(value)}};
      const std::string edited = EditMechanismText(text, path, change);
      const TextSpan span = ScalarSpan(text, path, "parameters." + name);
      CHECK(edited == text.substr(0, span.begin) + NumberText(value) + text.substr(span.end));
      const MechanismFile reread = ParseMechanismText(edited, path);
      CHECK(reread.parameters.Value(name) == value);
      CHECK(reread.parameters.Values() == by_set.parameters.Values());
      SamePoints(reread.mechanism, by_set.mechanism);
      ++changes;
    }
  }
  CHECK(files >= 40);
  CHECK(changes >= 100);
}

}  // namespace koppel::document_edit_test
