// FramePainter (tools/export/src/frame_painter.cpp) on a hand-made scene, its pixels read from
// the cairo surface. Reference: the view worked by hand from the header's definition (one view
// that fits every frame's parts and curves, to scale, y up, inside the margins and under the
// caption) for a 480 x 360 picture, and the scheme's colours (scheme.cpp) sampled well inside
// each region, away from anti-aliased edges.
#include "frame_painter.hpp"

#include "koppel/plot/parts.hpp"

#include <catch2/catch.hpp>

#include <cairo.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace koppel::frame_painter_test {
namespace {

using Vec = Eigen::Vector2d;

constexpr std::uint32_t kWhite = 0xffffff, kInk = 0x1d2b3a, kLinkFill = 0xd3e2f1, kFrameFill = 0xe6e6e6;
constexpr int kWidth = 480, kHeight = 360;

// The view worked by hand (px = 1 at 480 x 360; margin 18, caption 22, pivot symbol 13 px).
// The parts span x -0.5 .. 4.5 and y -0.5 .. 0.5 (a plate of width 1 round (0,0)-(4,0)):
// usable 444 x 289 px, so scale = min(444 / 5, 289 / 1) = 88.8 px per unit, x centred:
// ox = 240 - 88.8 * 2 = 62.4, and y centred in the band under the caption: oy = 40 + 144.5.
constexpr double kScale = 88.8, kOx = 62.4, kOy = 184.5;
// a sample kept this far from any edge sees no anti-aliasing (lines are at most 1.6 px wide)
constexpr double kClearOfEdges = 4;

Vec Device(const Vec& world) { return {kOx + kScale * world.x(), kOy - kScale * world.y()}; }

std::uint32_t PixelAt(cairo_surface_t* s, const Vec& device) {
  const int x = static_cast<int>(std::floor(device.x())), y = static_cast<int>(std::floor(device.y()));
  REQUIRE(x >= 0);
  REQUIRE(y >= 0);
  REQUIRE(x < cairo_image_surface_get_width(s));
  REQUIRE(y < cairo_image_surface_get_height(s));
  const unsigned char* row = cairo_image_surface_get_data(s) + static_cast<size_t>(y) * cairo_image_surface_get_stride(s);
  return reinterpret_cast<const std::uint32_t*>(row)[x] & 0xffffff;
}
std::uint32_t PixelAtWorld(cairo_surface_t* s, const Vec& world) { return PixelAt(s, Device(world)); }

bool Reddish(std::uint32_t c) { return static_cast<int>(c >> 16) > static_cast<int>((c >> 8) & 255) + 60; }

// A moving plate round (0,0)-(4,0), width 1, holes of diameter 0.4 at both ends and a coupler
// mark at (2, 0.25); the frame's pivot at (4,0); a traced curve along y = -0.3 drawn up to
// input 2 (one point per unit of input).
plot::AnimationScene Scene() {
  plot::Part frame;
  frame.link = "frame";
  frame.frame = true;
  frame.holes.push_back({Vec(4, 0), 0.4, "B"});
  plot::Part plate;
  plate.link = "crank";
  plate.outline = plot::RoundedHull({Vec(0, 0), Vec(4, 0)}, 0.5);
  plate.holes.push_back({Vec(0, 0), 0.4, "A"});
  plate.holes.push_back({Vec(4, 0), 0.4, "B"});
  plate.marks.push_back({"P", Vec(2, 0.25)});
  plot::AnimationFrame f;
  f.traced_up_to = 2;
  f.caption = "HHHH";
  f.parts = {frame, plate};
  plot::AnimationScene scene;
  scene.frames = {f};
  plot::TracedCurve c;
  c.name = "P";
  c.inputs = {{0, 1, 2, 3, 4}};
  c.runs = {{Vec(0, -0.3), Vec(1, -0.3), Vec(2, -0.3), Vec(3, -0.3), Vec(4, -0.3)}};
  scene.curves = {c};
  return scene;
}

}  // namespace

TEST_CASE("FramePainter: the view fits the parts to scale, y up, in the scheme's colours", "[export][gif]") {
  const plot::AnimationScene scene = Scene();
  plot::FramePainter painter(scene, kWidth, kHeight);
  painter.Paint(0);
  cairo_surface_t* s = painter.surface();
  REQUIRE(cairo_image_surface_get_format(s) == CAIRO_FORMAT_RGB24);
  CHECK(cairo_image_surface_get_width(s) == kWidth);
  CHECK(cairo_image_surface_get_height(s) == kHeight);
  // the plate filled, where the hand-worked view puts it
  CHECK(PixelAtWorld(s, {1, 0.2}) == kLinkFill);
  CHECK(PixelAtWorld(s, {3, -0.45 + kClearOfEdges / kScale}) == kLinkFill);
  // its edge: the plate's left end (x = -0.5) at 18 px, the margin; white beyond it; y up: the
  // top edge (y = 0.5) above the centre line on the picture
  CHECK(PixelAt(s, {18 + kClearOfEdges, kOy}) == kLinkFill);
  CHECK(PixelAt(s, {18 - kClearOfEdges, kOy}) == kWhite);
  CHECK(PixelAtWorld(s, {2, 0.5 + kClearOfEdges / kScale}) == kWhite);
  CHECK(PixelAtWorld(s, {2, 0.5 - kClearOfEdges / kScale}) == kLinkFill);
  CHECK(PixelAt(s, {kWidth - 18 + kClearOfEdges, kOy}) == kWhite);
  // the holes: white, a hole's radius 0.2 = 17.8 px, the ink of its rim between
  CHECK(PixelAtWorld(s, {0, 0}) == kWhite);
  CHECK(PixelAtWorld(s, {0.2 - kClearOfEdges / kScale, 0}) == kWhite);
  CHECK(PixelAtWorld(s, {0.2 + kClearOfEdges / kScale, 0}) == kLinkFill);
  CHECK(PixelAtWorld(s, {4, 0}) == kWhite);
  // the coupler mark: an ink dot (radius 2.2 px) at its point
  CHECK(PixelAtWorld(s, {2, 0.25}) == kInk);
  // the pivot's ground triangle under the frame's hole, over the plate: apex at the pin, height
  // max(13 px, 2.2 x the hole's radius in px) = 39.1 px; 30 px down it is 2 x 20 px wide
  CHECK(PixelAt(s, Device({4, 0}) + Vec(0, 30)) == kFrameFill);
  CHECK(PixelAt(s, Device({4, 0}) + Vec(30, 30)) != kFrameFill);
  // the curve up to the frame's input only (TracedCurve::UpTo): red at x = 1, not at x = 3
  bool red_before = false, red_after = false;
  for (int dy = -2; dy <= 2; ++dy) {
    red_before = red_before || Reddish(PixelAt(s, Device({1, -0.3}) + Vec(0, dy)));
    red_after = red_after || Reddish(PixelAt(s, Device({3, -0.3}) + Vec(0, dy)));
  }
  CHECK(red_before);
  CHECK_FALSE(red_after);
  // the caption at the top left, above the parts: some ink there
  bool caption = false;
  for (int y = 0; y < 36; ++y)
    for (int x = 0; x < 120; ++x) caption = caption || PixelAt(s, {x + 0.5, y + 0.5}) != kWhite;
  CHECK(caption);
}

TEST_CASE("FramePainter: one view for every frame; each frame painted afresh", "[export][gif]") {
  plot::AnimationScene scene = Scene();
  // a second frame with the plate moved up by 1: the view now fits y -0.5 .. 1.5 as well
  plot::AnimationFrame moved = scene.frames[0];
  moved.parts[1].outline = plot::RoundedHull({Vec(0, 1), Vec(4, 1)}, 0.5);
  moved.parts[1].holes = {{Vec(0, 1), 0.4, "A"}, {Vec(4, 1), 0.4, "B"}};
  moved.parts[1].marks = {};
  scene.frames.push_back(moved);
  plot::FramePainter painter(scene, kWidth, kHeight);
  cairo_surface_t* s = painter.surface();
  const auto pixels = [&] {
    const unsigned char* d = cairo_image_surface_get_data(s);
    return std::vector<unsigned char>(d, d + static_cast<size_t>(cairo_image_surface_get_stride(s)) * kHeight);
  };
  // (painted twice first: the first Paint draws with other line joins, see the test below)
  painter.Paint(0);
  painter.Paint(0);
  const std::vector<unsigned char> first = pixels();
  painter.Paint(1);
  const std::vector<unsigned char> second = pixels();
  const bool changed = first != second;  // (compared as a flag: Catch would print 700 kB of pixels)
  CHECK(changed);
  painter.Paint(0);
  const bool restored = pixels() == first;  // nothing of frame 1 is left
  CHECK(restored);
  // the view by hand: parts span 5 x 2 units; scale = min(444 / 5, 289 / 2) = 88.8 still, and
  // y centred on 0.5: world y = 0.5 at kOy. Frame 0's plate centre line (y = 0) lies 44.4 px
  // below it, frame 1's (y = 1) 44.4 px above.
  painter.Paint(0);
  CHECK(PixelAt(s, {kOx + kScale * 1, kOy + 44.4}) == kLinkFill);
  CHECK(PixelAt(s, {kOx + kScale * 1, kOy - 44.4}) == kWhite);
  painter.Paint(1);
  CHECK(PixelAt(s, {kOx + kScale * 1, kOy - 44.4}) == kLinkFill);
  CHECK_THROWS_AS(painter.Paint(2), std::out_of_range);
}

// frame_painter.hpp: "the same [view] in each frame so that only the mechanism moves". Curves()
// set CAIRO_LINE_JOIN_ROUND on the context and nothing set it back, so the first Paint stroked
// the pivots' triangles with mitre joins and every later one with round joins (10 pixels of the
// still frame differed); it now saves and restores the context around the curves.
TEST_CASE("FramePainter: the same frame painted twice gives the same pixels", "[export][gif]") {
  const plot::AnimationScene scene = Scene();
  plot::FramePainter painter(scene, kWidth, kHeight);
  cairo_surface_t* s = painter.surface();
  const auto pixels = [&] {
    const unsigned char* d = cairo_image_surface_get_data(s);
    return std::vector<unsigned char>(d, d + static_cast<size_t>(cairo_image_surface_get_stride(s)) * kHeight);
  };
  painter.Paint(0);
  const std::vector<unsigned char> first = pixels();
  painter.Paint(0);
  const bool same = pixels() == first;
  CHECK(same);
}

}  // namespace koppel::frame_painter_test
