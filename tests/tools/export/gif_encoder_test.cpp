// GifEncoder (tools/export/src/gif_encoder.cpp) on hand-made frames, read back two ways: the
// bytes of the GIF89a header and the Netscape loop block by hand (GIF89a specification,
// section 17-18, and the Netscape 2.0 application extension), and every frame through giflib's
// decoder (DGifSlurp: its own LZW decoder), composed as a viewer shows them. The reference for
// each pixel is the frame given: with fewer colours than the table holds, each distinct in its
// top 5 bits (the median cut's grid), the picture comes back exactly.
#include "gif_encoder.hpp"

#include "gif_reading.hpp"

#include <gif_lib.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace koppel::gif_encoder_test {
namespace {

struct Frame {
  int delay = 0, disposal = 0, transparent = NO_TRANSPARENT_COLOR;
  std::vector<int> indices;          // the raster as written
  std::vector<std::uint32_t> shown;  // composed over the frames before, 0xRRGGBB
};

std::vector<Frame> Decode(const std::string& bytes, int width, int height) {
  test::GifSource source{&bytes};
  int error = 0;
  GifFileType* gif = DGifOpen(&source, test::ReadGifBytes, &error);
  REQUIRE(gif != nullptr);
  REQUIRE(DGifSlurp(gif) == GIF_OK);
  CHECK(gif->SWidth == width);
  CHECK(gif->SHeight == height);
  std::vector<Frame> frames;
  std::vector<std::uint32_t> canvas(static_cast<size_t>(width) * height, 0);
  for (int i = 0; i < gif->ImageCount; ++i) {
    GraphicsControlBlock control;
    REQUIRE(DGifSavedExtensionToGCB(gif, i, &control) == GIF_OK);
    const SavedImage& image = gif->SavedImages[i];
    REQUIRE(image.ImageDesc.Width == width);
    REQUIRE(image.ImageDesc.Height == height);
    const ColorMapObject* map = image.ImageDesc.ColorMap ? image.ImageDesc.ColorMap : gif->SColorMap;
    REQUIRE(map != nullptr);
    Frame f;
    f.delay = control.DelayTime;
    f.disposal = control.DisposalMode;
    f.transparent = control.TransparentColor;
    for (size_t p = 0; p < canvas.size(); ++p) {
      const int index = image.RasterBits[p];
      f.indices.push_back(index);
      if (index == control.TransparentColor) continue;
      REQUIRE(index < map->ColorCount);
      const GifColorType c = map->Colors[index];
      canvas[p] = (static_cast<std::uint32_t>(c.Red) << 16) | (c.Green << 8) | c.Blue;
    }
    f.shown = canvas;
    frames.push_back(std::move(f));
  }
  DGifCloseFile(gif, &error);
  return frames;
}

const unsigned char* Bytes(const std::vector<std::uint32_t>& pixels) { return reinterpret_cast<const unsigned char*>(pixels.data()); }

// Colours distinct on the median cut's 5-bit grid: each gets a table entry of its own.
constexpr std::uint32_t kWhite = 0xffffff, kBlack = 0x000000, kRed = 0xff0000, kGreen = 0x00ff00, kBlue = 0x0000ff;

}  // namespace

TEST_CASE("GifEncoder: header, loop block and trailer as the GIF89a specification lays them out", "[export][gif]") {
  constexpr int w = 300, h = 2;  // 300 = 0x012c: little-endian 2c 01
  const std::vector<std::uint32_t> pixels(static_cast<size_t>(w) * h, kWhite);
  plot::GifEncoder encoder(w, h, 7);
  encoder.Add(Bytes(pixels), 4 * w);
  const std::string gif = encoder.Finish();
  REQUIRE(gif.size() > 13);
  CHECK(gif.substr(0, 6) == "GIF89a");
  const auto byte = [&](size_t i) { return static_cast<unsigned char>(gif[i]); };
  CHECK(byte(6) == 0x2c);
  CHECK(byte(7) == 0x01);
  CHECK(byte(8) == 2);
  CHECK(byte(9) == 0);
  CHECK((byte(10) & 0x80) == 0);  // no global colour table: each frame has its own
  // right after the 13-byte screen descriptor: the Netscape block, loop count 0 (forever)
  const std::string netscape = "\x21\xff\x0bNETSCAPE2.0\x03\x01\x00\x00\x00";
  CHECK(gif.compare(13, netscape.size(), netscape) == 0);
  CHECK(byte(gif.size() - 1) == 0x3b);  // the trailer
}

TEST_CASE("GifEncoder: frames decode back exactly; later frames hold only what changed", "[export][gif]") {
  constexpr int w = 5, h = 4;
  std::vector<std::uint32_t> first(static_cast<size_t>(w) * h, kWhite);
  first[0] = kBlack, first[7] = kRed, first[13] = kGreen, first[19] = kBlue;
  std::vector<std::uint32_t> second = first;
  second[7] = kBlue, second[8] = kBlack;  // two pixels change
  plot::GifEncoder encoder(w, h, 12);
  encoder.Add(Bytes(first), 4 * w);
  encoder.Add(Bytes(second), 4 * w);
  encoder.Add(Bytes(second), 4 * w);  // nothing changes
  const std::vector<Frame> frames = Decode(encoder.Finish(), w, h);
  REQUIRE(frames.size() == 3);
  for (const Frame& f : frames) {
    CHECK(f.delay == 12);
    CHECK(f.disposal == DISPOSE_DO_NOT);
  }
  // the first frame is complete: no transparent entry
  CHECK(frames[0].transparent == NO_TRANSPARENT_COLOR);
  CHECK(frames[0].shown == first);
  // the second: transparent everywhere but the two changed pixels, shown as the frame given
  REQUIRE(frames[1].transparent != NO_TRANSPARENT_COLOR);
  for (size_t p = 0; p < second.size(); ++p) {
    INFO("pixel " << p);
    CHECK((frames[1].indices[p] != frames[1].transparent) == (p == 7 || p == 8));
  }
  CHECK(frames[1].shown == second);
  // the third: all transparent, the picture unchanged
  CHECK(std::set<int>(frames[2].indices.begin(), frames[2].indices.end()) == std::set<int>{frames[2].transparent});
  CHECK(frames[2].shown == second);
}

TEST_CASE("GifEncoder: rows `stride` bytes apart, the padding and the unused top byte ignored", "[export][gif]") {
  constexpr int w = 3, h = 3, kPad = 2;  // two words of garbage at the end of each row
  std::vector<std::uint32_t> tight(static_cast<size_t>(w) * h), padded(static_cast<size_t>(w + kPad) * h, 0xdeadbeef);
  const std::uint32_t colours[] = {kWhite, kBlack, kRed, kGreen, kBlue};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      tight[y * w + x] = colours[(x + 2 * y) % 5];
      padded[y * (w + kPad) + x] = tight[y * w + x] | 0xab000000;  // cairo's RGB24 leaves the top byte undefined
    }
  plot::GifEncoder a(w, h, 4), b(w, h, 4);
  a.Add(Bytes(tight), 4 * w);
  b.Add(Bytes(padded), 4 * (w + kPad));
  const std::vector<Frame> from_tight = Decode(a.Finish(), w, h), from_padded = Decode(b.Finish(), w, h);
  REQUIRE(from_tight.size() == 1);
  REQUIRE(from_padded.size() == 1);
  CHECK(from_tight[0].shown == tight);
  CHECK(from_padded[0].shown == tight);
}

TEST_CASE("GifEncoder: more colours than a table holds; a flat area keeps its exact colour", "[export][gif]") {
  // 1024 distinct colours (a red-green ramp) over a white half: the median cut merges the ramp,
  // but each table entry is the mean of the colours it stands for, so white (alone in its
  // 5-bit cell) comes back 255, not the cut's 248
  constexpr int w = 64, h = 32;
  std::vector<std::uint32_t> pixels(static_cast<size_t>(w) * h, kWhite);
  for (int i = 0; i < w * h / 2; ++i) pixels[i] = (static_cast<std::uint32_t>(i % 32 * 4) << 16) | (static_cast<std::uint32_t>(i / 32 * 2) << 8) | 0x40;
  plot::GifEncoder encoder(w, h, 4);
  encoder.Add(Bytes(pixels), 4 * w);
  const std::vector<Frame> frames = Decode(encoder.Finish(), w, h);
  REQUIRE(frames.size() == 1);
  for (int i = w * h / 2; i < w * h; ++i) CHECK(frames[0].shown[i] == kWhite);
  // the ramp covers 128 cells of the cut's 5-bit grid (cells 8 levels wide), fewer than the
  // table's 255 entries: each entry is the mean of the colours of one cell, within 7 levels of each
  constexpr int kFiveBitCell = 8;
  int far = 0;
  for (int i = 0; i < w * h / 2; ++i) {
    const std::uint32_t a = pixels[i], b = frames[0].shown[i];
    for (const int shift : {16, 8, 0}) far += std::abs(static_cast<int>((a >> shift) & 255) - static_cast<int>((b >> shift) & 255)) >= kFiveBitCell;
  }
  CHECK(far == 0);
}

}  // namespace koppel::gif_encoder_test
