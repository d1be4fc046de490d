// The module libkoppel_gif.so (gif_module.hpp): RenderGif's frames painted with cairo, encoded
// with giflib.
#include "gif_module.hpp"

#include "frame_painter.hpp"
#include "gif_encoder.hpp"

namespace koppel::plot {
namespace {

std::string RenderFrames(const AnimationScene& scene, int width, int height, int delay_centiseconds) {
  FramePainter painter(scene, width, height);
  GifEncoder encoder(width, height, delay_centiseconds);
  for (int i = 0; i < static_cast<int>(scene.frames.size()); ++i) {
    painter.Paint(i);
    encoder.Add(cairo_image_surface_get_data(painter.surface()), cairo_image_surface_get_stride(painter.surface()));
  }
  return encoder.Finish();
}

const GifModuleTable kTable{{KOPPEL_MODULE_VERSION}, &RenderFrames};

}  // namespace
}  // namespace koppel::plot

extern "C" __attribute__((visibility("default"))) const koppel::ModuleTable* koppel_gif_module() { return &koppel::plot::kTable; }
