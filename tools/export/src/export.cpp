#include "koppel/export/export.hpp"

#include <stdexcept>

namespace koppel::plot {

ExportResult ExportDxf(const Mechanism& m, const WorkshopOptions& options, int insunits) {
  const WorkshopDrawing drawing = DrawWorkshop(m, options);
  ExportResult result{drawing.status, drawing.message, ""};
  if (drawing.status != PlotStatus::kFailed) result.bytes = WriteDxf(drawing, insunits);
  return result;
}

ExportResult AnimateGif(const Mechanism& m, const AnimationOptions& options, const GifOptions& gif) {
  std::string why;
  if (!gif.IsValid(options.frames, &why)) throw std::invalid_argument("AnimateGif: " + why);
  const AnimationScene scene = AnimateCycle(m, options);
  ExportResult result{scene.status, scene.message, ""};
  if (scene.status != PlotStatus::kFailed) result.bytes = RenderGif(scene, gif);
  return result;
}

}  // namespace koppel::plot
