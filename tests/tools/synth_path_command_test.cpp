// `koppel synth path` end to end with a 10^4-curve atlas built once for the run by `koppel atlas
// build`: the points of a crank-rocker's coupler curve (tests/data/path-points.csv, not in the
// atlas) are matched to 1e-6, the written mechanism file's curve passes them (koppel curve), and
// bad points files name their line.
#include "support/run.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>
#include <Eigen/Core>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace koppel::synth_path_command_test {
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
  CHECK(line == "rank,error,A0_x,A0_y,B0_x,B0_y,crank,coupler,rocker,frame,K_along,K_left,grashof,cognate_of,sse,phi_1,mu_min");
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    rows.emplace_back();
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) rows.back().push_back(cell);
    if (!line.empty() && line.back() == ',') rows.back().emplace_back();
  }
  REQUIRE(rows.size() == 3);
  CHECK(rows[0][0] == "1");
  const double error = std::stod(rows[0][1]);
  CHECK(error <= 1e-6);
  // issue 22 item 15: the three rows were one four-bar; now three designs (pivots or lengths
  // differ by more than the 1e-6 that repeats agree to), a cognate named by the rank it repeats
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = i + 1; j < rows.size(); ++j) {
      double largest = 0;
      for (int c = 2; c <= 9; ++c) largest = std::max(largest, std::abs(std::stod(rows[i][c]) - std::stod(rows[j][c])));
      INFO("rows " << i + 1 << " and " << j + 1);
      CHECK(largest > 1e-6);
    }
  CHECK(rows[0][13].empty());
  // the original and its Roberts cognate on B0, both exact, in the atlas's order: the second
  // named the first's cognate. C0 = A0 + r (B0 - A0), r = (K - A)/(B - A), for the four-bar of
  // the points (A0 (0, 0), A (1, 0.2), B (3.1, 2.4), B0 (4, 0.3), K (2.2, 3.3)) by hand:
  // r = (9.34 + 3.87 i)/9.25, C0 = (3.91341, 1.97643)
  CHECK(rows[1][13] == "1");
  const bool cognate_first = std::abs(std::stod(rows[0][2])) > 1.0;
  const std::vector<std::string>& original = rows[cognate_first ? 1 : 0];
  const std::vector<std::string>& cognate = rows[cognate_first ? 0 : 1];
  CHECK(std::stod(original[2]) == Approx(0.0).margin(1e-5));
  CHECK(std::stod(original[3]) == Approx(0.0).margin(1e-5));
  CHECK(std::stod(cognate[2]) == Approx(3.91341).margin(1e-5));
  CHECK(std::stod(cognate[3]) == Approx(1.97643).margin(1e-5));
  CHECK_THAT(r.err, Catch::Contains("repeats of a better design dropped"));
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

}  // namespace koppel::synth_path_command_test

namespace koppel::synth_path_command_test {

// The ellipse of the path-synthesis literature (tests/data/path-ellipse.csv): without a design
// space the nearest atlas curves fit it exactly with a frame of 862 for points that span 20. With
// the papers' space (every length within [0, 80], both pivots within +-80, a crank input) no
// returned linkage lies outside it: each row's lengths, pivots and Grashof type are checked here
// against the space, from the printed numbers.
TEST_CASE("synth path --design: no linkage outside the design space", "[cli][path]") {
  test::TempDir dir;
  const std::string space = dir.Write("space.yaml", "lengths: [0, 80]\npivots: {x: [-80, 80], y: [-80, 80]}\ninput: crank\n");
  const test::RunResult r =
      test::RunKoppel("synth path " + test::TestDataPath("path-ellipse.csv") + " --atlas " + CiAtlas() + " --top 3 --design " + space);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::istringstream in(r.out);
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "rank,error,A0_x,A0_y,B0_x,B0_y,crank,coupler,rocker,frame,K_along,K_left,grashof,cognate_of,sse,phi_1,mu_min");
  int rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    REQUIRE(cells.size() >= 13);
    INFO(line);
    for (int c = 2; c <= 5; ++c) CHECK(std::abs(std::stod(cells[c])) <= 80 + 1e-9);
    for (int c = 6; c <= 9; ++c) CHECK(std::stod(cells[c]) <= 80 + 1e-9);
    CHECK((cells[12] == "crank-rocker" || cells[12] == "double-crank"));
    CHECK(std::stod(cells[1]) < 0.5);  // RMS in the points' unit: the points span 20
  }
  CHECK(rows >= 1);
  // a space no linkage of the atlas meets: exit 1, naming the constraint the nearest one broke
  const std::string tiny = dir.Write("tiny.yaml", "lengths: [0, 0.001]\n");
  const test::RunResult none = test::RunKoppel("synth path " + test::TestDataPath("path-ellipse.csv") + " --atlas " + CiAtlas() + " --design " + tiny);
  CHECK(none.exit_code == 1);
  CHECK_THAT(none.err, Catch::Contains("inside the design space") && Catch::Contains("lengths: the"));
}

TEST_CASE("synth path --design refuses a bad design file with its line", "[cli][path]") {
  test::TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"lenghts: [0, 80]\n", "lenghts"},
      {"lengths: [80, 0]\n", "an empty interval"},
      {"ratio: 0.5\n", "at least 1"},
      {"lengths: [0, 1e300*1e300]\n", "finite"},
      {"pivots: {x: [0, 1], z: [0, 1]}\n", "'z'"},
      {"input: rocker\n", "expected crank or any"},
  };
  for (const auto& [text, phrase] : cases) {
    const std::string file = dir.Write("design.yaml", text);
    const test::RunResult r = test::RunKoppel("synth path " + test::TestDataPath("path-ellipse.csv") + " --atlas " + CiAtlas() + " --design " + file);
    INFO(text << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("design.yaml:1:") && Catch::Contains(phrase));
  }
}

// --units: every written linkage says the unit; an unknown unit is refused before the search.
TEST_CASE("synth path --units writes the unit into every linkage's file", "[cli][path]") {
  test::TempDir dir;
  const test::RunResult r =
      test::RunKoppel("synth path " + test::TestDataPath("path-points.csv") + " --atlas " + CiAtlas() + " --top 2 --units mm -o " + dir.path().string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) {
    CHECK_THAT(test::ReadText(e.path().string()), Catch::Contains("\nunits: {length: mm}\n"));
    ++files;
  }
  CHECK(files == 2);
  const test::RunResult bad = test::RunKoppel("synth path " + test::TestDataPath("path-points.csv") + " --atlas " + CiAtlas() + " --units furlong");
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.err, Catch::Contains("furlong"));
}

namespace {

// The rows of a synth path table, split at commas.
std::vector<std::vector<std::string>> Rows(const std::string& out) {
  std::istringstream in(out);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    rows.emplace_back();
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) rows.back().push_back(cell);
    if (!line.empty() && line.back() == ',') rows.back().emplace_back();
  }
  return rows;
}

// The sum of the squared distances of the points from the written mechanism's P, read from
// `koppel analyze FILE --at phi` for each prescribed angle: the file's own re-analysis.
double SseOfFile(const std::string& file, const std::vector<Eigen::Vector2d>& points, const std::vector<double>& phi_deg) {
  double sse = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const test::RunResult r = test::RunKoppel("analyze " + file + " --at " + fmt::format("{:.17g}", phi_deg[i]) + " --order 0");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::vector<std::vector<std::string>> rows = Rows(r.out);
    REQUIRE(rows.size() == 1);
    sse += (Eigen::Vector2d(std::stod(rows[0][1]), std::stod(rows[0][2])) - points[i]).squaredNorm();  // phi,P_x,P_y,...
  }
  return sse;
}

}  // namespace

// The five timed points of Kunjur and Krishnamurty (tests/data/benchmarks): A0 at the origin, the
// frame along +x, crank angles 30..90 deg. The points are given to three decimals, so a design
// through the exact curve they were rounded from has an sse of at most 5 * 2 * (5e-4)^2 = 2.5e-6.
TEST_CASE("synth path with a phi column: the five timed points within the data's rounding", "[cli][path][timed]") {
  test::TempDir dir;
  const std::string points = test::TestDataPath("benchmarks/kunjur-5-points.csv");
  const test::RunResult r = test::RunKoppel("synth path " + points + " --design " + test::TestDataPath("benchmarks/kunjur-5-points.yaml") +
                                            " --top 1 -o " + dir.path().string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("timing prescribed") && Catch::Contains("random starts"));
  const auto rows = Rows(r.out);
  REQUIRE(rows.size() == 1);
  const auto& row = rows[0];
  CHECK(std::stod(row[2]) == 0);  // A0_x
  CHECK(std::stod(row[3]) == 0);  // A0_y
  CHECK(std::abs(std::stod(row[5])) <= 1e-12);  // B0_y: the frame along +x
  CHECK(std::stod(row[4]) > 0);
  for (int c = 6; c <= 9; ++c) CHECK(std::stod(row[c]) <= 50);
  CHECK(row[12] == "crank-rocker");
  const double sse = std::stod(row[14]);
  CHECK(sse <= 2.5e-6);
  CHECK(std::stod(row[15]) == 30);  // phi_1: the first prescribed angle
  const std::vector<Eigen::Vector2d> p = {{3, 3}, {2.759, 3.363}, {2.372, 3.663}, {1.890, 3.862}, {1.355, 3.943}};
  CHECK(SseOfFile((dir.path() / "path-1.yaml").string(), p, {30, 45, 60, 75, 90}) == Approx(sse).epsilon(1e-6));
}

// The 18-point closed curve with 20 deg steps (tests/data/benchmarks): every design inside the
// papers' space (lengths <= 50, a crank), its sse recomputed from the written file.
TEST_CASE("synth path --timing-step: the 18-point closed curve inside its design space", "[cli][path][timed]") {
  test::TempDir dir;
  const std::string points = test::TestDataPath("benchmarks/cabrera-18-points.csv");
  const test::RunResult r = test::RunKoppel("synth path " + points + " --timing-step 20 --design " +
                                            test::TestDataPath("benchmarks/cabrera-18-points.yaml") + " --top 2 -o " + dir.path().string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto rows = Rows(r.out);
  REQUIRE(!rows.empty());
  const std::vector<Eigen::Vector2d> p = {{0.5, 1.1}, {0.4, 1.1}, {0.3, 1.1}, {0.2, 1.0}, {0.1, 0.9}, {0.005, 0.75}, {0.02, 0.6}, {0, 0.5}, {0, 0.4},
                                          {0.03, 0.3}, {0.1, 0.25}, {0.15, 0.2}, {0.2, 0.3}, {0.3, 0.4}, {0.4, 0.5}, {0.5, 0.7}, {0.6, 0.9}, {0.6, 1.0}};
  for (size_t i = 0; i < rows.size(); ++i) {
    const auto& row = rows[i];
    for (int c = 2; c <= 5; ++c) CHECK(std::abs(std::stod(row[c])) <= 50);
    for (int c = 6; c <= 9; ++c) CHECK(std::stod(row[c]) <= 50);
    CHECK((row[12] == "crank-rocker" || row[12] == "double-crank"));
    const double sse = std::stod(row[14]), phi_1 = std::stod(row[15]);
    // a fit, not a bystander: the RMS distance below 5 % of the curve's width (about 0.6)
    CHECK(std::stod(row[1]) < 0.03);
    std::vector<double> phi;
    for (int k = 0; k < 18; ++k) phi.push_back(phi_1 + 20 * k);
    CHECK(SseOfFile((dir.path() / fmt::format("path-{}.yaml", i + 1)).string(), p, phi) == Approx(sse).epsilon(1e-6));
  }
}

TEST_CASE("synth path refuses bad timings and a misplaced atlas with their place", "[cli][path][timed]") {
  test::TempDir dir;
  const std::vector<std::pair<std::string, std::string>> files = {
      {"x,y,phi\n0,0,10\n1,0,20\n1,1,20\n0,1,40\n", "points.csv:4:5: phi: 20 deg repeats the angle of line 3"},
      {"x,y,phi\n0,0,10\n1,0,30\n1,1,20\n0,1,40\n", "points.csv:4:5: phi: 20 deg turns back from the angle of line 3"},
      {"x,y,phi\n0,0,10\n1,0,nan\n1,1,20\n0,1,40\n", "points.csv:3:5: expected a finite number, found 'nan'"},
      {"x,y,phi\n0,0,10\n1,0\n1,1,20\n0,1,40\n", "points.csv:3:1: expected three finite numbers x,y,phi"},
      {"x,y,phi\n0,0,0\n1,0,100\n1,1,200\n0,1,360\n", "span 360 deg"},
  };
  for (const auto& [text, phrase] : files) {
    const std::string file = dir.Write("points.csv", text);
    const test::RunResult r = test::RunKoppel("synth path " + file);
    INFO(text << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains(phrase));
  }
  const std::string timed = dir.Write("timed.csv", "x,y,phi\n0,0,10\n1,0,20\n1,1,30\n0,1,40\n");
  const std::string plain = dir.Write("plain.csv", "x,y\n0,0\n1,0\n1,1\n0,1\n");
  const std::vector<std::pair<std::string, std::string>> commands = {
      {timed + " --atlas atlas.bin", "--atlas: not read when the timing is prescribed"},
      {plain + " --timing-step 20 --atlas atlas.bin", "--atlas: not read when the timing is prescribed"},
      {timed + " --timing-step 20", "prescribed twice"},
      {plain + " --timing-step 0", "non-zero"},
      {plain + " --timing-step 120", "spans a turn or more"},
      {plain + " --timing-step 20 --open", "open or closed changes nothing"},
      {plain + " --atlas atlas.bin --starts 10", "--starts: only the global search"},
      {plain + " --candidates 10", "--candidates: atlas curves are searched with --atlas only"},
  };
  for (const auto& [args, phrase] : commands) {
    const test::RunResult r = test::RunKoppel("synth path " + args);
    INFO(args << "\n" << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains(phrase));
  }
  // the design file's keys of a timed search
  const std::vector<std::pair<std::string, std::string>> designs = {
      {"A0: [1]\n", "design.yaml:1:5: expected [x, y] (A0)"},
      {"frame_angle: east\n", "design.yaml:1:"},
      {"coupler_point: [1, -1]\n", "an empty interval"},
      {"A0: [5, 0]\npivots: {x: [-1, 1]}\n", "A0 lies outside pivots.x"},
  };
  for (const auto& [text, phrase] : designs) {
    const std::string file = dir.Write("design.yaml", text);
    const test::RunResult r = test::RunKoppel("synth path " + timed + " --design " + file);
    INFO(text << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains(phrase));
  }
}

// The literature's problems without timing (tests/data/benchmarks), searched globally: six points
// on a line (an open stretch) have exact solutions inside lengths [5, 60]; the ten points of the
// ellipse (the last repeating the first a turn later) fit within lengths [5, 80]. Every design
// inside its space, its sse recomputed from the written file at the crank angles it reports
// (the first from phi_1; the file's sweep passes the rest in order). 1000 starts (a quarter of the
// default) find the ellipse's best design of the default run and exact fits of the six points.
TEST_CASE("synth path without an atlas: the literature's untimed problems inside their spaces", "[cli][path][global]") {
  struct Problem {
    std::string name, flags;
    double lengths;
  };
  for (const Problem& problem : {Problem{"cabrera-6-points", " --open", 60}, Problem{"lin-ellipse-10-points", "", 80}}) {
    test::TempDir dir;
    const test::RunResult r = test::RunKoppel("synth path " + test::TestDataPath("benchmarks/" + problem.name + ".csv") + problem.flags +
                                              " --design " + test::TestDataPath("benchmarks/" + problem.name + ".yaml") + " --top 2 --starts 1000 -o " +
                                              dir.path().string());
    INFO(problem.name << "\n" << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.err, Catch::Contains("timing free"));
    const auto rows = Rows(r.out);
    REQUIRE(!rows.empty());
    for (const auto& row : rows) {
      for (int c = 2; c <= 5; ++c) CHECK(std::abs(std::stod(row[c])) <= problem.lengths);
      for (int c = 6; c <= 9; ++c) {
        CHECK(std::stod(row[c]) <= problem.lengths);
        CHECK(std::stod(row[c]) >= 5);
      }
      CHECK((row[12] == "crank-rocker" || row[12] == "double-crank"));
      // a fit, not a bystander: the RMS distance below 0.1 % of the points' extent (25, 20)
      CHECK(std::stod(row[1]) < 0.02);
    }
    // the first design's P at phi_1 is the first point, within its share of the sse
    const double sse = std::stod(rows[0][14]), phi_1 = std::stod(rows[0][15]);
    const test::RunResult at = test::RunKoppel("analyze " + (dir.path() / "path-1.yaml").string() + " --at " + fmt::format("{:.17g}", phi_1) + " --order 0");
    REQUIRE(at.exit_code == 0);
    const auto p = Rows(at.out);
    const Eigen::Vector2d first = problem.name == "cabrera-6-points" ? Eigen::Vector2d(20, 20) : Eigen::Vector2d(20, 10);
    CHECK((Eigen::Vector2d(std::stod(p[0][1]), std::stod(p[0][2])) - first).squaredNorm() <= sse * (1 + 1e-6) + 1e-20);
  }
}
}  // namespace koppel::synth_path_command_test
