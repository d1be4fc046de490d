// `koppel analyze` end to end: the catalog files print their tables, the columns are the
// interface scripts rely on, bad input exits 2 with file:line, a stopped sweep exits 1.
#include "support/run.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <sys/wait.h>

namespace koppel::analyze_command_test {
namespace {

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<double> Numbers(const std::string& line) {
  std::vector<double> v;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) v.push_back(std::stod(cell));
  return v;
}

}  // namespace

TEST_CASE("analyze prints the documented columns for the three catalog files", "[cli]") {
  const test::RunResult sc = test::RunKoppel("analyze " + test::CatalogEntryPath("slider-crank-offset"));
  REQUIRE(sc.exit_code == 0);
  const auto lines = Lines(sc.out);
  REQUIRE(lines.size() == 362);  // header + 0..360 step 1
  CHECK(lines[0] == "phi,s,s_d1,s_d2,mu,mu_d1,mu_d2,singular");
  // row phi = 0 (e = 0.8): s = l1 (sin 0 + cos psi / lambda), sin psi = -(lambda + eps) (seed 000)
  const auto row0 = Numbers(lines[1]);
  CHECK(row0[0] == 0.0);
  CHECK(row0[1] == Approx(2.6 * std::sqrt(1 - std::pow(1.8 / 2.6, 2))).epsilon(1e-11));
  // mu printed in degrees: mu(0) = 90 - asin(1.8/2.6) in degrees
  CHECK(row0[4] == Approx(90 - std::asin(1.8 / 2.6) * 180 / M_PI).epsilon(1e-11));

  const test::RunResult k = test::RunKoppel("analyze " + test::CatalogEntryPath("mzc-crank-rocker") + " --step 90 --order 3");
  REQUIRE(k.exit_code == 0);
  CHECK(Lines(k.out)[0].rfind("phi,K_x,K_x_d1,K_x_d2,K_x_d3,K_y,K_y_d1,K_y_d2,K_y_d3,", 0) == 0);
  const test::RunResult p = test::RunKoppel("analyze " + test::CatalogEntryPath("proportional-linkage") + " --from 180 --to 180");
  REQUIRE(p.exit_code == 0);
  const auto prow = Numbers(Lines(p.out).at(1));
  CHECK(prow[1] == Approx(0.0).margin(1e-12));  // s(180) = 0
  CHECK(prow[2] == Approx(0.5 * 1.83 * (-1 - 0.5) / (1.5 * 1.5)).epsilon(1e-11));  // s'(180), seed 001
}

TEST_CASE("analyze --set, --format json and -o", "[cli]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "t.json").string();
  const test::RunResult r = test::RunKoppel("analyze " + test::CatalogEntryPath("slider-crank-offset") +
                                            " --set e=0 --from 90 --to 90 --format json -o " + out);
  REQUIRE(r.exit_code == 0);
  const std::string json = test::ReadText(out);
  CHECK_THAT(json, Catch::Contains("\"complete\": true"));
  CHECK_THAT(json, Catch::Contains("\"unit\": \"deg\""));
  CHECK_THAT(json, Catch::Contains("3.6"));  // e = 0, phi = 90 deg: s = l1 + l2 (extended)
}

TEST_CASE("analyze --set of a parameter that no formula reads exits 2 naming it and the ones read", "[cli]") {
  // watt-six-bar's psi1_a is read only by its catalog card's checks, never by the mechanism
  const std::string watt = test::CatalogEntryPath("watt-six-bar");
  const test::RunResult r = test::RunKoppel("analyze " + watt + " --step 90 --set psi1_a=1");
  CHECK(r.exit_code == 2);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Catch::Contains("--set psi1_a") && Catch::Contains("no formula of this file reads the parameter 'psi1_a'") &&
                        Catch::Contains("the parameters read: a1 b1 c1 d1"));
  CHECK(test::RunKoppel("analyze " + watt + " --step 90 --set a1=1.01").exit_code == 0);
}

TEST_CASE("analyze: bad input exits 2 naming file and line; nothing is written", "[cli]") {
  test::TempDir dir;
  std::string text = test::ReadText(test::CatalogEntryPath("slider-crank-offset"));
  text.replace(text.find("{type: R, links: [crank, coupler]}"), 34, "{type: X, links: [crank, coupler]}");
  const std::string bad = dir.Write("bad.yaml", text);
  const std::string out = (dir.path() / "never.csv").string();
  const test::RunResult r = test::RunKoppel("analyze " + bad + " -o " + out);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("bad.yaml:") && Catch::Contains("unknown type 'X'"));
  CHECK(r.out.empty());
  CHECK_FALSE(std::filesystem::exists(out));
  CHECK(test::RunKoppel("analyze " + test::CatalogEntryPath("slider-crank-offset") + " --set nope=1").exit_code == 2);
  CHECK(test::RunKoppel("analyze " + test::CatalogEntryPath("slider-crank-offset") + " --step 0").exit_code == 2);
  CHECK(test::RunKoppel("analyze " + test::CatalogEntryPath("slider-crank-offset") + " --from 1/0").exit_code == 2);
  CHECK(test::RunKoppel("analyze /nonexistent.yaml").exit_code == 2);
  CHECK(test::RunKoppel("analyze").exit_code == 2);  // missing argument: usage error
}

TEST_CASE("analyze: a sweep through a dead centre of the drive stops with exit 1 and says where", "[cli]") {
  test::TempDir dir;
  std::string text = test::ReadText(test::CatalogEntryPath("mzc-crank-rocker"));
  // drive the rocker instead of the crank; assemble at rocker angle 110 deg with B above A0B0
  text.replace(text.find("  joint: A0\n"), 12, "  joint: B0\n");
  text.replace(text.find("  input: 180\n"), 13, "  input: 110\n");
  const std::string file = dir.Write("rocker.yaml", text);
  const test::RunResult r = test::RunKoppel("analyze " + file + " --from 110 --to 180");
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("singular") && Catch::Contains("133.0795"));
  CHECK(Lines(r.out).size() == 25);  // header + 110 .. 133 deg: the rows that exist, no NaN
  CHECK(r.out.find("nan") == std::string::npos);
}

TEST_CASE("analyze -o writes, piece by piece, the very bytes it prints, every cell in printf's %.12g", "[cli]") {
  test::TempDir dir;
  const std::string out = (dir.path() / "long.csv").string();
  // 36 001 rows, about 3.5 MB: several of the 1 MB pieces the file is written in
  const std::string args = "analyze " + test::CatalogEntryPath("slider-crank-offset") + " --from 0 --to 360 --step 0.01";
  const test::RunResult to_file = test::RunKoppel(args + " -o " + out), printed = test::RunKoppel(args);
  REQUIRE(to_file.exit_code == 0);
  REQUIRE(printed.exit_code == 0);
  const std::string text = test::ReadText(out);
  CHECK(text.size() > 3'000'000);
  CHECK(text == printed.out);
  std::vector<std::string> listing;
  for (const auto& item : std::filesystem::directory_iterator(dir.path())) listing.push_back(item.path().filename().string());
  CHECK(listing == std::vector<std::string>{"long.csv"});  // no temporary left
  // the reference: the C library's printf of the number each cell reads as
  const std::vector<std::string> lines = Lines(text);
  REQUIRE(lines.size() == 36002);
  int cells = 0, differ = 0;
  for (size_t i = 1; i < lines.size(); ++i) {
    std::istringstream row(lines[i]);
    for (std::string cell; std::getline(row, cell, ',');) {
      char reference[32];
      std::snprintf(reference, sizeof reference, "%.12g", std::stod(cell));
      ++cells;
      if (cell != reference && cell != "0" && ++differ <= 3) FAIL_CHECK("row " << i << ": " << cell << " is " << reference << " in %.12g");
    }
  }
  CHECK(cells == 36001 * 8);
  CHECK(differ == 0);
}

TEST_CASE("analyze -o of a stopped sweep writes the rows it reached, as it prints them", "[cli]") {
  test::TempDir dir;
  std::string text = test::ReadText(test::CatalogEntryPath("mzc-crank-rocker"));
  text.replace(text.find("  joint: A0\n"), 12, "  joint: B0\n");  // the rocker drives: a dead centre at 133 deg
  text.replace(text.find("  input: 180\n"), 13, "  input: 110\n");
  const std::string file = dir.Write("rocker.yaml", text), out = (dir.path() / "rows.csv").string();
  const test::RunResult to_file = test::RunKoppel("analyze " + file + " --from 110 --to 180 -o " + out);
  const test::RunResult printed = test::RunKoppel("analyze " + file + " --from 110 --to 180");
  CHECK(to_file.exit_code == 1);
  CHECK(printed.exit_code == 1);
  CHECK(Lines(test::ReadText(out)).size() == 25);
  CHECK(test::ReadText(out) == printed.out);
}

TEST_CASE("--help teaches", "[cli]") {
  const test::RunResult r = test::RunKoppel("analyze --help");
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::Contains("NAME_d1") && Catch::Contains("degrees") && Catch::Contains("Example"));
}

}  // namespace koppel::analyze_command_test

namespace koppel::analyze_command_test {

// `koppel` run with the dynamic loader's LD_DEBUG=files: its stderr names every library the
// process maps, at start or later (dlopen).
// (as test::RunKoppel, the variable set for koppel alone, not for the shell that starts it)
test::RunResult RunTracingLibraries(const std::string& arguments) {
  test::TempDir dir;
  const std::string out = (dir.path() / "out").string(), err = (dir.path() / "err").string();
  const int status = std::system(("LD_DEBUG=files " + std::string(KOPPEL_EXECUTABLE) + " " + arguments + " > " + out + " 2> " + err + " < /dev/null").c_str());
  test::RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = test::ReadText(out);
  r.err = test::ReadText(err);
  return r;
}

// Issue 25: analyze reads a file for its mechanism; a catalog card's formulas are parsed by the
// catalog's commands (CardFormulas, koppel/catalog/mechanism_file.hpp). The references: the
// table of the unbroken entry, and the loader's own list of what it mapped.
TEST_CASE("analyze leaves a card's formulas to catalog check, and maps muparser only for a formula of the mechanism", "[cli]") {
  test::TempDir dir;
  const std::string good = test::ReadText(test::CatalogEntryPath("crank-rocker"));
  const std::string broken = test::Replace(good, "K1: d/a", "K1: d/(a");
  REQUIRE(broken != good);
  const std::string path = dir.Write("crank-rocker.yaml", broken);
  const test::RunResult reference = test::RunKoppel("analyze " + test::CatalogEntryPath("crank-rocker"));
  REQUIRE(reference.exit_code == 0);
  const test::RunResult analyzed = RunTracingLibraries("analyze " + path);
  CHECK(analyzed.exit_code == 0);
  CHECK(analyzed.out == reference.out);
  CHECK(analyzed.err.find("libstdc++") != std::string::npos);  // the trace is there
  CHECK(analyzed.err.find("libkoppel_muparser") == std::string::npos);
  CHECK(analyzed.err.find("libgomp") == std::string::npos);
  // the catalog's check refuses the card, at the formula's line
  const int line = 1 + static_cast<int>(std::count(broken.begin(), broken.begin() + static_cast<std::ptrdiff_t>(broken.find("K1: d/(a")), '\n'));
  const test::RunResult checked = test::RunKoppel("catalog check --catalog " + dir.path().string() + " crank-rocker");
  CHECK(checked.exit_code == 2);
  CHECK_THAT(checked.err, Catch::Contains("crank-rocker.yaml:" + std::to_string(line) + ":") && Catch::Contains("does not parse"));
  // a formula in the mechanism part maps muparser, with libgomp: the trace would show it
  const std::string formula = dir.Write("formula.yaml", test::Replace(good, "  a: 1 ", "  a: 2/2 "));
  REQUIRE(test::ReadText(formula) != good);
  const test::RunResult with_formula = RunTracingLibraries("analyze " + formula);
  CHECK(with_formula.exit_code == 0);
  CHECK(with_formula.out == reference.out);
  CHECK(with_formula.err.find("libkoppel_muparser") != std::string::npos);
}

}  // namespace koppel::analyze_command_test

namespace koppel::analyze_command_test {
namespace {

// The rocker angle [deg] of the four-bar A0 = 0, B0 = (d, 0) at crank angle phi [deg] on the
// branch with B left (side +1) or right (-1) of A -> B0: the circle intersection, far from flat
// at the rows it is used for (an independent reference).
double FourBarPsi(double a, double b, double c, double d, double phi_deg, int side) {
  const double phi = phi_deg * M_PI / 180, ax = a * std::cos(phi), ay = a * std::sin(phi);
  const double rx = d - ax, ry = -ay, rho = std::hypot(rx, ry);
  const double x = (b * b - c * c + rho * rho) / (2 * rho), h = side * std::sqrt(b * b - x * x);
  const double bx = ax + (x * rx - h * ry) / rho, by = ay + (x * ry + h * rx) / rho;
  double psi = std::atan2(by, bx - d) * 180 / M_PI;
  return psi < 0 ? psi + 360 : psi;
}

double DegreeDifference(double x, double y) { return std::remainder(x - y, 360.0); }

}  // namespace

// A linkage a hair from its change point passes the other branch at 3.5e-4 rad: a step of 45 deg
// jumped onto it and called the jump a branch point (rows off by up to pi, exit 0).
TEST_CASE("a crank-rocker Grashof by 5e-8 turns on its own branch at every step, without a branch point", "[cli]") {
  const std::string file = test::TestDataPath("near-change-point.yaml");
  for (const char* step : {"45", "7", "1", "90"}) {
    const test::RunResult r = test::RunKoppel("analyze " + file + " --step " + step + " --order 0");
    INFO("--step " << step << "\n" << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.find("branch point") == std::string::npos);
    const auto lines = Lines(r.out);
    REQUIRE(lines.size() >= 3);
    // the assembly's branch: B above A -> B0 at the hint (phi = 90 deg, the crank at 93 deg)
    for (size_t i = 1; i < lines.size(); ++i) {
      const auto row = Numbers(lines[i]);
      INFO("phi = " << row[0]);
      CHECK(std::abs(DegreeDifference(row[1], FourBarPsi(1, 2.00000005, 3, 4, row[0] + 3, 1))) < 1e-7);
    }
    if (Numbers(lines.back())[0] == 360) CHECK(Numbers(lines.back())[1] == Approx(Numbers(lines[1])[1]).margin(1e-9));  // psi(360) = psi(0)
  }
  // the figure: psi(270) on the mechanism's branch
  const test::RunResult r = test::RunKoppel("analyze " + file + " --step 45 --order 0 --from 270 --to 270");
  REQUIRE(r.exit_code == 0);
  CHECK(Numbers(Lines(r.out).at(1))[1] == Approx(166.241394675).margin(1e-8));
}

TEST_CASE("a four-bar 1.25e-5 from its folded change point: no false branch point, no false gap with --at-branch-point stop",
          "[cli]") {
  const std::string file = test::TestDataPath("near-change-point-folded.yaml");
  const test::RunResult r = test::RunKoppel("analyze " + file + " --step 45 --order 0 --at-branch-point stop");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("branch point") == std::string::npos);
  const auto lines = Lines(r.out);
  REQUIRE(lines.size() == 10);  // 0, 45, ..., 360
  for (size_t i = 1; i < lines.size(); ++i) {
    const auto row = Numbers(lines[i]);
    CHECK(std::abs(DegreeDifference(row[1], FourBarPsi(1, 4.99995, 2, 4, row[0] + 3, 1))) < 1e-7);
  }
}

// b + c = (a + d)(1 - 1e-8): a gap of 0.04 deg; every step once printed 361 rows across it, exit 0.
TEST_CASE("a 0.04 deg gap between two limit points is found at every step, listed, and exits 1", "[cli]") {
  const std::string file = test::TestDataPath("near-change-point-gap.yaml");
  // the crank's limits where |A B0| = b + c: cos phi_c = (a^2 + d^2 - (b + c)^2) / (2 a d), phi = phi_c - 3
  const double reach = 1.99999995 + 3, limit = std::acos((1 + 16 - reach * reach) / 8) * 180 / M_PI - 3;
  for (const char* step : {"1", "7", "45", "0.01"}) {
    const std::string range = std::string(step) == "0.01" ? " --from 170 --to 184" : "";
    const test::RunResult r = test::RunKoppel("analyze " + file + " --order 0 --step " + step + range);
    INFO("--step " << step << "\n" << r.err);
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("limit point") != std::string::npos);
    CHECK(r.err.find("branch point") == std::string::npos);
    for (const std::string& line : Lines(r.out)) {
      if (line.empty() || !std::isdigit(static_cast<unsigned char>(line[0]))) continue;
      const auto row = Numbers(line);
      INFO("phi = " << row[0]);
      // no row inside the gap (limit, 354 - limit), and each on the assembly's branch
      CHECK(!(row[0] > limit && row[0] < 354 - limit));
      CHECK(std::abs(DegreeDifference(row[1], FourBarPsi(1, 1.99999995, 3, 4, row[0] + 3, 1))) < 1e-6);
    }
  }
}

}  // namespace koppel::analyze_command_test

namespace koppel::analyze_command_test {

// The proportional linkage with its slot's slide S23 turned off the slot's line (axis [1, k]):
// the line of the second slide S34 then turns vertical, parallel to the output's guide, at a
// crank angle where the output's block runs off to infinity. The walk crept towards that point
// for minutes (some axes over 600 s); it must end there within a few seconds, exit 1, say so,
// and print the rows before it.
TEST_CASE("a slide whose meeting point runs off to infinity ends the walk there, quickly, with exit 1", "[cli]") {
  const std::string original = test::ReadText(test::CatalogEntryPath("proportional-linkage"));
  const std::string slide = "S23: {type: P, links: [slot, block2], points: [B0, A], axis: [1, 0]}";
  REQUIRE(original.find(slide) != std::string::npos);
  test::TempDir dir;
  for (const char* k : {"5", "10", "50", "360", "1e9"}) {
    std::string text = original;
    text.replace(text.find(slide), slide.size(), "S23: {type: P, links: [slot, block2], points: [B0, A], axis: [1, " + std::string(k) + "]}");
    const std::string file = dir.Write(std::string("axis-") + k + ".yaml", text);
    const auto start = std::chrono::steady_clock::now();
    const test::RunResult r = test::RunKoppel("analyze " + file + " --step 5 --order 0");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    INFO("axis [1, " << k << "]: " << seconds << " s\n" << r.err);
    CHECK(seconds < 5.0);  // under the sanitizers too; a release build takes 0.02-0.07 s
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("runs off to infinity") != std::string::npos);
    CHECK(Lines(r.out).size() > 1);
  }
}

// --at X: the one row at X, the same as the full sweep's row there (the same walk from the
// assembly); with --from/--to/--step it is refused.
TEST_CASE("analyze --at gives the sweep's row at that input", "[cli][analyze]") {
  const std::string file = test::CatalogEntryPath("slider-crank-offset");
  const test::RunResult one = test::RunKoppel("analyze " + file + " --at 30");
  REQUIRE(one.exit_code == 0);
  const test::RunResult all = test::RunKoppel("analyze " + file + " --step 1");
  REQUIRE(all.exit_code == 0);
  const std::string header = all.out.substr(0, all.out.find('\n') + 1);
  const size_t row = all.out.find("\n30,");
  REQUIRE(row != std::string::npos);
  CHECK(one.out == header + all.out.substr(row + 1, all.out.find('\n', row + 1) - row));
  CHECK(test::RunKoppel("analyze " + file + " --at 30 --from 0").exit_code == 2);
  CHECK(test::RunKoppel("analyze " + file + " --at 30 --step 2").exit_code == 2);
  CHECK(test::RunKoppel("analyze " + file + " --at thirty").exit_code == 2);
}
}  // namespace koppel::analyze_command_test
