#include "koppel/plot/workshop.hpp"

#include "koppel/plot/svg.hpp"
#include "plot_support.hpp"

#include <stdexcept>

namespace koppel::plot {

WorkshopDrawing DrawWorkshop(const Mechanism& m, const WorkshopOptions& options) {
  std::string why;
  if (!options.cycle.IsValid(&why)) throw std::invalid_argument("DrawWorkshop: " + why);
  WorkshopDrawing drawing;
  auto fail = [&](const std::string& message) {
    drawing.status = PlotStatus::kFailed;
    drawing.message = message;
    return drawing;
  };
  const Expected<CycleRange> range = CycleRangeOf(m, options.cycle.sweep);
  if (!range) return fail(range.error());
  drawing.range = *range;
  const Expected<CycleSamples> samples = SampleCycle(m, *range, options.cycle.traced, options.cycle.sweep.continuation);
  if (!samples) return fail(samples.error());
  drawing.input = options.at.value_or(m.hint.input);
  const Expected<Eigen::VectorXd> pose = PoseAt(m, samples->run, drawing.input);
  if (!pose) return fail("cannot reach " + InputName(m) + " = " + Num(ShownInput(m, drawing.input), 6) + ": " + pose.error());
  drawing.parts = PartsAtPose(m, *pose, samples->travel, options.cycle.sizes);
  drawing.curves = samples->curves;
  if (!samples->run.complete) {
    drawing.status = PlotStatus::kPartial;
    drawing.message = samples->run.message;
  }
  if (!range->note.empty()) drawing.message += (drawing.message.empty() ? "" : "; ") + range->note;
  return drawing;
}

}  // namespace koppel::plot
