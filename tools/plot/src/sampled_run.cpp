#include "koppel/plot/sampled_run.hpp"

#include "koppel/solver/position.hpp"

#include <cmath>

namespace koppel::plot {

int SampledRun::Column(const Mechanism& mechanism, int output, int component, int k) const {
  // The layout of PositionSolver::OutputDerivatives: output by output, component by component,
  // k = 0..order.
  int column = 0;
  for (int o = 0; o < output; ++o) column += mechanism.outputs[o].Components() * (order + 1);
  return column + component * (order + 1) + k;
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
  if (!run.complete) {
    // Today's sweep stops at the first position it cannot pass: one gap from there to the end.
    // (with no sample at all, the whole requested range is the gap).
    if (sweep.status == SolveStatus::kSingular && !run.inputs.empty()) run.singular.push_back(sweep.stopped_at);
    run.gaps.push_back({run.inputs.empty() ? options.from : sweep.stopped_at, options.to});
  }
  return run;
}

bool PoseAt(const Mechanism& mechanism, const SampledRun& run, double input, Eigen::VectorXd* q, std::string* why) {
  if (run.size() == 0) {
    *why = "no computed sample to start from";
    return false;
  }
  int nearest = 0;
  for (int i = 1; i < run.size(); ++i)
    if (std::abs(run.inputs[i] - input) < std::abs(run.inputs[nearest] - input)) nearest = i;
  PositionSolver solver(mechanism);
  Continuation path(solver);
  const SolveReport start = path.Start(run.inputs[nearest], run.poses.row(nearest).transpose());
  // steps of at most the run's spacing (or 1 degree / 1 % of the length scale for one sample)
  const double step = run.size() > 1 ? std::abs(run.inputs[1] - run.inputs[0])
                                     : (mechanism.InputIsAngle() ? 3.14159265358979323846 / 180 : 0.01 * LengthScale(mechanism));
  const SolveReport report = start.ok() ? path.AdvanceTo(input, step) : start;
  if (!report.ok()) {
    *why = report.message;
    return false;
  }
  *q = path.q();
  return true;
}

}  // namespace koppel::plot
