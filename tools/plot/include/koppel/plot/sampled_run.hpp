// The one adapter between the kernel's sweep and the pictures: every plot, scheme and page reads
// its samples from a SampledRun, never from SweepResult directly, so that a change of the sweep's
// result (singular rows, gap intervals) is absorbed here.
//
// A run is a list of samples split into stretches: a line is drawn through the samples of one
// stretch only, never across a gap or a singular position.
#pragma once

#include "koppel/core/expected.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/sweep.hpp"

#include <string>
#include <vector>

namespace koppel::plot {

struct Stretch {
  int begin = 0, end = 0;  // sample indices [begin, end)
};

struct InputGap {
  double from = 0, to = 0;  // inputs that were requested but not computed
};

struct SampledRun {
  int order = 2;
  std::vector<double> inputs;      // radians (R drive) or length, computed samples only
  Table outputs;                   // inputs.size() x OutputWidth(order), see PositionSolver
  Table poses;                     // inputs.size() x NumCoordinates()
  std::vector<Stretch> stretches;  // runs of samples joined by the solver's continuation
  std::vector<double> singular;    // inputs where the solver met a singular position
  std::vector<InputGap> gaps;      // requested inputs not computed
  bool complete = true;
  std::string message;             // why the run is incomplete

  int size() const { return static_cast<int>(inputs.size()); }
  // Column of output `output`, component (0 = x, 1 = y), derivative order k in `outputs`.
  int Column(const Mechanism& mechanism, int output, int component, int k) const;
};

// Sweeps the mechanism over options.from..to (Sweep: assembled at the file's hint, continued
// along its branch).
SampledRun SampleMechanism(const Mechanism& mechanism, const SweepOptions& options);

// The pose at `input`, continued from the nearest computed sample of the run (so on the run's
// assembly branch): the coordinates q, or why the solver cannot get there.
Expected<Eigen::VectorXd> PoseAt(const Mechanism& mechanism, const SampledRun& run, double input);

}  // namespace koppel::plot
