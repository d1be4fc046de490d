// DxfLayerNames (tools/export/src/dxf_layers.cpp): layer names that DXF accepts and that keep
// apart what the user kept apart. Reference: the DXF Reference's rules for a layer (symbol table)
// name: at most 255 characters, none of < > / \ " : ; ? * | = `, compared without case; a group
// value ends at a line break.
#include "koppel/export/dxf.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <set>
#include <string_view>

namespace koppel::dxf_layers_test {
namespace {

bool Legal(const std::string& layer) {
  if (layer.empty() || layer.size() > 255) return false;
  return std::all_of(layer.begin(), layer.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u > ' ' && u < 127 && std::string_view("<>/\\\":;?*|=`").find(c) == std::string_view::npos;
  });
}

std::string Folded(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

TEST_CASE("DXF layer names: plain names kept, forbidden characters replaced", "[export][dxf]") {
  CHECK(plot::DxfLayerNames({"frame", "crank", "curve-K"}) == std::vector<std::string>{"frame", "crank", "curve-K"});
  CHECK(plot::DxfLayerNames({"a b/c:d"}) == std::vector<std::string>{"a_b_c_d"});
  CHECK(plot::DxfLayerNames({""}) == std::vector<std::string>{"_"});
  CHECK(plot::DxfLayerNames({}).empty());
}

TEST_CASE("DXF layer names: a name with line breaks stays one value", "[export][dxf]") {
  // the repro: a link name that, written as it is, ends the layer's group and adds a LINE
  const std::string injected = "crank\n0\nLINE\n8\n0\n10\n0\n20\n0\n11\n99\n21\n99";
  const std::vector<std::string> layers = plot::DxfLayerNames({injected});
  REQUIRE(layers.size() == 1);
  CHECK(layers[0] == "crank_0_LINE_8_0_10_0_20_0_11_99_21_99");
  CHECK(Legal(layers[0]));
  // every other control character, DEL and bytes above 127 (UTF-8) too
  for (const std::string& odd : {std::string("a\rb"), std::string("a\tb"), std::string("a\x7f" "b"), std::string("a\0b", 3),
                                 std::string("K\xc3\xa4")})
    CHECK(Legal(plot::DxfLayerNames({odd})[0]));
}

TEST_CASE("DXF layer names: one to one, also where names differ only in what is replaced or in case", "[export][dxf]") {
  const std::vector<std::string> names = {"a<b", "a>b", "a_b", "Crank", "crank", "0", "DEFPOINTS", "a_b~2"};
  const std::vector<std::string> layers = plot::DxfLayerNames(names);
  REQUIRE(layers.size() == names.size());
  std::set<std::string> folded = {"0"};  // the default layer every drawing has
  for (const std::string& layer : layers) {
    CHECK(Legal(layer));
    CHECK(folded.insert(Folded(layer)).second);  // no two alike, not even in case
  }
  // the first keeps its name, the next the first free suffix: the same names, the same layers
  CHECK(layers[0] == "a_b");
  CHECK(layers[1] == "a_b~2");
  CHECK(layers[2] == "a_b~3");
  CHECK(layers[3] == "Crank");
  CHECK(layers[4] == "crank~2");
  CHECK(layers[5] == "0~2");
  CHECK(layers == plot::DxfLayerNames(names));
}

TEST_CASE("DXF layer names: long names cut to 255 characters, still apart", "[export][dxf]") {
  const std::string long_a(300, 'x'), long_b = std::string(300, 'x') + "y", short_c(255, 'x');
  const std::vector<std::string> layers = plot::DxfLayerNames({long_a, long_b, short_c});
  REQUIRE(layers.size() == 3);
  CHECK(layers[0] == std::string(255, 'x'));
  CHECK(layers[1] == std::string(253, 'x') + "~2");
  CHECK(layers[2] == std::string(253, 'x') + "~3");
  for (const std::string& layer : layers) CHECK(Legal(layer));
}

}  // namespace koppel::dxf_layers_test
