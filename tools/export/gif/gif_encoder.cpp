#include "gif_encoder.hpp"

#include <gif_lib.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace koppel::plot {
namespace {

int Append(GifFileType* gif, const GifByteType* data, int length) {
  static_cast<std::string*>(gif->UserData)->append(reinterpret_cast<const char*>(data), static_cast<size_t>(length));
  return length;
}

void Check(int result, GifFileType* gif, const char* what) {
  if (result != GIF_OK) throw std::runtime_error(std::string("giflib: ") + what + ": " + GifErrorString(gif ? gif->Error : 0));
}

// 255 colours a frame and the 256th entry transparent (DISPOSE_DO_NOT keeps the frame before).
constexpr int kColours = 255;
constexpr GifByteType kTransparent = 255;

// The colours of the changed pixels: giflib's median cut (on 5 bits per channel), then each
// table entry moved to the mean of the exact colours it stands for, so that a flat area keeps
// its colour (white stays 255, not the cut's 248).
std::vector<GifByteType> Quantise(const std::vector<std::uint32_t>& colours, GifColorType* table) {
  const size_t n = colours.size();
  std::vector<GifByteType> red(n), green(n), blue(n), indices(n);
  for (size_t i = 0; i < n; ++i) {
    red[i] = (colours[i] >> 16) & 0xff;
    green[i] = (colours[i] >> 8) & 0xff;
    blue[i] = colours[i] & 0xff;
  }
  int count = kColours;
  if (GifQuantizeBuffer(static_cast<unsigned>(n), 1, &count, red.data(), green.data(), blue.data(), indices.data(), table) == GIF_ERROR)
    throw std::runtime_error("giflib: cannot quantise a frame");
  std::vector<double> sum(3 * kColours, 0.0);
  std::vector<size_t> members(kColours, 0);
  for (size_t i = 0; i < n; ++i) {
    sum[3 * indices[i]] += red[i], sum[3 * indices[i] + 1] += green[i], sum[3 * indices[i] + 2] += blue[i];
    ++members[indices[i]];
  }
  for (int c = 0; c < kColours; ++c)
    if (members[c] > 0) {
      table[c].Red = static_cast<GifByteType>(std::lround(sum[3 * c] / members[c]));
      table[c].Green = static_cast<GifByteType>(std::lround(sum[3 * c + 1] / members[c]));
      table[c].Blue = static_cast<GifByteType>(std::lround(sum[3 * c + 2] / members[c]));
    }
  return indices;
}


}  // namespace

GifEncoder::GifEncoder(int width, int height, int delay_centiseconds) : width_(width), height_(height), delay_(delay_centiseconds) {
  int error = 0;
  gif_ = EGifOpen(&bytes_, Append, &error);
  if (gif_ == nullptr) throw std::runtime_error(std::string("giflib: cannot start a GIF: ") + GifErrorString(error));
  EGifSetGifVersion(gif_, true);
  Check(EGifPutScreenDesc(gif_, width, height, 8, 0, nullptr), gif_, "screen");
  // the Netscape application extension: loop forever (count 0)
  static const GifByteType kNetscape[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
  static const GifByteType kLoopForever[] = {1, 0, 0};
  Check(EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE), gif_, "loop");
  Check(EGifPutExtensionBlock(gif_, sizeof kNetscape, kNetscape), gif_, "loop");
  Check(EGifPutExtensionBlock(gif_, sizeof kLoopForever, kLoopForever), gif_, "loop");
  Check(EGifPutExtensionTrailer(gif_), gif_, "loop");
}

GifEncoder::~GifEncoder() {
  if (gif_ != nullptr) {
    int error = 0;
    EGifCloseFile(gif_, &error);
  }
}

void GifEncoder::Add(const unsigned char* pixels, int stride) {
  const size_t n = static_cast<size_t>(width_) * height_;
  std::vector<std::uint32_t> frame(n);
  for (int y = 0; y < height_; ++y) std::memcpy(frame.data() + static_cast<size_t>(y) * width_, pixels + static_cast<size_t>(y) * stride, 4 * width_);
  for (std::uint32_t& p : frame) p &= 0xffffff;
  // a pixel the picture did not change stays as shown: transparent over the previous frame
  const bool first = previous_.empty();
  std::vector<std::uint32_t> changed;  // pixel numbers: a frame has at most kMaxAnimationSide^2 < 2^32
  std::vector<std::uint32_t> colours;
  for (size_t i = 0; i < n; ++i)
    if (first || frame[i] != previous_[i]) changed.push_back(static_cast<std::uint32_t>(i)), colours.push_back(frame[i]);
  ColorMapObject* table = GifMakeMapObject(kColours + 1, nullptr);  // + 1: the transparent entry
  if (table == nullptr) throw std::runtime_error("giflib: out of memory");
  std::vector<GifByteType> indices(n, kTransparent);
  if (!changed.empty()) {
    const std::vector<GifByteType> quantised = Quantise(colours, table->Colors);
    for (size_t k = 0; k < changed.size(); ++k) indices[changed[k]] = quantised[k];
  }
  previous_ = std::move(frame);
  // the frame's delay and transparent entry, before its image
  GraphicsControlBlock control{};
  control.DisposalMode = DISPOSE_DO_NOT;
  control.DelayTime = delay_;
  control.TransparentColor = first ? NO_TRANSPARENT_COLOR : kTransparent;
  GifByteType extension[4];
  const size_t length = EGifGCBToExtension(&control, extension);
  int result = EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension);
  if (result == GIF_OK) result = EGifPutImageDesc(gif_, 0, 0, width_, height_, false, table);
  for (int y = 0; y < height_ && result == GIF_OK; ++y) result = EGifPutLine(gif_, indices.data() + static_cast<size_t>(y) * width_, width_);
  GifFreeMapObject(table);
  Check(result, gif_, "frame");
}

std::string GifEncoder::Finish() {
  int error = 0;
  const int result = EGifCloseFile(gif_, &error);
  gif_ = nullptr;
  if (result != GIF_OK) throw std::runtime_error(std::string("giflib: cannot finish the GIF: ") + GifErrorString(error));
  return std::move(bytes_);
}

}  // namespace koppel::plot
