// A mechanism file parsed once and evaluated with overrides: the reference is ReadMechanismFile,
// which reads the file anew each time; the source must give the same mechanism without the file.
#include "koppel/catalog/mechanism_source.hpp"
#include "koppel/catalog/catalog.hpp"
#include "koppel/catalog/mechanism_writer.hpp"

#include "support/seeds.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <random>
#include <utility>

namespace koppel::mechanism_source_test {
namespace {

// Every point of every link and every parameter: exactly equal, as the same text is evaluated.
void CheckSame(const MechanismFile& a, const MechanismFile& b) {
  CHECK(a.path == b.path);
  CHECK(a.parameters.Values() == b.parameters.Values());
  REQUIRE(a.mechanism.links.size() == b.mechanism.links.size());
  for (size_t l = 0; l < a.mechanism.links.size(); ++l) {
    REQUIRE(a.mechanism.links[l].points.size() == b.mechanism.links[l].points.size());
    for (size_t p = 0; p < a.mechanism.links[l].points.size(); ++p) {
      CHECK(a.mechanism.links[l].points[p].local == b.mechanism.links[l].points[p].local);
    }
  }
}

double Parameter(const MechanismFile& f, const std::string& name) {
  for (const auto& [n, v] : f.parameters.Values()) {
    if (n == name) return v;
  }
  FAIL("no parameter " << name);
  return 0;
}

TEST_CASE("a source evaluates as ReadMechanismFile reads, with and without overrides", "[source]") {
  const std::string path = test::CatalogEntryPath("slider-crank-offset");
  const MechanismSource source = MechanismSource::Read(path);
  CHECK(source.path() == path);
  CheckSame(source.Evaluate(), ReadMechanismFile(path));
  CheckSame(source.Evaluate({{"e", "0.3"}}), ReadMechanismFile(path, {{"e", "0.3"}}));
  CHECK(Parameter(source.Evaluate({{"e", "l1/2"}}), "e") == 0.5);
}

TEST_CASE("read and evaluated at once, a source gives what Read and Evaluate give, and evaluates again alike", "[source]") {
  const std::string path = test::CatalogEntryPath("slider-crank-offset");
  MechanismFile evaluated;
  const MechanismSource source = MechanismSource::Read(path, {{"e", "l1/4"}}, &evaluated);
  CHECK(source.path() == path);
  CheckSame(evaluated, ReadMechanismFile(path, {{"e", "l1/4"}}));
  CHECK(Parameter(evaluated, "e") == 0.25);
  CheckSame(source.Evaluate(), ReadMechanismFile(path));
  CHECK(source.text() == MechanismSource::Read(path).text());
  const std::string text = test::ReadText(path);
  MechanismFile parsed;
  CHECK(MechanismSource::Parse(text, "given.yaml", {}, &parsed).path() == "given.yaml");
  CHECK(parsed.path == "given.yaml");
  CheckSame(parsed, MechanismSource::Parse(text, "given.yaml").Evaluate());
}

TEST_CASE("read and evaluated at once, text that is no YAML and an override that does not evaluate are refused", "[source]") {
  MechanismFile evaluated;
  CHECK_THROWS_AS(MechanismSource::Parse("name: x\nlinks: [\n", "given.yaml", {}, &evaluated), InputError);
  try {
    MechanismSource::Read(test::CatalogEntryPath("slider-crank-offset"), {{"nosuch", "1"}}, &evaluated);
    FAIL("an unknown parameter was accepted");
  } catch (const InputError& e) {
    CHECK(e.diagnostics().at(0).file == test::CatalogEntryPath("slider-crank-offset"));
  }
}

TEST_CASE("a source needs its file no more once read: it is not read again", "[source]") {
  test::TempDir dir;
  const std::string path = dir.Write("m.yaml", test::ReadText(test::CatalogEntryPath("slider-crank-offset")));
  const MechanismSource source = MechanismSource::Read(path);
  std::filesystem::remove(path);
  CHECK(Parameter(source.Evaluate({{"e", "0.25"}}), "e") == 0.25);
}

TEST_CASE("an override that does not evaluate names the file; the source stays usable", "[source]") {
  const MechanismSource source = MechanismSource::Read(test::CatalogEntryPath("slider-crank-offset"));
  try {
    source.Evaluate({{"nosuch", "1"}});
    FAIL("an unknown parameter was accepted");
  } catch (const InputError& e) {
    CHECK(e.diagnostics().at(0).file == source.path());
  }
  CHECK(Parameter(source.Evaluate(), "e") == 0.8);
  // a catalog id resolves to the entry's file, as ReadMechanismFile resolves it
  CHECK(MechanismSource::Read("slider-crank-offset").path() == ReadMechanismFile("slider-crank-offset").path);
}

TEST_CASE("a text source names the given file in messages", "[source]") {
  const std::string text = test::ReadText(test::CatalogEntryPath("slider-crank-offset"));
  CHECK(MechanismSource::Parse(text, "given.yaml").Evaluate().path == "given.yaml");
  try {
    MechanismSource::Parse("name: x\nlinks: [\n", "given.yaml");
    FAIL("text that is no YAML was parsed");
  } catch (const InputError& e) {
    CHECK(e.diagnostics().at(0).file == "given.yaml");
  }
}

// The 1-based line of the first occurrence of `fragment` in `text`: the reference for a message's line.
int LineOf(const std::string& text, const std::string& fragment) {
  const size_t at = text.find(fragment);
  REQUIRE(at != std::string::npos);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

// Issue 25: a source is read for its mechanism (koppel::Model: analyze, curve ...): its card is
// the catalog commands' to read (CardReading), and its YAML is not parsed where BlankCard
// (card_text.hpp) can blank it. The reference: the whole text read by ParseMechanismText, which
// the catalog reads with and which refuses the card's problems at their lines.
TEST_CASE("a source does not read the card; the catalog's reading refuses its problems", "[source][card]") {
  const std::string good = test::ReadText(test::CatalogEntryPath("crank-rocker"));
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"K1: d/a", "K1: d/(a"},
                                 {"  kind: transfer", "  knd: transfer"},
                                 {"quantity: time_ratio", "quantity: time_ration"}}) {
    const std::string broken = test::Replace(good, from, to);
    REQUIRE(broken != good);
    INFO(to);
    MechanismFile evaluated;
    MechanismSource::Parse(broken, "broken.yaml", {}, &evaluated);
    CheckSame(evaluated, ParseMechanismText(good, "broken.yaml"));
    CHECK_FALSE(evaluated.card.has_value());
    CheckSame(MechanismSource::Parse(broken, "broken.yaml").Evaluate({{"a", "1.25"}}), ParseMechanismText(good, "broken.yaml", {{"a", "1.25"}}));
    try {
      ParseMechanismText(broken, "broken.yaml");
      FAIL("the catalog's reading accepted the card");
    } catch (const InputError& e) {
      REQUIRE_FALSE(e.diagnostics().empty());  // a broken `where` name: then the names that use it
      CHECK(e.diagnostics()[0].line == LineOf(broken, to));
    }
  }
}

// The whole text's YAML read without its card: the reference for what the source reads.
MechanismFile WholeText(const std::string& text) { return ParseMechanismText(text, "t.yaml", {}, CardReading::kSkipped); }

// The blanked card is not parsed at all: YAML that does not parse in it (a second `:` in a plain
// scalar) leaves the source's reading alone, while the catalog's reading refuses it at its line.
TEST_CASE("a plain card's YAML is not parsed by the source", "[source][card]") {
  const std::string good = test::ReadText(test::CatalogEntryPath("crank-rocker"));
  const std::string broken = test::Replace(good, "    en: Crank-rocker\n", "    en: Crank-rocker: the four-bar\n");
  REQUIRE(broken != good);
  MechanismFile evaluated;
  MechanismSource::Parse(broken, "broken.yaml", {}, &evaluated);
  CheckSame(evaluated, ParseMechanismText(good, "broken.yaml"));
  try {
    ParseMechanismText(broken, "broken.yaml");
    FAIL("yaml-cpp parsed a plain scalar with a second ': '");
  } catch (const InputError& e) {
    CHECK(e.diagnostics().at(0).line == LineOf(broken, "    en: Crank-rocker: the"));
    CHECK_THAT(e.diagnostics().at(0).message, Catch::Contains("YAML syntax error"));
  }
}

// What the source reads of a mechanism, compared field by field with the whole text's reading.
void CheckSameReading(const std::string& text) {
  MechanismFile alone;
  MechanismSource::Parse(text, "t.yaml", {}, &alone);
  const MechanismFile whole = WholeText(text);
  CheckSame(alone, whole);
  CHECK(alone.mechanism.hint.input == whole.mechanism.hint.input);
  CHECK(alone.title == whole.title);
  CHECK(alone.description == whole.description);
  CHECK(alone.sweep.from == whole.sweep.from);
  CHECK(alone.sweep.to == whole.sweep.to);
  CHECK(alone.formulas == whole.formulas);
}

TEST_CASE("the source reads the mechanism the whole text holds, however the card is written", "[source][card]") {
  const std::string good = test::ReadText(test::CatalogEntryPath("crank-rocker"));
  const std::string card = good.substr(good.find("\ncatalog:\n") + 1);
  const std::string mechanism = good.substr(0, good.find("\ncatalog:\n") + 1);
  CheckSameReading(good);
  // the card first, then the mechanism's keys after it
  CheckSameReading(test::Replace(mechanism, "sweep: {from: 0, to: 360, step: 1}\n", "") + card + "sweep: {from: 0, to: 90, step: 2}\n");
  // yaml-cpp lets a quoted scalar run on at column 0: here the card's note holds the `assembly`
  // and `sweep` lines, which the whole text's reading does not see as keys
  const std::string run_on = test::Replace(test::Replace(mechanism, "assembly:\n  input: 90\n  points: {B: [3.5, 3]}\n", ""),
                                           "sweep: {from: 0, to: 360, step: 1}\n", "") +
                             "catalog:\n  title: \"a card\nassembly: {input: 270}\nsweep: {from: 0, to: 90, step: 2}\"\n";
  CheckSameReading(run_on);
  CHECK(WholeText(run_on).sweep.to == 360);  // the default: the sweep line is the title's
  // the text before the card leaves its quote open: the card's lines belong to the title
  CheckSameReading(test::Replace(mechanism, "title: Crank-rocker\n", "") + "title: \"open\ncatalog:\n  x\"\n");
  CHECK(WholeText(test::Replace(mechanism, "title: Crank-rocker\n", "") + "title: \"open\ncatalog:\n  x\"\n").title == "open catalog: x");
}

// Everything a reading gives of the mechanism, as one text: the writer's YAML (geometry, drive,
// outputs, hint, sweep, parameters, loads) and the file's title, description and formulas.
std::string Everything(const MechanismFile& f) {
  std::string text = WriteMechanismYaml(f.mechanism, f.title, f.sweep, f.parameters.Values(), &f.loads) + f.description;
  for (const auto& [path, formula] : f.formulas) text += "\n" + path + "=" + formula;
  return text;
}

// Every catalog entry with quotes, brackets, tags, comments and top-level keys typed in at random
// places, the card's lines among them: wherever the source and the whole text's reading both
// read a mechanism, it is the same one (the danger BlankCard guards against: a key of the whole
// text lost, or a line of the card's taken for a key). Fixed seed; which readings fail is not
// asserted (a broken card fails only the whole text's).
TEST_CASE("with random edits, the source reads what the whole text holds wherever both read", "[source][card]") {
  const std::vector<std::string> edits = {"\"", "'", "[", "]", "{", "}", "\n", " #", "!!str\"", "\t", ": ", "\n  ", "\n---\n",
                                          "\nsweep: {from: 0, to: 90, step: 2}\n", "\nassembly: {input: 270}\n", "\ncatalog:\n"};
  std::mt19937 random(25);
  int both = 0;
  for (const std::string& id : CatalogIds(test::CatalogEntryPath("crank-rocker").substr(0, test::CatalogEntryPath("crank-rocker").rfind('/')))) {
    const std::string good = test::ReadText(test::CatalogEntryPath(id));
    for (int trial = 0; trial < test::SeedCount(80); ++trial) {
      std::string text = good;
      for (int k = 0; k < 1 + trial % 2; ++k) {
        const size_t at = std::uniform_int_distribution<size_t>(0, text.size())(random);
        text.insert(at, edits[std::uniform_int_distribution<size_t>(0, edits.size() - 1)(random)]);
      }
      std::optional<MechanismFile> alone, whole;
      try {
        MechanismFile f;
        MechanismSource::Parse(text, "t.yaml", {}, &f);
        alone = std::move(f);
      } catch (const InputError&) {
      }
      try {
        whole = WholeText(text);
      } catch (const InputError&) {
      }
      if (!alone || !whole) continue;
      ++both;
      INFO(id << " edited:\n" << text);
      CHECK(Everything(*alone) == Everything(*whole));
    }
  }
  CHECK(both > 10 * test::SeedCount(80));  // enough edits leave a file both read (a test that compares nothing proves nothing)
}

}  // namespace
}  // namespace koppel::mechanism_source_test
