// The GIF's frames are drawn by cairo and encoded by giflib in the module libkoppel_gif.so
// (tools/export/gif), loaded by the first RenderGif (koppel/core/module.hpp): cairo brings X11,
// fontconfig, freetype and pixman, twenty libraries no other command needs at start-up.
#pragma once

#include "koppel/core/module.hpp"
#include "koppel/export/gif.hpp"

#include <string>

namespace koppel::plot {

struct GifModuleTable : ModuleTable {
  // RenderGif's work, its preconditions checked by it (gif.hpp): the file's bytes
  std::string (*render)(const AnimationScene& scene, int width, int height, int delay_centiseconds);
};

// Loaded on the first call; std::runtime_error when it cannot be loaded.
inline const GifModuleTable& GifModule() { return static_cast<const GifModuleTable&>(LoadModule("gif")); }

}  // namespace koppel::plot
