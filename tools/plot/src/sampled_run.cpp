#include "koppel/plot/sampled_run.hpp"
#include "koppel/core/angles.hpp"

#include "koppel/solver/position.hpp"

#include <cmath>

namespace koppel::plot {

int SampledRun::Column(const Mechanism& mechanism, int output, int component, int k) const {
  return OutputColumn(mechanism, output, component, order) + k;
}

SampledRun SampleMechanism(const Mechanism& mechanism, const SweepOptions& options) {
  const SweepResult sweep = Sweep(mechanism, options);
  SampledRun run;
  run.order = sweep.order;
  run.inputs = sweep.inputs;
  run.outputs = sweep.outputs;
  run.poses = sweep.poses;
  if (!run.inputs.empty()) run.stretches.push_back({0, run.size()});
  run.complete = sweep.complete();
  run.message = sweep.message;
  // the rows of a sweep are one contiguous stretch of the branch (it walks outward from the
  // assembly); what lies beyond is a gap, and the singular points met are marked
  for (const SingularPoint& p : sweep.singular_points) run.singular.push_back(p.input);
  for (const InputInterval& g : sweep.gaps) run.gaps.push_back({g.from, g.to});
  return run;
}

Expected<Eigen::VectorXd> PoseAt(const Mechanism& mechanism, const SampledRun& run, double input) {
  using Result = Expected<Eigen::VectorXd>;
  if (run.size() == 0) return Result::Error("no computed sample to start from");
  int nearest = 0;
  for (int i = 1; i < run.size(); ++i)
    if (std::abs(run.inputs[i] - input) < std::abs(run.inputs[nearest] - input)) nearest = i;
  PositionSolver solver(mechanism);
  Continuation path(solver);
  const SolveReport start = path.Start(run.inputs[nearest], run.poses.row(nearest).transpose());
  // steps of at most the run's spacing (or 1 degree / 1 % of the length scale for one sample)
  const double step = run.size() > 1 ? std::abs(run.inputs[1] - run.inputs[0])
                                     : (mechanism.InputIsAngle() ? kPi / 180 : 0.01 * LengthScale(mechanism));
  if (!start.ok()) return Result::Error(start.message);
  const WalkReport report = path.AdvanceTo(input, step);
  if (!report.ok()) return Result::Error(report.message);
  return Eigen::VectorXd(path.q());
}

}  // namespace koppel::plot
