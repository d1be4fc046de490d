// Frames to a GIF file with giflib: GIF89a that loops forever, each frame shown for a fixed
// delay. A frame holds only the pixels that changed since the one before (the rest transparent,
// so the mostly still picture costs little), quantised to 255 colours (giflib's median cut,
// GifQuantizeBuffer) in its own colour table.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

struct GifFileType;

namespace koppel::plot {

class GifEncoder {
 public:
  // Throws std::runtime_error when giflib fails.
  GifEncoder(int width, int height, int delay_centiseconds);
  ~GifEncoder();
  GifEncoder(const GifEncoder&) = delete;
  GifEncoder& operator=(const GifEncoder&) = delete;

  // One frame from 32-bit pixels 0x00RRGGBB (cairo's RGB24), rows `stride` bytes apart.
  void Add(const unsigned char* pixels, int stride);
  // The file's bytes; no frame can be added after.
  std::string Finish();

 private:
  int width_, height_, delay_;
  GifFileType* gif_ = nullptr;
  std::string bytes_;
  std::vector<std::uint32_t> previous_;  // the last frame's pixels, 0x00RRGGBB
};

}  // namespace koppel::plot
