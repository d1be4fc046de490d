// The one SVG writer: numbers, escaping, balanced groups, paths whose runs stay separate.
#include "koppel/plot/svg.hpp"

#include "tools/plot/svg_reading.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace koppel::svg_test {

TEST_CASE("Num prints short numbers and refuses non-finite ones", "[plot]") {
  CHECK(plot::Num(1.0) == "1");
  CHECK(plot::Num(-0.0001) == "0");
  CHECK(plot::Num(2.345678) == "2.35");
  CHECK(plot::Num(2.75, 0) == "3");
  CHECK(plot::Num(1234.5, 3) == "1234.5");
  CHECK_THROWS_AS(plot::Num(std::numeric_limits<double>::quiet_NaN()), std::logic_error);
  CHECK_THROWS_AS(plot::Num(INFINITY), std::logic_error);
}

TEST_CASE("Svg writes a document an XML parser reads back, text escaped", "[plot]") {
  plot::Svg svg(200, 100);
  svg.OpenGroup({{"class", "panel"}, {"data-title", "s < 1 & \"q\""}});
  svg.Text({10, 20}, "φ_a <i> & 'x'", {{"class", "label"}});
  svg.Path({{{0, 0}, {10, 10}}, {{20, 20}, {30, 30}, {40, 35}}}, {{"class", "curve"}});
  svg.CloseGroup();
  const auto doc = test::ParseSvg(svg.Finish());
  const auto panel = test::Find(doc, "g", "panel");
  REQUIRE(panel.size() == 1);
  CHECK(std::string(panel[0].attribute("data-title").as_string()) == "s < 1 & \"q\"");
  CHECK(std::string(test::Find(doc, "text", "label")[0].child_value()) == "φ_a <i> & 'x'");
  const auto runs = test::Subpaths(test::Find(doc, "path", "curve")[0]);
  REQUIRE(runs.size() == 2);  // the gap between the runs is not bridged
  CHECK(runs[0].size() == 2);
  CHECK(runs[1].size() == 3);
  CHECK(runs[1].back().isApprox(Eigen::Vector2d(40, 35)));
}

// XML 1.0 section 2.2, Char: tab, LF, CR, U+0020..U+D7FF, U+E000..U+FFFD, U+10000..U+10FFFF. The
// bytes checked here: no C0 byte but tab, LF and CR, and not the UTF-8 of U+FFFE or U+FFFF.
bool HasOnlyXmlChars(const std::string& text) {
  for (size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') return false;
    if (c == 0xEF && i + 2 < text.size() && text[i + 1] == '\xBF' && (text[i + 2] == '\xBE' || text[i + 2] == '\xBF')) return false;
  }
  return true;
}

TEST_CASE("Svg stays well-formed whatever a name holds: what XML forbids becomes U+FFFD", "[plot]") {
  // names the file reader refuses, as the library API or the Python module may still pass them:
  // NUL, ESC, BEL, U+FFFF, a byte that is not UTF-8; the tab stays (XML allows it)
  const std::string name = std::string("crank\0", 6) + "\x1b[31m\x07\xEF\xBF\xBF\xFF\tend";
  plot::Svg svg(100, 100);
  svg.Text({10, 20}, name, {{"class", "label"}, {"data-link", name}});
  const std::string text = svg.Finish();
  CHECK(HasOnlyXmlChars(text));
  const auto doc = test::ParseSvg(text);
  const std::string shown = "crank\uFFFD\uFFFD[31m\uFFFD\uFFFD\uFFFD\tend";  // one U+FFFD a character
  CHECK(std::string(test::Find(doc, "text", "label").at(0).child_value()) == shown);
  // an attribute's tab is read as a space (XML 1.0 section 3.3.3, attribute-value normalization)
  CHECK(std::string(test::Find(doc, "text", "label").at(0).attribute("data-link").as_string()) ==
        "crank\uFFFD\uFFFD[31m\uFFFD\uFFFD\uFFFD end");
  // the markup of the names of tests/data/hostile-names.yaml stays text
  const std::string markup = "s<img src=x onerror=\"document.title+='[X]'\"> <!--<script>";
  plot::Svg page(100, 100);
  page.Text({10, 20}, markup, {{"class", "label"}});
  const auto read = test::ParseSvg(page.Finish());
  CHECK(std::string(test::Find(read, "text", "label").at(0).child_value()) == markup);
  CHECK(test::Find(read, "img", "").empty());
}

TEST_CASE("Svg refuses unbalanced groups", "[plot]") {
  plot::Svg svg(10, 10);
  CHECK_THROWS_AS(svg.CloseGroup(), std::logic_error);
  svg.OpenGroup({});
  CHECK_THROWS_AS(svg.Finish(), std::logic_error);
}

}  // namespace koppel::svg_test
