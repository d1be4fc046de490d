// Every writer of a file (a DXF drawing, a GIF animation, an SVG picture, the two pages) writes
// the same bytes from the same input, run after run: a drawing under version control changes only
// where the mechanism did. (DXF's DIMSTYLE handle came out different from run to run while the
// text style was named `standard`.) The reference is the first run's bytes; the inputs are a
// catalog entry, the file of hostile names and an engine slider-crank.
#include "support/run.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace koppel::reproducible_outputs_test {

TEST_CASE("the same input writes the same bytes: DXF, GIF, SVG and pages", "[cli][reproducible]") {
  test::TempDir dir;
  // each with a transmission angle among its outputs (plot --mu)
  const std::vector<std::string> files = {test::CatalogEntryPath("mzc-crank-rocker"), test::TestDataPath("hostile-names.yaml"),
                                          test::CatalogEntryPath("engine-slider-crank")};
  // each writer as a command without its -o, and the extension of what it writes
  const std::vector<std::pair<std::string, std::string>> writers = {
      {"export {} --dxf", "dxf"},           {"animate {} --frames 6 --size 160x120", "gif"},
      {"draw {}", "svg"},                   {"draw {} --deadcentres", "svg"},
      {"plot {} --mu", "svg"},              {"view {}", "html"},
      {"edit {}", "html"},
  };
  for (const std::string& file : files) {
    for (const auto& [pattern, extension] : writers) {
      std::string command = pattern;
      command.replace(command.find("{}"), 2, file);
      const std::string a = (dir.path() / ("a." + extension)).string(), b = (dir.path() / ("b." + extension)).string();
      const test::RunResult first = test::RunKoppel(command + " -o " + a);
      // a checked build has no editor page (its WebAssembly is built in the Release build only)
      if (first.exit_code == 1 && first.err.find("built without emscripten") != std::string::npos) continue;
      const test::RunResult second = test::RunKoppel(command + " -o " + b);
      INFO(command << "\n" << first.err);
      // a writer may end partial (exit 1) where the file's range has gaps: the bytes still agree
      REQUIRE(first.exit_code <= 1);
      REQUIRE(second.exit_code == first.exit_code);
      const std::string bytes = test::ReadText(a);
      CHECK(bytes.size() > 100);
      CHECK(bytes == test::ReadText(b));
    }
  }
}

}  // namespace koppel::reproducible_outputs_test
