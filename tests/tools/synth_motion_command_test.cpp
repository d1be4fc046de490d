// `koppel synth motion` end to end on poses of a known crank-rocker's coupler (tests/data/
// motion-*-poses.yaml, read off koppel's sweep of A0 (0, 0), A (1, 0.2), B (3.1, 2.4),
// B0 (4, 0.3)): the known four-bar is among the rows, every written mechanism file analyses
// through the poses again (koppel analyze), and bad requests exit 2.
#include "support/run.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>
#include <Eigen/Core>

#include <cmath>
#include <filesystem>
#include <sstream>

namespace koppel::synth_motion_command_test {
namespace {

constexpr double kRecovered = 1e-9;

struct Row {
  std::vector<double> numbers;  // the eight coordinates
  std::string grashof;
  int branch_defect = 0, order_defect = 0;
  double mu_min = 0;
};

std::vector<Row> Rows(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "A0_x,A0_y,A_x,A_y,B_x,B_y,B0_x,B0_y,grashof,branch_defect,order_defect,mu_min");
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::string cell;
    Row r;
    for (int i = 0; i < 8 && std::getline(cells, cell, ','); ++i) r.numbers.push_back(std::stod(cell));
    std::getline(cells, r.grashof, ',');
    std::getline(cells, cell, ',');
    r.branch_defect = std::stoi(cell);
    std::getline(cells, cell, ',');
    r.order_defect = std::stoi(cell);
    std::getline(cells, cell, ',');
    r.mu_min = std::stod(cell);
    rows.push_back(r);
  }
  return rows;
}

bool IsKnown(const Row& r) {
  const double known[] = {0, 0, 1, 0.2, 3.1, 2.4, 4, 0.3};
  for (int i = 0; i < 8; ++i)
    if (std::abs(r.numbers[i] - known[i]) > kRecovered) return false;
  return true;
}

}  // namespace

TEST_CASE("synth motion recovers the known four-bar from 3, 4 and 5 poses", "[cli][motion]") {
  const std::string three = test::TestDataPath("motion-three-poses.yaml"), four = test::TestDataPath("motion-four-poses.yaml"),
                    five = test::TestDataPath("motion-five-poses.yaml");
  for (const std::string& request : {three + " --circle-point 1,0.2 --circle-point 3.1,2.4", four + " --circle-point 1,0.2 --circle-point 3.1,2.4", five}) {
    INFO(request);
    const test::RunResult r = test::RunKoppel("synth motion " + request);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::vector<Row> rows = Rows(r.out);
    int known = 0;
    for (size_t i = 0; i < rows.size(); ++i) {
      // the defect-free first, each part sorted by mu_min
      const bool free = rows[i].branch_defect == 0 && rows[i].order_defect == 0;
      if (i > 0) {
        const bool before = rows[i - 1].branch_defect == 0 && rows[i - 1].order_defect == 0;
        CHECK((before || !free));
        if (before == free) CHECK(rows[i].mu_min <= rows[i - 1].mu_min);
      }
      if (!IsKnown(rows[i])) continue;
      ++known;
      CHECK(rows[i].grashof == "crank-rocker");
      CHECK(rows[i].branch_defect == 0);
      CHECK(rows[i].order_defect == 0);
    }
    CHECK(known == 1);
  }
}

// A user's three poses on a 10 x 10 grid of circle points: 9 874 rows by mu_min put the first
// defect-free design at rank 58, and 26 four-bars that failed their re-analysis made it exit 1.
// Now the defect-free come first, the counts are said, and it exits 0.
TEST_CASE("synth motion lists the four-bars without a defect first and counts the rest", "[cli][motion]") {
  test::TempDir dir;
  const std::string poses = dir.Write("poses.yaml", "poses: [[0, 0, 0], [1.5, 1.0, 30], [3, 0.5, 80]]\n");
  const test::RunResult r = test::RunKoppel("synth motion " + poses + " --grid 6 --require crank");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("candidate four-bars:") && Catch::Contains("without a defect") &&
                        Catch::Contains("with a branch or order defect") && Catch::Contains("failed their re-analysis"));
  const std::vector<Row> rows = Rows(r.out);
  REQUIRE(!rows.empty());
  CHECK(rows.front().branch_defect == 0);
  CHECK(rows.front().order_defect == 0);
  bool defective = false;
  for (const Row& row : rows) {
    const bool free = row.branch_defect == 0 && row.order_defect == 0;
    if (!free) defective = true;
    if (defective) CHECK_FALSE(free);  // no defect-free row after a defective one
  }
}

TEST_CASE("synth motion -o writes mechanism files whose coupler meets the poses again", "[cli][motion]") {
  test::TempDir dir;
  const test::RunResult r = test::RunKoppel("synth motion " + test::TestDataPath("motion-five-poses.yaml") + " --require crank -o " + dir.path().string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const std::vector<Row> rows = Rows(r.out);
  REQUIRE(!rows.empty());
  for (size_t i = 0; i < rows.size(); ++i) {
    const std::string file = (dir.path() / ("four-bar-" + std::to_string(i + 1) + ".yaml")).string();
    // the file reads back and turns fully (--require crank)
    const test::RunResult c = test::RunKoppel("classify " + file);
    INFO(c.out << c.err);
    CHECK(c.exit_code == 0);
    CHECK_THAT(c.out, Catch::Contains(rows[i].grashof));
  }
}

TEST_CASE("synth motion: four poses write the Burmester curves", "[cli][motion]") {
  test::TempDir dir;
  const std::string curves = (dir.path() / "curves.csv").string();
  const test::RunResult r = test::RunKoppel("synth motion " + test::TestDataPath("motion-four-poses.yaml") + " --samples 6 --top 3 --curves " + curves);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(Rows(r.out).size() <= 3);
  const std::string text = test::ReadText(curves);
  CHECK(text.rfind("direction,centre_x,centre_y,circle_x,circle_y\n", 0) == 0);
  CHECK(std::count(text.begin(), text.end(), '\n') > 360);
}

TEST_CASE("synth motion refuses bad requests", "[cli][motion]") {
  test::TempDir dir;
  const std::string three = test::TestDataPath("motion-three-poses.yaml");
  CHECK(test::RunKoppel("synth motion " + three).exit_code == 2);  // no circle point, no grid
  CHECK(test::RunKoppel("synth motion " + three + " --circle-point 1").exit_code == 2);
  CHECK(test::RunKoppel("synth motion " + three + " --grid 3 --require rocker").exit_code == 2);
  const test::RunResult six = test::RunKoppel("synth motion " + dir.Write("six.yaml", "poses: [[0,0,0],[1,0,1],[2,0,2],[3,0,3],[4,0,4],[5,0,5]]\n"));
  CHECK(six.exit_code == 2);
  CHECK_THAT(six.err, Catch::Contains("six.yaml:1:8") && Catch::Contains("2 to 5 poses"));
  const test::RunResult bad = test::RunKoppel("synth motion " + dir.Write("bad.yaml", "poses:\n  - [0, 0, 0]\n  - [1, 0]\n"));
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.err, Catch::Contains("bad.yaml:3:") && Catch::Contains("[x, y, angle_deg]"));
  // a circle point off the circle-point curve of four poses has no centre point
  const test::RunResult off = test::RunKoppel("synth motion " + test::TestDataPath("motion-four-poses.yaml") + " --circle-point 0.5,0.5");
  CHECK(off.exit_code == 1);
  CHECK_THAT(off.err, Catch::Contains("not on the circle-point curve"));
}

// --units: every written four-bar says the unit (and reads back in it); an unknown unit is refused
// before the search, nothing written.
TEST_CASE("synth motion --units writes the unit into every four-bar's file", "[cli][motion]") {
  test::TempDir dir;
  const test::RunResult r =
      test::RunKoppel("synth motion " + test::TestDataPath("motion-five-poses.yaml") + " --require crank --units cm -o " + dir.path().string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) {
    CHECK_THAT(test::ReadText(e.path().string()), Catch::Contains("\nunits: {length: cm}\n"));
    CHECK_THAT(test::RunKoppel("analyze " + e.path().string() + " --step 30 --format json").out, Catch::Contains("\"cm\""));
    ++files;
  }
  CHECK(files > 0);
  test::TempDir none;
  const test::RunResult bad = test::RunKoppel("synth motion " + test::TestDataPath("motion-five-poses.yaml") + " --units furlong -o " + none.path().string());
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.err, Catch::Contains("furlong"));
  CHECK(std::filesystem::is_empty(none.path()));
}

// --design: the three poses of the user's report with a 10 x 10 grid of circle points, within a
// design space of links at most 3 long and a transmission angle of at least 60 deg: every listed
// four-bar meets it, read from the printed pivots and circle points (the lengths) and mu_min;
// stderr counts those left out. A space nothing meets exits 1 naming the constraint.
TEST_CASE("synth motion --design: every listed four-bar inside the space", "[cli][motion]") {
  test::TempDir dir;
  const std::string space = dir.Write("space.yaml", "mu_min: 60\nlengths: [0, 3]\n");
  const test::RunResult r = test::RunKoppel("synth motion " + test::TestDataPath("motion-three-poses.yaml") + " --grid 10 --design " + space);
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("four-bars outside the design space left out"));
  std::istringstream in(r.out);
  std::string line;
  std::getline(in, line);
  int rows = 0;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) v.push_back(cell.empty() || std::isalpha(static_cast<unsigned char>(cell[0])) ? 0 : std::stod(cell));
    REQUIRE(v.size() == 12);
    INFO(line);
    const Eigen::Vector2d a0(v[0], v[1]), a(v[2], v[3]), b(v[4], v[5]), b0(v[6], v[7]);
    for (double length : {(a - a0).norm(), (b - a).norm(), (b0 - b).norm(), (b0 - a0).norm()}) CHECK(length <= 3 + 1e-9);
    CHECK(v[11] >= 60 - 1e-6);
    ++rows;
  }
  CHECK(rows > 0);
  const std::string tight = dir.Write("tight.yaml", "lengths: [0, 0.01]\n");
  const test::RunResult none = test::RunKoppel("synth motion " + test::TestDataPath("motion-three-poses.yaml") + " --grid 10 --design " + tight);
  CHECK(none.exit_code == 1);
  CHECK_THAT(none.err, Catch::Contains("inside the design space") && Catch::Contains("lengths: the"));
  const std::string bad = dir.Write("bad.yaml", "mu_min: 95\n");
  const test::RunResult refused = test::RunKoppel("synth motion " + test::TestDataPath("motion-three-poses.yaml") + " --grid 10 --design " + bad);
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.err, Catch::Contains("bad.yaml:1:") && Catch::Contains("below 90 deg"));
  // a fixed A0 is kept by synth path's global search only: refused here, not ignored
  const test::RunResult a0 = test::RunKoppel("synth motion " + test::TestDataPath("motion-three-poses.yaml") + " --grid 10 --design " +
                                             dir.Write("a0.yaml", "A0: [0, 0]\n"));
  CHECK(a0.exit_code == 2);
  CHECK_THAT(a0.err, Catch::Contains("A0: synth motion places its frame itself"));
}
}  // namespace koppel::synth_motion_command_test
