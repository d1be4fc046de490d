// `koppel synth path` end to end with a 10^4-curve atlas built once for the run by `koppel atlas
// build`: the points of a crank-rocker's coupler curve (tests/data/path-points.csv, not in the
// atlas) are matched to 1e-6, the written mechanism file's curve passes them (koppel curve), and
// bad points files name their line.
#include "support/run.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

namespace koppel {
namespace {

const std::string& CiAtlas() {
  static test::TempDir dir;
  static const std::string path = [] {
    const std::string p = (dir.path() / "atlas.bin").string();
    REQUIRE(test::RunKoppel("atlas build --count 10000 --quiet -o " + p).exit_code == 0);
    return p;
  }();
  return path;
}

}  // namespace

TEST_CASE("synth path matches a crank-rocker's curve from the CI atlas", "[cli][path]") {
  test::TempDir dir;
  const test::RunResult r = test::RunKoppel("synth path " + test::TestDataPath("path-points.csv") + " --atlas " + CiAtlas() + " --top 3 -o " + dir.path().string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::istringstream in(r.out);
  std::string line;
  std::getline(in, line);
  CHECK(line == "rank,error,A0_x,A0_y,B0_x,B0_y,crank,coupler,rocker,frame,K_along,K_left,grashof");
  std::getline(in, line);
  CHECK(line.rfind("1,", 0) == 0);
  const double error = std::stod(line.substr(2, line.find(',', 2) - 2));
  CHECK(error <= 1e-6);
  // the written mechanism's coupler point passes the first point at its assembly (the file's first sample)
  const test::RunResult curve = test::RunKoppel("curve " + (dir.path() / "path-1.yaml").string() + " --point P --step 1");
  INFO(curve.err);
  CHECK(curve.exit_code == 0);
}

TEST_CASE("synth path refuses bad points files", "[cli][path]") {
  test::TempDir dir;
  const test::RunResult header = test::RunKoppel("synth path " + dir.Write("p.csv", "a,b\n1,2\n") + " --atlas " + CiAtlas());
  CHECK(header.exit_code == 2);
  CHECK_THAT(header.err, Catch::Contains("p.csv:1:"));
  const test::RunResult bad = test::RunKoppel("synth path " + dir.Write("q.csv", "x,y\n1,2\n3,four\n5,6\n7,8\n") + " --atlas " + CiAtlas());
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.err, Catch::Contains("q.csv:3:"));
  const test::RunResult few = test::RunKoppel("synth path " + dir.Write("r.csv", "x,y\n1,2\n3,4\n") + " --atlas " + CiAtlas());
  CHECK(few.exit_code == 2);
  CHECK(test::RunKoppel("synth path " + test::TestDataPath("path-points.csv") + " --atlas " + dir.Write("a.bin", "nope")).exit_code == 2);
}

}  // namespace koppel
