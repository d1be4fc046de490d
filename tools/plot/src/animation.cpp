#include "koppel/plot/animation.hpp"

#include "koppel/core/limits.hpp"
#include "koppel/plot/svg.hpp"
#include "plot_support.hpp"

#include <stdexcept>

namespace koppel::plot {

bool AnimationOptions::IsValid(std::string* why) const {
  if (!cycle.IsValid(why)) return false;
  if (frames < 1 || frames > kMaxAnimationFrames)
    *why = "the number of frames must be 1 .. " + std::to_string(kMaxAnimationFrames) + " (kMaxAnimationFrames)";
  return why->empty();
}

AnimationScene AnimateCycle(const Mechanism& m, const AnimationOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("AnimateCycle: " + why);
  AnimationScene scene;
  auto fail = [&](const std::string& message) {
    scene.status = PlotStatus::kFailed;
    scene.message = message;
    return scene;
  };
  const Expected<CycleSamples> samples = SampleCycle(m, options.cycle);
  if (!samples) return fail(samples.error());
  const CycleRange& range = samples->range;
  scene.range = range;
  scene.curves = samples->curves;
  std::vector<std::string> problems;
  if (!samples->run.complete) problems.push_back(samples->run.message);
  const std::vector<double> inputs = CycleInputs(range, options.frames);
  for (int i = 0; i < options.frames; ++i) {
    const Expected<Eigen::VectorXd> pose = PoseOnCycle(m, *samples, inputs[i]);
    if (!pose) {
      problems.push_back("frame " + std::to_string(i) + " at " + InputName(m) + " = " + Num(ShownInput(m, inputs[i]), 6) +
                         " left out: " + pose.error());
      continue;
    }
    AnimationFrame frame;
    frame.input = inputs[i];
    frame.traced_up_to = TracedUpTo(range, options.frames, i);
    frame.caption = m.name + "   " + InputName(m) + " = " + Num(ShownInput(m, inputs[i]), 1) + (m.InputIsAngle() ? "°" : "");
    frame.parts = PartsAtPose(m, *pose, samples->travel, options.cycle.sizes);
    scene.frames.push_back(std::move(frame));
  }
  if (scene.frames.empty()) return fail(problems.empty() ? "no frame could be computed" : problems.back());
  for (const std::string& p : problems) scene.message += (scene.message.empty() ? "" : "; ") + p;
  if (!problems.empty()) scene.status = PlotStatus::kPartial;
  if (!range.note.empty()) scene.message += (scene.message.empty() ? "" : "; ") + range.note;
  return scene;
}

}  // namespace koppel::plot
