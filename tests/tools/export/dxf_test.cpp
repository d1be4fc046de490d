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
  int insunits = -1;
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

TEST_CASE("DXF layer names: the characters DXF forbids replaced", "[export][dxf]") {
  CHECK(plot::DxfLayerName("crank") == "crank");
  CHECK(plot::DxfLayerName("curve-K") == "curve-K");
  CHECK(plot::DxfLayerName("a b/c:d") == "a_b_c_d");
  CHECK(plot::DxfLayerName("") == "_");
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

}  // namespace koppel::dxf_test
