// DrawSchemeOf (tools/plot/src/scheme_drawing.cpp): `koppel draw` in one call, the SVG read back.
// References: seed 000's dead centres in closed form (closed_forms.hpp: phi_a, phi_i), the
// file's sweep for the trace's sample count.
#include "koppel/plot/scheme_drawing.hpp"
#include "koppel/core/angles.hpp"
#include "support/closed_forms.hpp"
#include "support/temp_file.hpp"
#include "tools/plot/svg_reading.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <string>

namespace koppel::scheme_drawing_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

// "φ_a = 102.84°": a dead centre as the caption names it, two decimals
std::string Named(const char* suffix, double degrees) {
  char text[64];
  std::snprintf(text, sizeof text, "φ_%s = %.2f°", suffix, degrees);
  return text;
}

}  // namespace

TEST_CASE("DrawSchemeOf: seed 000 at 120 deg with both dead centres named in the caption", "[plot]") {
  const Model m = Model::Load(test::CatalogEntryPath("slider-crank-offset"));
  plot::SchemeRequest request;
  request.at = 120;
  request.dead_centres = true;
  const plot::SchemeDrawing d = plot::DrawSchemeOf(m, request);
  REQUIRE(d.status == plot::PlotStatus::kComplete);
  CHECK(d.problems.empty());
  const pugi::xml_document doc = test::ParseSvg(d.svg);
  CHECK(test::Find(doc, "g", "overlay").size() == 2);
  const std::string caption = test::Find(doc, "text", "caption").at(0).child_value();
  const double phi_a = RadToDeg(test::SliderCrankPhiA(1, 2.6, 0.8)), phi_i = RadToDeg(test::SliderCrankPhiI(1, 2.6, 0.8));
  CHECK_THAT(caption, Catch::Contains("φ = 120.00°") && Catch::Contains(Named("a", phi_a)) &&
                          Catch::Contains(Named("i", phi_i)) && Catch::Contains("dead centres of s"));
}

TEST_CASE("DrawSchemeOf: the trace covers the file's sweep unless the request says otherwise", "[plot]") {
  const Model m = Model::Load(test::CatalogEntryPath("mzc-crank-rocker"));
  plot::SchemeRequest request;
  const Expected<PointRef> k = FindPointByText(m.mechanism(), "K");
  REQUIRE(k);
  request.trace = *k;
  request.trace_name = "K";
  plot::SchemeDrawing d = plot::DrawSchemeOf(m, request);
  REQUIRE(d.status == plot::PlotStatus::kComplete);
  CHECK(test::Subpaths(test::Find(test::ParseSvg(d.svg), "path", "trace").at(0)).at(0).size() == 361);  // 0..360 by 1
  request.step = 10;
  d = plot::DrawSchemeOf(m, request);
  CHECK(test::Subpaths(test::Find(test::ParseSvg(d.svg), "path", "trace").at(0)).at(0).size() == 37);
}

TEST_CASE("DrawSchemeOf: a step of 0 or too many samples is refused", "[plot]") {
  const Model m = Model::Load(test::CatalogEntryPath("mzc-crank-rocker"));
  plot::SchemeRequest request;
  std::string why;
  CHECK(request.IsValid(m, &why));
  request.step = 0;
  CHECK_FALSE(request.IsValid(m, &why));
  CHECK_THROWS_AS(plot::DrawSchemeOf(m, request), InputError);
  request.step = 360.0 / 20000;  // 20001 samples: the most
  CHECK(request.IsValid(m, &why));
  request.step = 360.0 / 20001;
  CHECK_FALSE(request.IsValid(m, &why));
}

}  // namespace koppel::scheme_drawing_test
