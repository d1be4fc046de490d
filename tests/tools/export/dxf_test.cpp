// The DXF writer: units, layer names, and the file read back with dxflib's own reader (the
// independent reader, ezdxf, reads the CLI's files in dxf_readback_test.py). References: the
// DXF reference's $INSUNITS codes (AutoCAD DXF Reference, HEADER section) and the parts given.
#include "koppel/export/dxf.hpp"

#include "support/mechanisms.hpp"

#include "koppel/core/angles.hpp"

#include <dl_creationadapter.h>
#include <dl_dxf.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

namespace koppel::dxf_test {
namespace {

// the bulge tan(sweep / 4) of a half circle is tan(pi / 4) = 1 up to the rounding of pi / 4 (1 ulp)
constexpr double kBulgeRoundoff = 1e-14;

// What a DXF holds, as dxflib reads it.
struct Reader : DL_CreationAdapter {
  std::vector<std::string> layers;
  std::vector<std::pair<std::string, DL_CircleData>> circles;
  std::vector<std::pair<std::string, int>> polylines;  // layer, vertices
  std::vector<DL_VertexData> vertices;
  std::vector<std::string> points;  // layers
  int lines = 0;
  int insunits = -1;
  void addLine(const DL_LineData&) override { ++lines; }
  void addPoint(const DL_PointData&) override { points.push_back(getAttributes().getLayer()); }
  void addLayer(const DL_LayerData& d) override { layers.push_back(d.name); }
  void addCircle(const DL_CircleData& d) override { circles.emplace_back(getAttributes().getLayer(), d); }
  void addPolyline(const DL_PolylineData& d) override { polylines.emplace_back(getAttributes().getLayer(), d.number); }
  void addVertex(const DL_VertexData& d) override { vertices.push_back(d); }
  void setVariableInt(const std::string& name, int value, int) override {
    if (name == "$INSUNITS") insunits = value;
  }
};

Reader Read(const std::string& text) {
  Reader r;
  std::stringstream stream(text);
  DL_Dxf dxf;
  REQUIRE(dxf.in(stream, &r));
  return r;
}

// The group pairs of a DXF text, in order: (code, value).
std::vector<std::pair<int, std::string>> Groups(const std::string& text) {
  std::vector<std::pair<int, std::string>> groups;
  std::istringstream in(text);
  std::string code, value;
  while (std::getline(in, code) && std::getline(in, value)) groups.emplace_back(std::stoi(code), value);
  return groups;
}

// The value of group `code` in the first table entry `entry` (group 0) named `name` (group 2).
std::string GroupOf(const std::string& text, const std::string& entry, const std::string& name, int code) {
  const auto groups = Groups(text);
  for (size_t i = 0; i < groups.size(); ++i) {
    if (groups[i] != std::pair<int, std::string>{0, entry}) continue;
    std::string found, entry_name;
    for (size_t k = i + 1; k < groups.size() && groups[k].first != 0; ++k) {
      if (groups[k].first == 2) entry_name = groups[k].second;
      if (groups[k].first == code && found.empty()) found = groups[k].second;
    }
    if (entry_name == name) return found;
  }
  return "";
}

// A crank and its frame pivot, the crank named `crank`.
plot::WorkshopDrawing CrankDrawing(const std::string& crank_name) {
  plot::WorkshopDrawing drawing;
  plot::Part frame, crank;
  frame.link = "frame";
  frame.frame = true;
  frame.holes = {{{0, 0}, 0.1, "A0"}};
  crank.link = crank_name;
  crank.outline = plot::RoundedHull({{0, 0}, {1, 0}}, 0.15);
  crank.holes = {{{0, 0}, 0.1, "A0"}, {{1, 0}, 0.1, "A"}};
  crank.marks = {{"K", {0.5, 0.2}}};
  drawing.parts = {frame, crank};
  return drawing;
}

}  // namespace

TEST_CASE("DXF units: $INSUNITS of the file's length unit", "[export][dxf]") {
  CHECK(plot::DxfUnits(0.001, true) == 4);   // mm
  CHECK(plot::DxfUnits(0.01, true) == 5);    // cm
  CHECK(plot::DxfUnits(1.0, true) == 6);     // m
  CHECK(plot::DxfUnits(0.0254, true) == 1);  // in
  CHECK(plot::DxfUnits(0.3048, true) == 2);  // ft
  CHECK(plot::DxfUnits(1000.0, true) == 7);  // km
  CHECK(plot::DxfUnits(1e-6, true) == 13);   // um
  CHECK(plot::DxfUnits(0.1, true) == 14);    // dm
  CHECK(plot::DxfUnits(0.5, true) == 0);     // a unit DXF has no code for
  CHECK(plot::DxfUnits(1.0, false) == 0);    // no unit in the file: unitless
}

TEST_CASE("DXF of a drawing read back with dxflib", "[export][dxf]") {
  plot::WorkshopDrawing drawing;
  plot::Part frame, crank;
  frame.link = "frame";
  frame.frame = true;
  frame.holes = {{{0, 0}, 0.1, "A0"}};
  crank.link = "crank";
  crank.outline = plot::RoundedHull({{0, 0}, {1, 0}}, 0.15);
  crank.holes = {{{0, 0}, 0.1, "A0"}, {{1, 0}, 0.1, "A"}};
  drawing.parts = {frame, crank};
  plot::TracedCurve curve;
  curve.name = "K";
  curve.closed = true;
  curve.runs = {{{2, 0}, {0, 2}, {-2, 0}, {0, -2}}};
  curve.inputs = {{0, 1, 2, 3}};
  drawing.curves = {curve};
  const Reader r = Read(plot::WriteDxf(drawing, 4));
  CHECK(r.insunits == 4);
  CHECK(r.layers == std::vector<std::string>{"0", "frame", "crank", "curve-K"});
  REQUIRE(r.circles.size() == 3);
  CHECK(r.circles[2].first == "crank");
  CHECK(r.circles[2].second.cx == 1);
  CHECK(r.circles[2].second.radius == 0.05);
  // the crank's plate: 2 arcs, 4 vertices; the curve: its 4 points
  REQUIRE(r.polylines.size() == 2);
  CHECK(r.polylines[0] == std::pair<std::string, int>{"crank", 4});
  CHECK(r.polylines[1] == std::pair<std::string, int>{"curve-K", 4});
  // half circles: bulge tan(pi/4) = 1 at the arcs' starts
  REQUIRE(r.vertices.size() == 8);
  CHECK_THAT(r.vertices[0].bulge, Catch::Matchers::WithinAbs(1, kBulgeRoundoff));
  CHECK(r.vertices[1].bulge == 0);
  plot::WorkshopDrawing failed;
  failed.status = plot::PlotStatus::kFailed;
  CHECK_THROWS_AS(plot::WriteDxf(failed, 0), std::invalid_argument);
}

TEST_CASE("DXF of a link whose name holds a DXF text: the same entities as under a plain name", "[export][dxf]") {
  // the repro: written as it was, the name ended the layer's group 8 and the rest became a LINE
  // to (99, 99) on layer 0 after the plate and after each hole
  const std::string injected = "crank\n0\nLINE\n8\n0\n10\n0\n20\n0\n11\n99\n21\n99";
  const Reader plain = Read(plot::WriteDxf(CrankDrawing("crank"), 0));
  const Reader odd = Read(plot::WriteDxf(CrankDrawing(injected), 0));
  CHECK(odd.lines == 0);
  CHECK(odd.circles.size() == plain.circles.size());
  CHECK(odd.polylines.size() == plain.polylines.size());
  CHECK(odd.vertices.size() == plain.vertices.size());
  CHECK(odd.points.size() == plain.points.size());
  const std::string layer = plot::DxfLayerNames({"frame", injected})[1];
  CHECK(odd.layers == std::vector<std::string>{"0", "frame", layer});
  for (const auto& [on, circle] : odd.circles) CHECK((on == "frame" || on == layer));
  CHECK(odd.polylines[0].first == layer);
  CHECK(odd.points == std::vector<std::string>{layer});
}

TEST_CASE("DXF: the dimension style refers to the text style written, the same bytes every time", "[export][dxf]") {
  // dxflib keeps the text style's handle for the dimension style's group 340 only for the name
  // "Standard"; under "standard" it wrote a member never set, different from run to run
  const std::string text = plot::WriteDxf(CrankDrawing("crank"), 4);
  const std::string style = GroupOf(text, "STYLE", "Standard", 5);
  REQUIRE_FALSE(style.empty());
  CHECK(GroupOf(text, "DIMSTYLE", "Standard", 340) == style);
  CHECK(plot::WriteDxf(CrankDrawing("crank"), 4) == text);
}

}  // namespace koppel::dxf_test
