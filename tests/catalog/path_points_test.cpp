// The points file of synth path (catalog/src/path_points.cpp): values as written (including a
// UTF-8 byte-order mark, CR line ends, a leading '+', the finite -1e-308), and every bad line
// reported with its line and column.
#include "koppel/catalog/path_points.hpp"

#include "koppel/catalog/mechanism_file.hpp"

#include <catch2/catch.hpp>

namespace koppel::path_points_test {
namespace {

std::vector<Diagnostic> Problems(const std::string& text) {
  try {
    ParseTimedPathPoints(text, "pts.csv");
  } catch (const InputError& e) {
    return e.diagnostics();
  }
  return {};
}

}  // namespace

TEST_CASE("points are read as written", "[points]") {
  const std::vector<Eigen::Vector2d> p = ParseTimedPathPoints("\xEF\xBB\xBFx,y\r\n1, 2\r\n\r\n+3.5,-1e-308\n-4e3 ,0\n", "pts.csv").points;
  REQUIRE(p.size() == 3);
  CHECK(p[0] == Eigen::Vector2d(1, 2));
  CHECK(p[1] == Eigen::Vector2d(3.5, -1e-308));  // a subnormal is a finite number
  CHECK(p[2] == Eigen::Vector2d(-4000, 0));
  CHECK(ParseTimedPathPoints("\n\nx,y\n0,0\n", "pts.csv").points.size() == 1);  // blank lines before the header
}

TEST_CASE("every bad points line is reported at its line and column", "[points]") {
  const std::vector<Diagnostic> d = Problems("x,y\n1,2\n1,5,2\n3,abc\nnan,1\n1e400,0\n");
  REQUIRE(d.size() == 4);
  CHECK(d[0].line == 3);
  CHECK_THAT(d[0].message, Catch::Contains("3 fields") && Catch::Contains("decimal comma"));
  CHECK(d[1].line == 4);
  CHECK(d[1].column == 3);
  CHECK_THAT(d[1].message, Catch::Contains("'abc'"));
  CHECK(d[2].line == 5);
  CHECK(d[2].column == 1);
  CHECK(d[3].line == 6);  // out of the range of a double
  CHECK_THAT(Problems("a,b\n1,2\n").at(0).message, Catch::Contains("expected the header x,y"));
  CHECK_THAT(Problems("").at(0).message, Catch::Contains("found nothing"));
}

TEST_CASE("a points file stops reporting after 20 problems", "[points]") {
  std::string text = "x,y\n";
  for (int i = 0; i < 100; ++i) text += "bad\n";
  CHECK(Problems(text).size() == 21);
}

}  // namespace koppel::path_points_test
