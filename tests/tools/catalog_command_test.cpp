// `koppel catalog list | find | show | check` end to end: the report a person reads, the
// machine formats, lookups by features, class, motion, keyword and chain structure, and a
// catalog with a broken entry that must fail loudly.
#include "support/run.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>

namespace koppel::catalog_command_test {
namespace {

int Lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

// A hand-sketched four-bar with names unlike any entry's: its chain is every four-bar's.
const char* kSketch = R"(name: sketch
links:
  ground: {frame: true, points: {P: [0, 0], Q: [4, 0]}}
  input: {points: {P: [0, 0], R: [1, 0]}}
  middle: {points: {R: [0, 0], T: [3, 0]}}
  output: {points: {Q: [0, 0], T: [3, 0]}}
joints:
  j1: {type: R, links: [middle, output], points: [T, T]}
  j2: {type: R, links: [ground, input], points: [P, P]}
  j3: {type: R, links: [input, middle], points: [R, R]}
  j4: {type: R, links: [output, ground], points: [Q, Q]}
drive: {joint: j2}
)";

}  // namespace

TEST_CASE("catalog check prints one line per entry and a summary", "[cli][catalog]") {
  const test::RunResult r = test::RunKoppel("catalog check");
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::StartsWith("id") && Catch::Contains("worst/tol"));
  CHECK_THAT(r.out, Catch::Contains("\nslider-crank-offset ") && Catch::Contains("passed"));
  CHECK(r.out.find("FAIL") == std::string::npos);
  CHECK_THAT(r.out, Catch::Contains("koppel catalog check: ") && Catch::Contains(" failed; ") && Catch::Contains("checks, 0 failed"));
  const test::RunResult list = test::RunKoppel("catalog list --format csv");
  // header, one line per entry, summary
  CHECK(Lines(r.out) == Lines(list.out) + 1);
}

TEST_CASE("catalog check --verbose and --format csv give every check", "[cli][catalog]") {
  const test::RunResult csv = test::RunKoppel("catalog check slider-crank-offset --format csv");
  REQUIRE(csv.exit_code == 0);
  CHECK_THAT(csv.out, Catch::StartsWith("id,variant,kind,check,status,worst,tolerance,value,at,detail"));
  CHECK(csv.out.find(",FAIL,") == std::string::npos);
  CHECK(Lines(csv.out) > 40);  // seed 000: 44 checks
  CHECK_THAT(csv.err, Catch::Contains("1 entries, 1 passed, 0 failed"));
  const test::RunResult verbose = test::RunKoppel("catalog check slider-crank-offset --verbose");
  REQUIRE(verbose.exit_code == 0);
  CHECK(Lines(verbose.out) > 44);
  CHECK_THAT(verbose.out, Catch::Contains("pass figure 'stroke s_H = 2 l1 (e = 0)' [e=0]"));
  const test::RunResult json = test::RunKoppel("catalog check mzc-crank-rocker --format json");
  CHECK_THAT(json.out, Catch::Contains("\"status\": \"pass\""));
}

TEST_CASE("a broken entry fails check and show with the failing check named", "[cli][catalog]") {
  test::TempDir dir;
  const std::string text = test::ReadText(test::CatalogEntryPath("slider-crank-offset"));
  dir.Write("slider-crank-offset.yaml", test::Replace(text, "expected: 2*l1\n", "expected: 2.1*l1\n"));
  const std::string catalog = "--catalog " + dir.path().string();
  const test::RunResult r = test::RunKoppel("catalog check " + catalog);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.out, Catch::Contains("slider-crank-offset  FAILED"));
  CHECK_THAT(r.out, Catch::Contains("FAIL figure 'stroke s_H = 2 l1 (e = 0)' [e=0]") && Catch::Contains("document 2.1, koppel 2"));
  CHECK_THAT(r.out, Catch::Contains("1 entries, 0 passed, 1 failed"));
  const test::RunResult show = test::RunKoppel("catalog show slider-crank-offset " + catalog);
  CHECK(show.exit_code == 1);
  CHECK_THAT(show.out, Catch::Contains("FAIL [e=0]: koppel 2"));
  // a card that does not read is bad input, with its line
  dir.Write("slider-crank-offset.yaml", test::Replace(text, "quantity: stroke\n", "quantity: strok\n"));
  const test::RunResult bad = test::RunKoppel("catalog check " + catalog);
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.err, Catch::Contains("slider-crank-offset.yaml:" + std::to_string(test::LineOf(test::Replace(text, "quantity: stroke\n", "quantity: strok\n"), "quantity: strok\n")) + ":"));
  CHECK_THAT(bad.err, Catch::Contains("unknown quantity 'strok'"));
}

TEST_CASE("catalog find by features, ranges, kind, class, motion and keyword", "[cli][catalog]") {
  const test::RunResult f = test::RunKoppel("catalog find --links 6 --ternary 2 --revolute 4 --prismatic 3 --drives-at-frame 1 --format csv");
  REQUIRE(f.exit_code == 0);
  CHECK_THAT(f.out, Catch::Contains("\nproportional-linkage,"));
  const test::RunResult range = test::RunKoppel("catalog find --links 3..4 --prismatic 0 --format json");
  REQUIRE(range.exit_code == 0);
  CHECK_THAT(range.out, Catch::Contains("\"mzc-crank-rocker\""));
  CHECK(range.out.find("proportional-linkage") == std::string::npos);
  const test::RunResult table = test::RunKoppel("catalog find --class watt-six-bar");
  REQUIRE(table.exit_code == 0);
  CHECK_THAT(table.out, Catch::StartsWith("id ") && Catch::Contains("\nproportional-linkage "));
  CHECK(table.out.find("mzc-crank-rocker") == std::string::npos);
  const test::RunResult motion = test::RunKoppel("catalog find --motion 'rotation -> oscillating translation' --format csv");
  CHECK_THAT(motion.out, Catch::Contains("\nslider-crank-offset,"));
  CHECK(motion.out.find("mzc-crank-rocker") == std::string::npos);
  const test::RunResult keyword = test::RunKoppel("catalog find --keyword Schubkurbel --format csv");
  CHECK_THAT(keyword.out, Catch::Contains("\nslider-crank-offset,"));
  const test::RunResult guidance = test::RunKoppel("catalog find --kind guidance --format csv");
  CHECK_THAT(guidance.out, Catch::Contains("\nmzc-crank-rocker,"));
  CHECK(guidance.out.find("slider-crank-offset") == std::string::npos);
  CHECK(test::RunKoppel("catalog find --links six").exit_code == 2);
  CHECK(test::RunKoppel("catalog find --kind other").exit_code == 2);
  CHECK(test::RunKoppel("catalog find --class crank_rocker").exit_code == 2);
  // a class word that several classes hold: they are suggested first
  const test::RunResult straight = test::RunKoppel("catalog find --class straight-line");
  CHECK(straight.exit_code == 2);
  CHECK_THAT(straight.err, Catch::Contains("did you mean 'straight-line-approximate' or 'straight-line-exact'?"));
  CHECK_THAT(test::RunKoppel("catalog find --class quick-retrun").err, Catch::Contains("did you mean 'quick-return'?"));
  CHECK(test::RunKoppel("catalog list --format xml").exit_code == 2);
}

TEST_CASE("catalog find --like finds the entries with the sketch's chain, joint types respected", "[cli][catalog]") {
  test::TempDir dir;
  const std::string four_bar = dir.Write("sketch.yaml", kSketch);
  const test::RunResult r = test::RunKoppel("catalog find --like " + four_bar + " --format csv");
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::Contains("\nmzc-crank-rocker,") && Catch::Contains("\ndeadcentre-crank-rocker,"));
  CHECK(r.out.find("slider-crank-offset") == std::string::npos);
  // one joint made prismatic: the slider-crank chain, no four-bar
  const std::string slider = dir.Write("slider.yaml", test::Replace(test::Replace(kSketch, "j4: {type: R, links: [output, ground], points: [Q, Q]}",
                                                                                  "j4: {type: P, links: [ground, output], points: [Q, Q], axis: [1, 0]}"),
                                                                    "  output: {points: {Q: [0, 0], T: [3, 0]}}", "  output: {points: {Q: [0, 0], T: [0, 0]}}"));
  const test::RunResult s = test::RunKoppel("catalog find --like " + slider + " --format csv");
  REQUIRE(s.exit_code == 0);
  CHECK_THAT(s.out, Catch::Contains("\nslider-crank-offset,"));
  CHECK(s.out.find("mzc-crank-rocker") == std::string::npos);
  CHECK(test::RunKoppel("catalog find --like /nonexistent/sketch.yaml").exit_code == 2);
}

TEST_CASE("catalog page draws every entry and carries the search module or says it does not", "[cli][catalog]") {
  test::TempDir dir;
  const std::string html = (dir.path() / "catalog.html").string();
  const test::RunResult page = test::RunKoppel("catalog page -o " + html);
  INFO(page.err);
  const std::string text = test::ReadText(html);
  // the ids as catalog list prints them (the reference), each a card with its scheme
  const test::RunResult list = test::RunKoppel("catalog list --format csv");
  std::istringstream rows(list.out);
  std::string row;
  std::getline(rows, row);  // header
  int entries = 0;
  while (std::getline(rows, row)) {
    const std::string id = row.substr(0, row.find(','));
    INFO(id);
    const size_t card = text.find("<section class=\"entry\" id=\"" + id + "\">");
    REQUIRE(card != std::string::npos);
    CHECK(text.find("<svg", card) < text.find("</section>", card));
    ++entries;
  }
  CHECK(entries > 30);
  // with the module the page is whole (exit 0); without it (a build without em++) exit 1 and a word why
  const bool search = text.find("KoppelSearch") != std::string::npos && text.find("koppel_search_score") != std::string::npos;
  CHECK(page.exit_code == (search ? 0 : 1));
  if (!search) CHECK_THAT(page.err, Catch::Contains("no search box"));
}

TEST_CASE("catalog list and show", "[cli][catalog]") {
  const test::RunResult list = test::RunKoppel("catalog list");
  CHECK_THAT(list.out, Catch::Contains("slider-crank-offset") && Catch::Contains("mzc-crank-rocker") && Catch::Contains(" entries\n"));
  const test::RunResult show = test::RunKoppel("catalog show proportional-linkage");
  REQUIRE(show.exit_code == 0);
  CHECK_THAT(show.out, Catch::Contains("S34: S slot-block4") && Catch::Contains("4 binary, 2 ternary") &&
                           Catch::Contains("Waagrechtstoßmaschine") && Catch::Contains("Figures") && Catch::Contains("Literature") &&
                           Catch::Contains("pass: koppel"));
  const test::RunResult json = test::RunKoppel("catalog show slider-crank-offset --format json");
  REQUIRE(json.exit_code == 0);
  CHECK_THAT(json.out, Catch::Contains("\"passed\": true") && Catch::Contains("\"printed\""));
  // the page with its scheme and the plot of its output, written atomically to a file
  test::TempDir dir;
  const std::string html = (dir.path() / "page.html").string();
  const test::RunResult page = test::RunKoppel("catalog show jansen-linkage --format html -o " + html);
  INFO(page.err);
  REQUIRE(page.exit_code == 0);
  const std::string text = test::ReadText(html);
  CHECK_THAT(text, Catch::StartsWith("<!DOCTYPE html>") && Catch::Contains("Jansen-Bein (Strandbeest)") && Catch::Contains("output link (Abtrieb): foot (output &apos;F&apos;)"));
  // the card's text is escaped as XML (plot::EscapeXml, one escaper for SVG and HTML): ' too
  CHECK(text.find("output 'F'") == std::string::npos);
  CHECK(std::count(text.begin(), text.end(), '\n') > 50);
  size_t svgs = 0;
  for (size_t at = text.find("<svg"); at != std::string::npos; at = text.find("<svg", at + 1)) ++svgs;
  CHECK(svgs == 2);  // the scheme and the foot's path
  CHECK(test::RunKoppel("catalog show jansen-linkage --format csv").exit_code == 2);
  const test::RunResult missing = test::RunKoppel("catalog show nothing-like-this");
  CHECK(missing.exit_code == 2);
  CHECK_THAT(missing.err, Catch::Contains("no catalog entry"));
}

}  // namespace koppel::catalog_command_test
