// YamlReader (catalog/src/yaml_reader.cpp, private to the catalog): every accessor reports at the
// node's line and column (1-based, as editors count) with its key path, and keeps going so that a
// file's problems are collected; "did you mean" picks the nearest key by edit distance.
#include "yaml_reader.hpp"

#include "koppel/core/limits.hpp"

#include <catch2/catch.hpp>

namespace koppel::yaml_reader_test {
namespace {

// 0.5 * 4 and 2^3 through muparser: exact in double.
constexpr double kExact = 0;

TEST_CASE("numbers are formulas over the parameters, errors at 1-based line and column", "[yaml_reader]") {
  ParameterSet parameters;
  parameters.DefineValue("l", 4);
  YamlReader r("m.yaml", &parameters);
  const YAML::Node root = YAML::Load("a: 0.5 * l\nb: 2^3\nc:   [1, 2]\nd: l2 + 1\n");
  CHECK_THAT(*r.Number(root["a"], "a"), Catch::Matchers::WithinAbs(2.0, kExact));
  CHECK_THAT(*r.Number(root["b"], "b"), Catch::Matchers::WithinAbs(8.0, kExact));
  CHECK_FALSE(r.Number(root["c"], "c"));  // a list: line 3, column 6 (reference: counted by hand)
  CHECK_FALSE(r.Number(root["d"], "d"));  // unknown name
  REQUIRE(r.diagnostics().size() == 2);
  const Diagnostic& list = r.diagnostics()[0];
  CHECK(list.file == "m.yaml");
  CHECK(list.line == 3);
  CHECK(list.column == 6);
  CHECK(list.path == "c");
  CHECK(list.message == "expected a number or formula, found a list");
  CHECK(r.diagnostics()[1].line == 4);
}

TEST_CASE("a formula naming a failed parameter reports nothing more", "[yaml_reader]") {
  ParameterSet parameters;
  YamlReader r("m.yaml", &parameters);
  r.MarkFailedParameter("span");
  const YAML::Node root = YAML::Load("a: 2 * span\nb: 2 * spanner\n");
  CHECK_FALSE(r.Number(root["a"], "a"));
  CHECK(r.diagnostics().empty());      // span failed at its own line already
  CHECK_FALSE(r.Number(root["b"], "b"));  // spanner is another name: reported
  CHECK(r.diagnostics().size() == 1);
  CHECK(r.NamesFailedParameter("sin(span)/2"));
  CHECK_FALSE(r.NamesFailedParameter("spa + n"));
}

TEST_CASE("counts, points, flags and texts refuse what they are not", "[yaml_reader]") {
  YamlReader r("m.yaml", nullptr);
  const YAML::Node root = YAML::Load("n: 3\nhalf: 2.5\nneg: -1\np: [1, 2]\nq: [1, 2, 3]\nf: yes\ng: maybe\nt: [a, b]\n");
  CHECK(r.Count(root["n"], "n") == 3);
  CHECK_FALSE(r.Count(root["half"], "half"));
  CHECK_FALSE(r.Count(root["neg"], "neg"));
  CHECK(*r.Vector(root["p"], "p") == Eigen::Vector2d(1, 2));
  CHECK_FALSE(r.Vector(root["q"], "q"));
  CHECK(r.Flag(root["f"], "f") == true);
  CHECK_FALSE(r.Flag(root["g"], "g"));
  CHECK(r.TextList(root["t"], "t") == std::vector<std::string>{"a", "b"});
  CHECK_FALSE(r.Text(root["t"], "t"));
  // one report per refusal, in the order made: half, neg, q, g, t (hand count)
  REQUIRE(r.diagnostics().size() == 5);
  CHECK(r.diagnostics()[0].message == "expected a whole number >= 0");
  CHECK(r.diagnostics()[1].path == "neg");
  CHECK(r.diagnostics()[2].message == "expected a point [x, y], found a list");
  CHECK(r.diagnostics()[3].message == "expected true or false, found 'maybe'");
  CHECK(r.diagnostics()[4].message == "expected text, found a list");
}

TEST_CASE("unknown and duplicate keys, required keys, key paths", "[yaml_reader]") {
  YamlReader r("m.yaml", nullptr);
  const YAML::Node root = YAML::Load("links: 1\njionts: 2\nzzz: 3\n");
  r.CheckKeys(root, "", {"links", "joints", "drive"});
  CHECK_FALSE(r.Require(root, "drive", "").IsDefined());
  REQUIRE(r.diagnostics().size() == 3);
  CHECK(r.diagnostics()[0].line == 2);
  CHECK(r.diagnostics()[0].message == "unknown key 'jionts' (did you mean 'joints'?)");  // two edits
  CHECK(r.diagnostics()[1].message == "unknown key 'zzz' (expected one of: links joints drive)");
  CHECK(r.diagnostics()[2].message == "missing required key 'drive'");
  CHECK(r.diagnostics()[2].line == 1);  // at the map
  const YAML::Node twice = YAML::Load("{a: 1, a: 2}");
  YamlReader s("m.yaml", nullptr);
  CHECK(s.Entries(twice, "p").size() == 1);
  REQUIRE(s.diagnostics().size() == 1);
  CHECK(s.diagnostics()[0].message == "duplicate key 'a'");
  CHECK(s.diagnostics()[0].path == "p.a");
  CHECK(Child("", "links") == "links");
  CHECK(Index(Child("joints", "A"), 1) == "joints.A[1]");
}

TEST_CASE("a name is printable UTF-8 of at most kMaxNameBytes; otherwise an error at its key", "[yaml_reader]") {
  YamlReader r("m.yaml", nullptr);
  // markup, quotes, commas, formulas and any script are printable: taken as they are
  const YAML::Node good = YAML::Load("\"s<img src=x onerror=\\\"f()\\\">, <!--<script> =HYPERLINK(1) σ ✓\": 1\n");
  CHECK(r.CheckName(good.begin()->first, "links", "link", good.begin()->first.Scalar()));
  CHECK(r.CheckName(good, "x", "link", std::string(kMaxNameBytes, 'x')));  // the limit itself
  CHECK(r.diagnostics().empty());
  // YAML's escapes \e (ESC) and \0 (NUL) in keys on line 2; the first at column 5 (counted by hand: its opening quote)
  const YAML::Node bad = YAML::Load("a: 1\nb: {\"crank\\e[31m\": 1, \"cr\\0\": 2}\n");
  auto key = bad["b"].begin();
  CHECK_FALSE(r.CheckName(key->first, "links.crank\x1b[31m", "link", key->first.Scalar()));
  ++key;
  CHECK_FALSE(r.CheckName(key->first, "links.cr", "link", key->first.Scalar()));
  CHECK_FALSE(r.CheckName(bad["a"], "outputs.x", "output", std::string(kMaxNameBytes + 1, 'x')));
  CHECK_FALSE(r.CheckName(bad["a"], "drive.name", "drive's input", "Gr\xFC\xDF"));  // Latin-1, not UTF-8
  REQUIRE(r.diagnostics().size() == 4);
  const Diagnostic& esc = r.diagnostics()[0];
  CHECK(esc.line == 2);
  CHECK(esc.column == 5);
  CHECK(esc.message == "the link name 'crank\x1b[31m' holds U+001B at byte 6: a name must be printable UTF-8 text, without control characters");
  // shown to a person with the control character escaped (Diagnostic::ToString)
  CHECK(esc.ToString() ==
        "m.yaml:2:5: the link name 'crank\\x1B[31m' holds U+001B at byte 6: a name must be printable UTF-8 text, without control "
        "characters (links.crank\\x1B[31m)");
  CHECK_THAT(r.diagnostics()[1].message, Catch::Contains("holds U+0000 at byte 3"));
  CHECK(r.diagnostics()[2].message == "the output name is 129 bytes long, more than the limit of 128 (kMaxNameBytes)");
  CHECK_THAT(r.diagnostics()[3].message, Catch::Contains("holds the byte 0xFC (not UTF-8) at byte 3"));
}

TEST_CASE("the nearest candidate is fewer than three edits away", "[yaml_reader]") {
  // reference: Levenshtein distances counted by hand
  CHECK(Nearest("crank", {"crank2", "rocker"}) == "crank2");   // 1 insertion
  CHECK(Nearest("cnrak", {"crank"}) == "crank");               // 2 substitutions
  CHECK(Nearest("abcde", {"vwxyz"}).empty());                  // 5
  CHECK(Nearest("frame", {"frames", "fame"}) == "frames");     // both 1: the first wins
  CHECK(Nearest("xyz", {"xab"}) == "xab");                     // 2 substitutions: still near
  CHECK(Nearest("abc", {"xyz"}).empty());                      // 3: too far
}

TEST_CASE("a missing node reports at the fallback mark", "[yaml_reader]") {
  YamlReader r("m.yaml", nullptr);
  const YAML::Node root = YAML::Load("a: 1\n");
  r.Error(root["missing"], "missing", "no such thing");
  CHECK(r.diagnostics().at(0).line == 0);  // no mark, no fallback: line 0 ("unknown")
  r.set_fallback(root.Mark());
  r.Error(root["missing"], "missing", "no such thing");
  CHECK(r.diagnostics().at(1).line == 1);
}

}  // namespace
}  // namespace koppel::yaml_reader_test
