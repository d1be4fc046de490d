// ViewPage (tools/plot/src/view_page.cpp): the page's data, read back from the HTML with a JSON
// parser, against the four-bar's closed form (tests/support/closed_forms: circle intersection),
// the page's loop/back-and-forth rule and the escaping of a hostile title. (The page running in a
// browser is tests/tools/view/page_test.mjs.)
#include "koppel/plot/view_page.hpp"

#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

namespace koppel::view_page_test {
namespace {

// The page rounds its numbers to six significant digits: half a unit in the sixth digit of
// numbers below 10 is 5e-6.
constexpr double kSixDigits = 5e-6;

// A crank-rocker (1 + 3.2 < 3 + 2.5) with coupler point K = 1.5 at 0.4 rad off A -> B.
constexpr double kL1 = 1, kL2 = 3, kL3 = 2.5, kL4 = 3.2, kK = 1.5, kKappa = 0.4;

SweepOptions Degrees(double from, double to, double step) {
  SweepOptions s;
  s.from = DegToRad(from);
  s.to = DegToRad(to);
  s.step = DegToRad(step);
  return s;
}

// The JSON of <script id="koppel-data">.
nlohmann::json PageData(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"koppel-data\">";
  const size_t begin = page.find(open);
  REQUIRE(begin != std::string::npos);
  const size_t from = begin + open.size(), to = page.find("</script>", from);
  REQUIRE(to != std::string::npos);
  return nlohmann::json::parse(page.substr(from, to - from));
}

const nlohmann::json& Series(const nlohmann::json& list, const std::string& label) {
  for (const nlohmann::json& s : list)
    if (s["label"] == label) return s;
  FAIL("no series " << label);
  throw std::logic_error("unreachable");
}

TEST_CASE("a full turn: the inputs in degrees, the coupler point of the closed form, a looping page", "[view_page]") {
  const Mechanism m = test::FourBar(kL1, kL2, kL3, kL4, kK, kKappa, 1);
  plot::ViewOptions options;
  options.range = Degrees(0, 360, 5);
  const plot::PlotResult r = plot::ViewPage(m, options);
  REQUIRE(r.status == plot::PlotStatus::kComplete);
  const nlohmann::json data = PageData(r.svg);
  CHECK(data["title"] == "four-bar");
  CHECK(data["cyclic"] == true);
  CHECK(data["breaks"].empty());
  const std::vector<double> inputs = data["inputs"];
  REQUIRE(inputs.size() == 73);  // 0, 5, ..., 360: hand count
  const std::vector<double> kx = Series(data["readout"], "K_x")["values"], ky = Series(data["readout"], "K_y")["values"];
  REQUIRE(kx.size() == inputs.size());
  for (size_t i = 0; i < inputs.size(); ++i) {
    CHECK(inputs[i] == 5.0 * i);
    const Eigen::Vector2d k = test::FourBarCouplerPoint(kL1, kL2, kL3, kL4, kK, kKappa, DegToRad(5.0 * i), 1);
    CHECK_THAT(kx[i], Catch::Matchers::WithinAbs(k.x(), kSixDigits));
    CHECK_THAT(ky[i], Catch::Matchers::WithinAbs(k.y(), kSixDigits));
  }
  // one chart per scalar output: psi and phi with two transfer functions, mu alone (hand count)
  REQUIRE(data["charts"].size() == 3);
  CHECK(data["charts"][0]["series"].size() == 3);
  CHECK(data["charts"][2]["series"].size() == 1);
  CHECK(data["coordinates"] == 9);  // three moving links, (x, y, theta) each
  CHECK(data["poses"].size() == 73 * 9);
}

TEST_CASE("a range the drive cannot cover: a partial page going back and forth", "[view_page]") {
  // a Grashof double-rocker (coupler 1 shortest): the input swings between 38.6 and 78.6 deg
  const Eigen::Vector2d hint = test::FourBarRocker(3, 1, 3.5, 4, DegToRad(60), +1)->b;
  const Mechanism m = test::PlainFourBar(3, 1, 3.5, 4, DegToRad(60), hint);
  plot::ViewOptions options;
  options.range = Degrees(0, 120, 1);
  const plot::PlotResult r = plot::ViewPage(m, options);
  REQUIRE(r.status == plot::PlotStatus::kPartial);
  CHECK_FALSE(r.message.empty());
  const nlohmann::json data = PageData(r.svg);
  CHECK(data["cyclic"] == false);
  CHECK(data["message"] == r.message);
  CHECK(data["inputs"].size() == 40);  // 39 .. 78 deg
}

TEST_CASE("a hostile title cannot end the page's script or inject markup", "[view_page]") {
  const Mechanism m = test::FourBar(kL1, kL2, kL3, kL4, kK, kKappa, 1);
  plot::ViewOptions plain, hostile;
  plain.range = hostile.range = Degrees(0, 360, 30);
  plain.title = "x";
  hostile.title = "</script><b>x</b> & 'y'";
  const std::string a = plot::ViewPage(m, plain).svg, b = plot::ViewPage(m, hostile).svg;
  // reference: the page with a harmless title has as many </script> as the hostile one
  auto count = [](const std::string& s, const std::string& what) {
    int n = 0;
    for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
    return n;
  };
  CHECK(count(b, "</script>") == count(a, "</script>"));
  CHECK(PageData(b)["title"] == hostile.title);  // the data keep the title as it is
  CHECK(b.find("<title>&lt;/script&gt;&lt;b&gt;x&lt;/b&gt; &amp;") != std::string::npos);
}

TEST_CASE("a range of too many frames is refused before any work", "[view_page]") {
  plot::ViewOptions o;
  o.range = Degrees(0, 360, 0.05);  // 7201 samples > 3601
  std::string why;
  CHECK_FALSE(o.IsValid(&why));
  CHECK_THAT(why, Catch::Contains("7201 samples"));
  const plot::PlotResult r = plot::ViewPage(test::FourBar(kL1, kL2, kL3, kL4, kK, kKappa, 1), o);
  CHECK(r.status == plot::PlotStatus::kFailed);
  CHECK(r.svg.empty());
}

}  // namespace
}  // namespace koppel::view_page_test
