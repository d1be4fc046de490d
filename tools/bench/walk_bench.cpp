// Walk steps: the generic solver's continuation step with the transfer functions of every output
// up to 2nd order (positions, 1st, 2nd order, as `koppel analyze` computes each row) against a
// hand-written closed form doing the same work, and chains of loops against the 4-loop chain per
// loop. One benchmark iteration walks a full turn in steps of 1 deg, up and down by turns, so the
// walk never leaves the first turn (angles stay small) and never restarts.
#include "bench.hpp"
#include "bench_mechanisms.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/assembly.hpp"
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/point_schedule.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace koppel::bench {
namespace walk_bench {  // this file's own names, apart from the other benchmarks' in a unity build
namespace {

constexpr int kStepsPerTurn = 360;
const double kStep = DegToRad(1.0);
// The generic solver must agree with the closed form before it is timed (the closed forms
// are exact; the solver converges to 1e-13 L).
constexpr double kAgreement = 1e-9;

// A mechanism walking to and fro over one turn from its assembly.
class Walker {
 public:
  explicit Walker(Mechanism mechanism)
      : mechanism_(std::make_unique<Mechanism>(std::move(mechanism))), solver_(*mechanism_), path_(solver_) {
    const Assembly assembly = AssembleRegular(*mechanism_, solver_);
    if (!assembly.ok()) {
      error_ = mechanism_->name + ": " + assembly.error;
      return;
    }
    start_ = assembly.input;
    path_.Start(assembly.input, assembly.q);
    row_.resize(solver_.OutputWidth(2));
  }
  const std::string& error() const { return error_; }
  const std::vector<double>& row() const { return row_; }
  double input() const { return path_.input(); }

  // One step of 1 deg along the turn, then back; with `transfer`, every output and its 1st and
  // 2nd derivative into row().
  bool Step(bool transfer) {
    const double next = start_ + (up_ ? at_ + 1 : kStepsPerTurn - 1 - at_) * kStep;
    if (!path_.AdvanceTo(next, std::numeric_limits<double>::infinity()).ok()) return false;
    if (transfer) path_.OutputDerivatives(2, row_.data());
    if (++at_ == kStepsPerTurn) {
      at_ = 0;
      up_ = !up_;
    }
    return true;
  }
  bool Steps(int count, bool transfer) {
    for (int i = 0; i < count; ++i) {
      if (!Step(transfer)) return false;
      // The solved pose is the walk's state (joint points, link origins, cos and sin); the link
      // angles as numbers are written when read (Continuation::q), which a row of outputs does
      // not need, nor the positions libslvs is compared with (its points).
      benchmark::DoNotOptimize(row_.data());
    }
    return true;
  }

 private:
  std::unique_ptr<Mechanism> mechanism_;
  PositionSolver solver_;
  Continuation path_;
  std::vector<double> row_;
  double start_ = 0.0;
  int at_ = 0;  // steps taken in this turn
  bool up_ = true;
  std::string error_;
};

// The walk of `mechanism`, checked first over one turn against `check(input, row)` (empty when
// no closed form exists).
void TimeWalk(benchmark::State& state, const Mechanism& mechanism, bool transfer, int steps,
              const std::function<double(double, const std::vector<double>&)>& check) {
  Walker walker(mechanism);
  if (!walker.error().empty()) {
    state.SkipWithError(walker.error().c_str());
    return;
  }
  if (check) {
    double worst = 0.0;
    for (int i = 0; i < kStepsPerTurn; ++i) {
      if (!walker.Step(true)) break;
      worst = std::max(worst, check(walker.input(), walker.row()));
    }
    if (!(worst <= kAgreement)) {
      const std::string message = mechanism.name + ": the solver and the closed form differ by " + std::to_string(worst);
      state.SkipWithError(message.c_str());
      return;
    }
  }
  for (auto _ : state) {
    if (!walker.Steps(steps, transfer)) {
      state.SkipWithError((mechanism.name + ": the walk failed").c_str());
      return;
    }
  }
}

// The compiled joint-point step (point_schedule.hpp) over the same walk: positions, then every
// output and its 1st and 2nd derivative from the schedule's jets, without the continuation.
void TimePointWalk(benchmark::State& state, const Mechanism& mechanism,
                   const std::function<double(double, const std::vector<double>&)>& check) {
  PositionSolver solver(mechanism);
  const Assembly assembly = AssembleRegular(mechanism, solver);
  Continuation path(solver);
  PointSchedule schedule(solver.system());
  if (!assembly.ok() || !path.Start(assembly.input, assembly.q).ok() || !schedule.compiled()) {
    state.SkipWithError((mechanism.name + ": not assembled or not compiled: " + schedule.why_not()).c_str());
    return;
  }
  schedule.Load(path.input(), path.q(), path.Series(2));
  std::vector<double> row(solver.OutputWidth(2));
  int at = 0;
  bool up = true;
  auto step = [&] {
    const double next = assembly.input + (up ? at + 1 : kStepsPerTurn - 1 - at) * kStep;
    if (!schedule.Step(next)) return false;
    schedule.OutputDerivatives(2, row.data());
    if (++at == kStepsPerTurn) {
      at = 0;
      up = !up;
    }
    return true;
  };
  double worst = 0.0;
  for (int i = 0; i < kStepsPerTurn; ++i) {
    if (!step()) break;
    const double input = assembly.input + (up ? at : kStepsPerTurn - at) * kStep;
    worst = std::max(worst, check(input, row));
  }
  if (!(worst <= kAgreement)) {
    state.SkipWithError((mechanism.name + ": the schedule and the closed form differ by " + std::to_string(worst)).c_str());
    return;
  }
  for (auto _ : state) {
    for (int i = 0; i < kStepsPerTurn; ++i) {
      if (!step()) {
        state.SkipWithError((mechanism.name + ": the compiled walk failed").c_str());
        return;
      }
      benchmark::DoNotOptimize(row.data());
    }
  }
}

double Deviation(const Jet& jet, const double* row) {
  return std::max({std::abs(jet.v - row[0]), std::abs(jet.d1 - row[1]), std::abs(jet.d2 - row[2])});
}

double FourBarCheck(double phi, const std::vector<double>& row) {
  const FourBarValues v = SeedFourBarClosedForm(phi);
  return std::max({Deviation(v.kx, &row[0]), Deviation(v.ky, &row[3]), Deviation(v.psi, &row[6]), Deviation(v.mu, &row[9])});
}

double SliderCrankCheck(double phi, const std::vector<double>& row) {
  const SliderCrankValues v = SeedSliderCrankClosedForm(phi);
  return std::max(Deviation(v.s, &row[0]), Deviation(v.mu, &row[3]));
}

double ProportionalCheck(double phi, const std::vector<double>& row) { return Deviation(SeedProportionalClosedForm(phi), &row[0]); }

// The closed form over the same inputs as a walk: one turn per iteration.
template <class Values>
void TimeClosedForm(benchmark::State& state, Values (*closed_form)(double)) {
  bool up = true;
  for (auto _ : state) {
    for (int i = 0; i < kStepsPerTurn; ++i) {
      Values v = closed_form((up ? i + 1 : kStepsPerTurn - 1 - i) * kStep);
      benchmark::DoNotOptimize(v);
    }
    up = !up;
  }
}

Case StepCase(std::string name, std::string baseline, int steps, std::function<void(benchmark::State&)> run, double factor = 1.0) {
  Case c;
  c.name = std::move(name);
  c.per = Per::kStep;
  c.steps_per_iteration = steps;
  c.baseline = std::move(baseline);
  c.baseline_factor = factor;
  c.run = std::move(run);
  return c;
}

template <class Values>
Case ClosedFormCase(std::string name, Values (*closed_form)(double)) {
  return StepCase(std::move(name), "", kStepsPerTurn, [closed_form](benchmark::State& s) { TimeClosedForm(s, closed_form); });
}

Case WalkCase(std::string name, Mechanism (*mechanism)(), std::function<double(double, const std::vector<double>&)> check) {
  return StepCase(name, name + "-closed-form", kStepsPerTurn,
                  [mechanism, check](benchmark::State& s) { TimeWalk(s, mechanism(), true, kStepsPerTurn, check); });
}

}  // namespace
}  // namespace walk_bench

std::vector<Case> WalkCases() {
  using namespace walk_bench;
  std::vector<Case> cases;
  cases.push_back(ClosedFormCase("fourbar-closed-form", SeedFourBarClosedForm));
  cases.push_back(WalkCase("fourbar", SeedFourBar, FourBarCheck));
  cases.push_back(ClosedFormCase("slider-crank-closed-form", SeedSliderCrankClosedForm));
  cases.push_back(WalkCase("slider-crank", SeedSliderCrank, SliderCrankCheck));
  cases.push_back(StepCase("fourbar-compiled", "fourbar-closed-form", kStepsPerTurn,
                           [](benchmark::State& s) { TimePointWalk(s, SeedFourBar(), FourBarCheck); }));
  cases.push_back(StepCase("slider-crank-compiled", "slider-crank-closed-form", kStepsPerTurn,
                           [](benchmark::State& s) { TimePointWalk(s, SeedSliderCrank(), SliderCrankCheck); }));
  cases.push_back(ClosedFormCase("proportional-closed-form", SeedProportionalClosedForm));
  cases.push_back(WalkCase("proportional", SeedProportional, ProportionalCheck));
  for (int loops : {4, 16, 128}) {
    // fewer steps per iteration for the long chains, so that one iteration stays short
    const int steps = loops <= 16 ? kStepsPerTurn : 10;
    cases.push_back(StepCase("chain" + std::to_string(loops), loops == 4 ? "" : "chain4", steps,
                             [loops, steps](benchmark::State& s) { TimeWalk(s, Chain(loops), true, steps, nullptr); }, loops / 4.0));
  }
  return cases;
}

// The positions alone (the walk step without the outputs' transfer functions), the side of the
// libslvs comparison that koppel runs.
void TimeFourBarPositions(benchmark::State& state) {
  using namespace walk_bench;
  TimeWalk(state, SeedFourBar(), false, kStepsPerTurn, FourBarCheck);
}

// The closed form of the same positions over the same inputs, checked first against the walk's
// reference closed form (SeedFourBarClosedForm's K).
void TimeFourBarPositionsClosedForm(benchmark::State& state) {
  using namespace walk_bench;
  double worst = 0.0;
  for (int i = 0; i < kStepsPerTurn; ++i) {
    const FourBarPoints p = SeedFourBarPositionsClosedForm(i * kStep);
    const FourBarValues v = SeedFourBarClosedForm(i * kStep);
    worst = std::max({worst, std::abs(p.kx - v.kx.v), std::abs(p.ky - v.ky.v)});
  }
  if (!(worst <= kAgreement)) {
    state.SkipWithError(("the two closed forms differ by " + std::to_string(worst)).c_str());
    return;
  }
  TimeClosedForm(state, SeedFourBarPositionsClosedForm);
}

}  // namespace koppel::bench
