// The one-call exits: a file when there is something to draw, none and the reason otherwise.
// Reference: the double rocker's limit positions (49.2 and 97.2 deg: no pose at 120 deg).
#include "koppel/export/export.hpp"

#include "tools/plot/cycle_fixtures.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

namespace koppel::export_test {
TEST_CASE("export: a DXF, or no file and why", "[export]") {
  const Mechanism m = test::DoubleRocker();
  plot::WorkshopOptions o;
  o.cycle = test::CycleOptionsFor(m);
  o.at = DegToRad(60);
  const plot::ExportResult ok = plot::ExportDxf(m, o, 0);
  CHECK(ok.status == plot::PlotStatus::kComplete);
  CHECK(ok.bytes.rfind("999\ndxflib", 0) == 0);
  CHECK(ok.bytes.size() > 1000);
  o.at = DegToRad(120);
  const plot::ExportResult beyond = plot::ExportDxf(m, o, 0);
  CHECK(beyond.status == plot::PlotStatus::kFailed);
  CHECK_THAT(beyond.message, Catch::Contains("cannot reach"));
  CHECK(beyond.bytes.empty());
}

TEST_CASE("animate: a GIF of the frames asked for", "[export]") {
  const Mechanism m = test::DoubleRocker();
  plot::AnimationOptions o;
  o.cycle = test::CycleOptionsFor(m);
  o.frames = 4;
  plot::GifOptions gif;
  gif.width = gif.height = 64;
  const plot::ExportResult r = plot::AnimateGif(m, o, gif);
  CHECK(r.status == plot::PlotStatus::kComplete);
  CHECK(r.bytes.rfind("GIF89a", 0) == 0);
  gif.width = 0;
  CHECK_THROWS_AS(plot::AnimateGif(m, o, gif), std::invalid_argument);
}

}  // namespace koppel::export_test
