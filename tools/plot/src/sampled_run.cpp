#include "koppel/plot/sampled_run.hpp"
#include "koppel/core/angles.hpp"

#include "koppel/solver/position.hpp"

#include <algorithm>
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
  run.complete = sweep.complete();
  run.message = sweep.message;
  // the rows between two gaps are one contiguous stretch of the branch (an R drive's rows a turn
  // away from the assembly's are the branch a turn on: the sweep maps them); the singular points
  // met are marked where the range shows them (modulo a turn for an R drive)
  for (const InputInterval& g : sweep.gaps) run.gaps.push_back({g.from, g.to});
  int begin = 0;
  for (int i = 0; i + 1 < run.size(); ++i) {
    const double a = std::min(run.inputs[i], run.inputs[i + 1]), b = std::max(run.inputs[i], run.inputs[i + 1]);
    const bool gap_between = std::any_of(sweep.gaps.begin(), sweep.gaps.end(), [&](const InputInterval& g) {
      return std::min(g.from, g.to) >= a && std::max(g.from, g.to) <= b;
    });
    if (gap_between) {
      run.stretches.push_back({begin, i + 1});
      begin = i + 1;
    }
  }
  if (!run.inputs.empty()) run.stretches.push_back({begin, run.size()});
  const double low = std::min(options.from, options.to), high = std::max(options.from, options.to), turn = 2 * kPi;
  for (const SingularPoint& p : sweep.singular_points) {
    if (!mechanism.InputIsAngle()) {
      run.singular.push_back(p.input);
      continue;
    }
    bool shown = false;
    for (double k = std::ceil((low - p.input) / turn); p.input + k * turn <= high; ++k) {
      run.singular.push_back(p.input + k * turn);
      shown = true;
    }
    if (!shown) run.singular.push_back(p.input);
  }
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
