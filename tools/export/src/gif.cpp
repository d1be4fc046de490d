#include "koppel/export/gif.hpp"

#include "gif_module.hpp"

#include "koppel/core/limits.hpp"

#include <cmath>
#include <stdexcept>

namespace koppel::plot {
namespace {

// A picture smaller than this has no room for the caption and the margins.
constexpr int kMinSide = 16;
// GIF delays are whole 1/100 s; browsers show delays under 2/100 s as 10/100 s, so 50 fps is the
// fastest that plays as asked. 0.1 fps: a frame every 10 s, a slide show.
constexpr double kMaxFps = 50, kMinFps = 0.1;

}  // namespace

bool GifOptions::IsValid(int frames, std::string* why) const {
  why->clear();
  if (width < kMinSide || height < kMinSide || width > kMaxAnimationSide || height > kMaxAnimationSide)
    *why = "the picture's sides must be " + std::to_string(kMinSide) + " .. " + std::to_string(kMaxAnimationSide) +
           " px (kMaxAnimationSide)";
  else if (static_cast<double>(frames) * width * height > static_cast<double>(kMaxAnimationPixels))
    *why = "frames x width x height must be at most " + std::to_string(kMaxAnimationPixels) + " px (kMaxAnimationPixels)";
  else if (!(fps >= kMinFps && fps <= kMaxFps))
    *why = "the frame rate must be 0.1 .. 50 frames per second (a GIF counts its delays in 1/100 s)";
  return why->empty();
}

int GifOptions::DelayCentiseconds() const { return static_cast<int>(std::lround(100 / fps)); }

std::string RenderGif(const AnimationScene& scene, const GifOptions& options) {
  std::string why;
  if (!options.IsValid(static_cast<int>(scene.frames.size()), &why)) throw std::invalid_argument("RenderGif: " + why);
  if (scene.frames.empty()) throw std::invalid_argument("RenderGif: no frame to draw");
  return GifModule().render(scene, options.width, options.height, options.DelayCentiseconds());
}

}  // namespace koppel::plot
