// A mechanism file parsed once and evaluated with overrides: the reference is ReadMechanismFile,
// which reads the file anew each time; the source must give the same mechanism without the file.
#include "koppel/catalog/mechanism_source.hpp"

#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>

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

}  // namespace
}  // namespace koppel::mechanism_source_test
