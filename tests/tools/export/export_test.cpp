// The one-call exits: a file when there is something to draw, none and the reason otherwise.
// Reference: the double rocker's limit positions (49.2 and 97.2 deg: no pose at 120 deg).
#include "koppel/export/export.hpp"

#include "support/mechanisms.hpp"

#include "koppel/core/angles.hpp"

#include <catch2/catch.hpp>

namespace koppel {
namespace {

plot::CycleOptions Cycle(const Mechanism& m) {
  plot::CycleOptions o;
  o.sizes = plot::DefaultPartSizes(m);
  o.sweep.to = 2 * kPi;
  return o;
}

}  // namespace

TEST_CASE("export: a DXF, or no file and why", "[export]") {
  const Mechanism m = test::PlainFourBar(3, 1, 3.5, 3, DegToRad(70), {2, 3.4});
  plot::WorkshopOptions o;
  o.cycle = Cycle(m);
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
  const Mechanism m = test::PlainFourBar(3, 1, 3.5, 3, DegToRad(70), {2, 3.4});
  plot::AnimationOptions o;
  o.cycle = Cycle(m);
  o.frames = 4;
  plot::GifOptions gif;
  gif.width = gif.height = 64;
  const plot::ExportResult r = plot::AnimateGif(m, o, gif);
  CHECK(r.status == plot::PlotStatus::kComplete);
  CHECK(r.bytes.rfind("GIF89a", 0) == 0);
  gif.width = 0;
  CHECK_THROWS_AS(plot::AnimateGif(m, o, gif), std::invalid_argument);
}

}  // namespace koppel
