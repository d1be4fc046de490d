// A catalog id where a mechanism file is expected (issue 22, item 9): every command that reads a
// mechanism reads the catalog entry for its id (ResolveMechanismName, catalog.hpp), with the same
// output as for the entry's file (the reference); a file of that name in the working directory
// wins; a mistyped id says which id it may have meant (item 10), in one line.
#include "support/run.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace koppel::catalog_id_test {
namespace {

// `koppel ARGUMENTS` run in `folder` (not the source tree): exit code and stdout.
test::RunResult RunIn(const test::TempDir& folder, const std::string& arguments) {
  const std::string out = (folder.path() / ".out").string(), err = (folder.path() / ".err").string();
  const std::string command = "cd " + folder.path().string() + " && " + KOPPEL_EXECUTABLE + " " + arguments + " > " + out + " 2> " + err + " < /dev/null";
  const int status = std::system(command.c_str());
  test::RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = test::ReadText(out);
  r.err = test::ReadText(err);
  return r;
}

int Lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

}  // namespace

TEST_CASE("every command takes a catalog id for a mechanism file (issue 22, item 9)", "[cli][catalog]") {
  test::TempDir here;
  struct Use {
    std::string command, id, rest;
  };
  // the tables: equal to the same command on the entry's file
  const std::vector<Use> tables = {
      {"analyze", "crank-rocker", "--step 30"},
      {"analyze", "triple-rocker", "--from -100 --to 100 --step 50 --format json"},
      {"deadcentres", "slider-crank-offset", "--output s --summary"},
      {"curve", "mzc-crank-rocker", "--point K --step 30"},
      {"proportional", "proportional-linkage", "--output s --from 112.5 --to 247.5"},
      {"cognates", "mzc-crank-rocker", "--point K -o cognates"},
      {"range", "crank-rocker", "--all-branches"},
      {"classify", "crank-rocker", ""},
  };
  for (const Use& u : tables) {
    INFO(u.command << " " << u.id << " " << u.rest);
    const test::RunResult by_id = RunIn(here, u.command + " " + u.id + " " + u.rest);
    const test::RunResult by_file = RunIn(here, u.command + " " + test::CatalogEntryPath(u.id) + " " + u.rest);
    INFO(by_id.err);
    CHECK(by_id.exit_code == 0);  // was 2: "cannot open file"
    CHECK(by_id.exit_code == by_file.exit_code);
    CHECK(!by_id.out.empty());
    CHECK(by_id.out == by_file.out);
  }
  // the pictures and files: written, as for the file
  const std::vector<Use> pictures = {
      {"plot", "slider-crank-offset", "--mu -o mu.svg"},
      {"draw", "slider-crank-offset", "--at 120 -o scheme.svg"},
      {"export", "mzc-crank-rocker", "--dxf --at 30 -o m.dxf"},
      {"animate", "mzc-crank-rocker", "--frames 4 --size 64x48 -o m.gif"},
  };
  for (const Use& u : pictures) {
    INFO(u.command << " " << u.id << " " << u.rest);
    const test::RunResult by_id = RunIn(here, u.command + " " + u.id + " " + u.rest);
    INFO(by_id.err);
    CHECK(by_id.exit_code == 0);
  }
  CHECK(std::filesystem::file_size(here.path() / "mu.svg") > 1000);
  CHECK(std::filesystem::file_size(here.path() / "m.gif") > 100);
  // catalog find --like an id: the entries with its chain, itself among them
  const test::RunResult like = RunIn(here, "catalog find --like crank-rocker --format csv");
  CHECK(like.exit_code == 0);
  CHECK_THAT(like.out, Catch::Contains("\ncrank-rocker,") && Catch::Contains("\ndouble-rocker,"));
}

TEST_CASE("a file named like an id wins over the catalog entry", "[cli][catalog]") {
  test::TempDir here;
  // a slider-crank saved as ./crank-rocker: its s column, not the catalog's four-bar
  here.Write("crank-rocker", test::ReadText(test::CatalogEntryPath("slider-crank-offset")));
  const test::RunResult r = RunIn(here, "analyze crank-rocker --step 90");
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.out == RunIn(here, "analyze " + test::CatalogEntryPath("slider-crank-offset") + " --step 90").out);
}

TEST_CASE("a mistyped id is one line naming the nearest id (issue 22, item 10)", "[cli][catalog]") {
  test::TempDir here;
  const test::RunResult show = RunIn(here, "catalog show crank-roker");
  CHECK(show.exit_code == 2);
  // was: every one of the 33 ids
  CHECK(show.err == "koppel: no catalog entry 'crank-roker' (did you mean 'crank-rocker'?)\n");
  const test::RunResult check = RunIn(here, "catalog check slider-crank-ofset");
  CHECK(check.exit_code == 2);
  CHECK_THAT(check.err, Catch::Contains("did you mean 'slider-crank-offset'?"));
  CHECK(Lines(check.err) == 1);
  const test::RunResult far = RunIn(here, "catalog show no-such-mechanism");
  CHECK(far.exit_code == 2);
  CHECK(Lines(far.err) == 1);
  CHECK_THAT(far.err, Catch::Contains("koppel catalog list"));
  // where a file is expected: the file is missing and the id is near one
  const test::RunResult analyze = RunIn(here, "analyze crank-roker");
  CHECK(analyze.exit_code == 2);
  CHECK_THAT(analyze.err, Catch::Contains("crank-roker: cannot open file") && Catch::Contains("did you mean 'crank-rocker'?"));
  // a path is a path: no catalog look-up, the reader's message alone
  const test::RunResult path = RunIn(here, "analyze ./crank-roker.yaml");
  CHECK(path.exit_code == 2);
  CHECK(path.err.find("catalog") == std::string::npos);
}

}  // namespace koppel::catalog_id_test
