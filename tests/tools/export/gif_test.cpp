// The GIF writer: its options, and the file read back with giflib's decoder, frames composed as
// a viewer shows them (each frame's transparent pixels keep the one before). References: the
// GIF89a specification (delays in 1/100 s, transparency, "do not dispose") and the scene drawn:
// a four-bar (seed 003) whose frames must differ where the links move and nowhere else.
#include "koppel/export/gif.hpp"

#include "tools/plot/cycle_fixtures.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/limits.hpp"

#include "gif_reading.hpp"

#include <gif_lib.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

namespace koppel::gif_test {
namespace {

// Each frame has its own colour table (a median cut of its changed pixels): the same picture in
// two frames differs by a few levels in most pixels, and by more in a few rare colours (edge
// pixels whose table entry they share with distant colours): at most 1 pixel in 1000.
constexpr int kQuantisationLevels = 16;
constexpr double kRareColourShare = 1e-3;

struct Decoded {
  int width = 0, height = 0;
  std::vector<int> delays;                       // 1/100 s
  std::vector<std::vector<std::uint32_t>> shown;  // each frame composed over the ones before, 0xRRGGBB
};

Decoded Decode(const std::string& bytes) {
  test::GifSource source{&bytes};
  int error = 0;
  GifFileType* gif = DGifOpen(&source, test::ReadGifBytes, &error);
  REQUIRE(gif != nullptr);
  REQUIRE(DGifSlurp(gif) == GIF_OK);
  Decoded d;
  d.width = gif->SWidth;
  d.height = gif->SHeight;
  std::vector<std::uint32_t> canvas(static_cast<size_t>(d.width) * d.height, 0);
  for (int i = 0; i < gif->ImageCount; ++i) {
    GraphicsControlBlock control;
    REQUIRE(DGifSavedExtensionToGCB(gif, i, &control) == GIF_OK);
    d.delays.push_back(control.DelayTime);
    const SavedImage& image = gif->SavedImages[i];
    const ColorMapObject* map = image.ImageDesc.ColorMap ? image.ImageDesc.ColorMap : gif->SColorMap;
    REQUIRE(map != nullptr);
    for (size_t p = 0; p < canvas.size(); ++p) {
      const int index = image.RasterBits[p];
      if (index == control.TransparentColor) continue;
      const GifColorType c = map->Colors[index];
      canvas[p] = (static_cast<std::uint32_t>(c.Red) << 16) | (c.Green << 8) | c.Blue;
    }
    d.shown.push_back(canvas);
  }
  DGifCloseFile(gif, &error);
  return d;
}

plot::AnimationScene Scene(int frames) {
  const Mechanism m = test::MzcCrankRocker();
  return plot::AnimateCycle(m, {test::CycleOptionsFor(m), frames});
}

}  // namespace

TEST_CASE("GIF options: sizes, pixels and frame rate within their limits", "[export][gif]") {
  std::string why;
  plot::GifOptions o;
  CHECK(o.IsValid(72, &why));
  CHECK(o.DelayCentiseconds() == 4);  // 24 fps: round(100 / 24)
  o.fps = 10;
  CHECK(o.DelayCentiseconds() == 10);
  o.fps = 51;
  CHECK_FALSE(o.IsValid(72, &why));
  o.fps = 24;
  o.width = 0;
  o.height = 0;
  CHECK_FALSE(o.IsValid(72, &why));
  CHECK_THAT(why, Catch::Contains("kMaxAnimationSide"));
  o.width = o.height = kMaxAnimationSide + 1;
  CHECK_FALSE(o.IsValid(1, &why));
  o.width = o.height = kMaxAnimationSide;
  CHECK(o.IsValid(1, &why));
  CHECK_FALSE(o.IsValid(kMaxAnimationFrames, &why));
  CHECK_THAT(why, Catch::Contains("kMaxAnimationPixels"));
}

TEST_CASE("GIF of seed 003's cycle read back with giflib", "[export][gif]") {
  const plot::AnimationScene scene = Scene(12);
  REQUIRE(scene.frames.size() == 12);
  plot::GifOptions o;
  o.width = 200;
  o.height = 150;
  o.fps = 5;
  const Decoded d = Decode(plot::RenderGif(scene, o));
  CHECK(d.width == 200);
  CHECK(d.height == 150);
  REQUIRE(d.shown.size() == 12);
  CHECK(d.delays == std::vector<int>(12, 20));
  // a white background, and every frame differs from the one before where the links moved
  CHECK(d.shown[0][0] == 0xffffff);
  for (int i = 1; i < 12; ++i) CHECK(d.shown[i] != d.shown[i - 1]);
  // frame 5 drawn first (the same frames, so the same view) is the picture composed from the
  // frames before it: the first frame is complete, the later ones hold what changed
  plot::AnimationScene again = scene;
  std::swap(again.frames[0], again.frames[5]);
  const Decoded single = Decode(plot::RenderGif(again, o));
  size_t far = 0;
  for (size_t p = 0; p < single.shown[0].size(); ++p) {
    const std::uint32_t a = single.shown[0][p], b = d.shown[5][p];
    const int diff = std::max({std::abs(int(a >> 16) - int(b >> 16)), std::abs(int((a >> 8) & 255) - int((b >> 8) & 255)),
                               std::abs(int(a & 255) - int(b & 255))});
    far += diff > kQuantisationLevels;
  }
  CHECK(far < kRareColourShare * single.shown[0].size());
  CHECK_THROWS_AS(plot::RenderGif(plot::AnimationScene{}, o), std::invalid_argument);
}

}  // namespace koppel::gif_test
