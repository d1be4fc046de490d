#include "koppel/plot/workshop.hpp"

#include "koppel/plot/svg.hpp"
#include "plot_support.hpp"

#include <fmt/core.h>

#include <stdexcept>

namespace koppel::plot {

namespace {

WorkshopDrawing FailedDrawing(const std::string& message) {
  WorkshopDrawing drawing;
  drawing.status = PlotStatus::kFailed;
  drawing.message = message;
  return drawing;
}

}  // namespace

WorkshopDrawing DrawWorkshop(const Mechanism& m, const WorkshopOptions& options) {
  std::string why;
  if (!options.cycle.IsValid(&why)) throw std::invalid_argument("DrawWorkshop: " + why);
  const Expected<CycleSamples> samples = SampleCycle(m, options.cycle);
  if (!samples) return FailedDrawing(samples.error());
  const double input = options.at.value_or(m.hint.input);
  const Expected<Eigen::VectorXd> pose = PoseOnCycle(m, *samples, input);
  if (!pose) return FailedDrawing("cannot reach " + InputName(m) + " = " + fmt::format("{:.12g}", ShownInput(m, input)) + ": " + pose.error());
  WorkshopDrawing drawing;
  drawing.input = input;
  drawing.range = samples->range;
  drawing.parts = PartsAtPose(m, *pose, samples->travel, options.cycle.sizes);
  drawing.curves = samples->curves;
  if (!samples->run.complete) {
    drawing.status = PlotStatus::kPartial;
    drawing.message = samples->run.message;
  }
  if (!samples->range.note.empty()) drawing.message += (drawing.message.empty() ? "" : "; ") + samples->range.note;
  return drawing;
}

}  // namespace koppel::plot
