// koppel plot, draw and view run as a user would: pictures for the seed mechanisms (a slider
// mechanism and the six-link among them) and a user's file, partial pictures with exit code 1,
// bad input with exit code 2. The SVGs are read with an XML parser (tests/tools/plot/svg_reading.hpp).
#include "support/run.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"
#include "tools/plot/scheme_reading.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>

namespace koppel::plot_command_test {
namespace {

pugi::xml_document Svg(const std::string& path) {
  REQUIRE(std::filesystem::exists(path));
  return test::ParseSvg(test::ReadText(path));
}

// `text` as one shell word: in single quotes, a quote in it as '\''
std::string ShellWord(const std::string& text) {
  std::string word = "'";
  for (char c : text) word += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return word + "'";
}

// Every text and attribute value of the document, as an XML parser reads them.
std::vector<std::string> Strings(const pugi::xml_node& root) {
  std::vector<std::string> all;
  for (const pugi::xpath_node& x : root.select_nodes("//node()")) {
    const pugi::xml_node n = x.node();
    if (n.type() == pugi::node_pcdata) all.emplace_back(n.value());
    for (const pugi::xml_attribute& a : n.attributes()) all.emplace_back(a.value());
  }
  return all;
}

}  // namespace

TEST_CASE("plot --transfer / --mu / --curve for the seed mechanisms", "[cli]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "p.svg").string();
  // seed 000 (slider), seed 001 (six links, three sliders), seed 003 (point output)
  for (const char* id : {"slider-crank-offset", "proportional-linkage"}) {
    INFO(id);
    const test::RunResult r = test::RunKoppel(std::string("plot ") + test::CatalogEntryPath(id) + " --transfer s --order 2 -o " + out);
    REQUIRE(r.exit_code == 0);
    const auto doc = Svg(out);
    CHECK(test::Find(doc, "g", "panel").size() == 3);
    for (const auto& panel : test::Find(doc, "g", "panel")) CHECK(test::Find(panel, "path", "curve").size() == 1);
  }
  REQUIRE(test::RunKoppel("plot " + test::CatalogEntryPath("mzc-crank-rocker") + " --transfer K --order 1 -o " + out).exit_code == 0);
  CHECK(test::Find(Svg(out), "path", "curve").size() == 4);  // K_x, K_y in two panels
  REQUIRE(test::RunKoppel("plot " + test::CatalogEntryPath("slider-crank-offset") + " --mu -o " + out).exit_code == 0);
  CHECK(test::Find(Svg(out), "g", "minimum").size() == 1);
  REQUIRE(test::RunKoppel("plot " + test::CatalogEntryPath("mzc-crank-rocker") + " --curve K --straight --at 180 -o " + out).exit_code == 0);
  CHECK(test::Find(Svg(out), "polygon", "band").size() == 1);
  // the proportional linkage has no transmission angle: bad input, no file
  std::filesystem::remove(out);
  const test::RunResult none = test::RunKoppel("plot " + test::CatalogEntryPath("proportional-linkage") + " --mu -o " + out);
  CHECK(none.exit_code == 2);
  CHECK_THAT(none.err, Catch::Contains("no transmission-angle output"));
  CHECK_FALSE(std::filesystem::exists(out));
  CHECK(test::RunKoppel("plot " + test::CatalogEntryPath("slider-crank-offset") + " --transfer nope").exit_code == 2);
  CHECK(test::RunKoppel("plot " + test::CatalogEntryPath("slider-crank-offset")).exit_code == 2);
  CHECK(test::RunKoppel("plot " + test::CatalogEntryPath("slider-crank-offset") + " --mu --transfer s").exit_code == 2);
}

TEST_CASE("plot of a sweep that stops: the picture is written, exit code 1", "[cli]") {
  // a user's file: the slider-crank with l2 - l1 < e cannot turn fully
  test::TempDir dir;
  const std::string text = test::Replace(test::Replace(test::ReadText(test::CatalogEntryPath("slider-crank-offset")), "l2: 2.6", "l2: 1.5"),
                                         "input: 0\n  points: {B: [2, 0]}", "input: 180\n  points: {B: [1.5, 0]}");
  const std::string file = dir.Write("limited.yaml", text), out = (dir.path() / "t.svg").string();
  const test::RunResult r = test::RunKoppel("plot " + file + " --transfer s --from 90 --to 360 -o " + out);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("limit point"));
  const auto doc = Svg(out);
  CHECK(test::Find(doc, "rect", "gap").size() == 3);  // shaded in each panel
  CHECK(test::RunKoppel("draw " + file + " --at 200 --from 90 --to 360 -o " + out).exit_code == 1);
  CHECK(test::Find(Svg(out), "g", "link").size() == 3);
}

TEST_CASE("plot of a design chart from synth chart", "[cli]") {
  test::TempDir dir;
  const std::string csv = (dir.path() / "chart.csv").string(), out = (dir.path() / "chart.svg").string();
  REQUIRE(test::RunKoppel("synth chart slider-crank --phi0 110:130:10 --quiet -o " + csv).exit_code == 0);
  REQUIRE(test::RunKoppel("plot " + csv + " -o " + out).exit_code == 0);
  CHECK(test::Find(Svg(out), "g", "panel").size() == 2);
  const std::string bad = dir.Write("bad.csv", "phi0,psi0\n1,2\n");
  const test::RunResult r = test::RunKoppel("plot " + bad + " -o " + out);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("bad.csv:1:"));
}

TEST_CASE("draw: scheme, dead centres and trace for the seed mechanisms", "[cli]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "s.svg").string();
  const test::RunResult r = test::RunKoppel("draw " + test::CatalogEntryPath("slider-crank-offset") + " --at 120 --deadcentres -o " + out);
  REQUIRE(r.exit_code == 0);
  auto doc = Svg(out);
  CHECK(test::Find(doc, "g", "overlay").size() == 2);
  CHECK_THAT(std::string(test::Find(doc, "text", "caption")[0].child_value()), Catch::Contains("φ_a = 102.84°") && Catch::Contains("φ_i = 300.00°"));
  // issue 22 item 15: "B" and "B_a" printed on top of each other, F without its guide line
  test::CheckLabelsLegible(doc);
  CHECK(test::Find(doc, "line", "guide-axis").size() == 1);
  REQUIRE(test::RunKoppel("draw " + test::CatalogEntryPath("proportional-linkage") + " --at 150 -o " + out).exit_code == 0);
  doc = Svg(out);
  CHECK(test::Find(doc, "g", "link").size() == 5);
  CHECK(test::Find(doc, "polygon", "block").size() == 3);
  REQUIRE(test::RunKoppel("draw " + test::CatalogEntryPath("mzc-crank-rocker") + " --trace K -o " + out).exit_code == 0);
  CHECK(test::Subpaths(test::Find(Svg(out), "path", "trace").at(0)).at(0).size() == 361);  // the file's sweep: 0..360 by 1
  CHECK(test::RunKoppel("draw " + test::CatalogEntryPath("mzc-crank-rocker") + " --trace Q").exit_code == 2);
}

TEST_CASE("draw and plot of tests/data/hostile-names.yaml: well-formed SVG, the names as text", "[cli]") {
  // the names hold quotes, commas, markup and formulas; reference: the fixture's names as pugixml
  // reads them back, and no element their markup would make (img, script)
  const std::string file = std::string(KOPPEL_TEST_DATA_DIR) + "/hostile-names.yaml";
  const std::string img = "<img src=x onerror=\"document.title+='[X]'\">";
  const std::string s = "s, mm " + img, k = "+K <svg onload=\"document.title+='[X]'\">";
  test::TempDir dir;
  const std::string out = (dir.path() / "h.svg").string();
  for (const std::string& command : {"draw " + file + " --at 30 --deadcentres --trace " + ShellWord(k), "plot " + file + " --transfer " + ShellWord(s),
                                     "plot " + file + " --curve " + ShellWord(k)}) {
    INFO(command);
    const test::RunResult r = test::RunKoppel(command + " -o " + out);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const auto doc = Svg(out);
    CHECK(test::Find(doc, "img", "").empty());
    CHECK(test::Find(doc, "script", "").empty());
    const std::vector<std::string> strings = Strings(doc);
    const auto holds = [&](const std::string& name) {
      return std::any_of(strings.begin(), strings.end(), [&](const std::string& t) { return t.find(name) != std::string::npos; });
    };
    if (command.rfind("draw", 0) == 0) {
      for (const std::string link : {"=HYPERLINK(\"http://x\",\"crank\")", "coupler <img src=x onerror=alert(1)>", "Schieber σ ✓"})
        CHECK(holds(link));
      CHECK(holds("A, \"Ä\""));  // a point's label
    } else {
      // the transfer plot names the output; the coupler curve the point it traces (the crank's @K)
      CHECK(holds(command.find("--transfer") != std::string::npos ? s : "@K"));
    }
  }
}

TEST_CASE("view writes one self-contained page", "[cli]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "m.html").string();
  REQUIRE(test::RunKoppel("view " + test::CatalogEntryPath("proportional-linkage") + " -o " + out).exit_code == 0);
  const std::string page = test::ReadText(out);
  CHECK(page.size() < 300 * 1024);
  CHECK_THAT(page, Catch::Contains("<svg") && Catch::Contains("The MIT License") && Catch::Contains("id=\"koppel-data\""));
  // nothing to fetch: no src= or href= attributes at all
  CHECK(page.find(" src=") == std::string::npos);
  CHECK(page.find(" href=") == std::string::npos);
}

// The editor page (its numbers are checked in a browser by tests/tools/edit/editor_page_test.mjs).
TEST_CASE("edit writes one self-contained editor page, or says that this build has none", "[cli]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "editor.html").string();
  const test::RunResult r = test::RunKoppel("edit " + test::CatalogEntryPath("slider-crank-offset") + " --set e=0.3 -o " + out);
  if (r.exit_code == 1 && r.err.find("built without emscripten") != std::string::npos) {
    WARN("this build has no editor page (no em++)");
  } else {
    REQUIRE(r.exit_code == 0);
    const std::string page = test::ReadText(out);
    // the document with the override as the formula of e, the module, math.js with its licence
    CHECK_THAT(page, Catch::Contains("id=\"koppel-document\"") && Catch::Contains("\"formula\":\"0.3\"") &&
                         Catch::Contains("KoppelModule") && Catch::Contains("Apache License"));
    CHECK(page.find(" href=") == std::string::npos);  // nothing to fetch
    // a file that does not assemble as given: the page is written (its sliders can fix it), exit 1
    const test::RunResult bad = test::RunKoppel("edit " + test::CatalogEntryPath("slider-crank-offset") + " --set e=9 -o " + out);
    CHECK(bad.exit_code == 1);
    CHECK_THAT(bad.err, Catch::Contains("the page says so"));
  }
  // bad input as every command: an unknown parameter, a file that is not there
  CHECK(test::RunKoppel("edit " + test::CatalogEntryPath("slider-crank-offset") + " --set nope=1 -o " + out).exit_code == 2);
  CHECK(test::RunKoppel("edit no-such-file.yaml -o " + out).exit_code == 2);
}

// The axes say the file's length unit: the compressor in mm labels s [mm] and s' [mm/rad], never
// "[length]"; a file without units keeps "[length]".
TEST_CASE("plot --transfer labels lengths with the file's unit", "[cli][plot]") {
  test::TempDir dir;
  const std::string mm = (dir.path() / "mm.svg").string(), plain = (dir.path() / "plain.svg").string();
  REQUIRE(test::RunKoppel("plot " + test::TestDataPath("slider-crank-loads.yaml") + " --transfer s -o " + mm).exit_code == 0);
  CHECK_THAT(test::ReadText(mm), Catch::Contains("[mm]") && Catch::Contains("[mm/rad]") && !Catch::Contains("length"));
  REQUIRE(test::RunKoppel("plot " + test::CatalogEntryPath("slider-crank-offset") + " --transfer s -o " + plain).exit_code == 0);
  CHECK_THAT(test::ReadText(plain), Catch::Contains("[length]"));
}
}  // namespace koppel::plot_command_test
