// Side by side with SolveSpace's constraint solver (libslvs, Debian libslvs1-dev), in the same
// process: the positions of seed 003's four-bar per step of 1 deg. libslvs solves the sketch
// A0, A, B, B0, K with the crank point A set from the input and B, K free under the distances
// AB, B0B, AK, BK, from the previous step's solution; koppel walks the same mechanism (positions
// only: the continuation step, without the outputs' transfer functions).
#include "bench.hpp"
#include "bench_mechanisms.hpp"

#include "koppel/core/angles.hpp"

#ifdef KOPPEL_HAVE_SLVS
#include <dlfcn.h>
#include <slvs.h>
#endif

#include <cmath>
#include <string>
#include <vector>

namespace koppel::bench {

void TimeFourBarPositions(benchmark::State& state);            // walk_bench.cpp
void TimeFourBarPositionsClosedForm(benchmark::State& state);  // walk_bench.cpp

#ifdef KOPPEL_HAVE_SLVS
namespace slvs_bench {  // this file's own names, apart from the other benchmarks' in a unity build
namespace {

constexpr int kStepsPerTurn = 360;
constexpr double kAgreement = 1e-9;  // libslvs converges to about 1e-10 of the sketch's size

// libslvs is loaded here, by the one benchmark that calls it, not by every start of koppel (its
// static initialisers and libgomp took 2 ms of `koppel --version`, issue 25). Everything else of
// slvs.h is inline. Null, with *why, when it cannot be loaded.
using SlvsSolveFunction = void (*)(Slvs_System*, Slvs_hGroup);
SlvsSolveFunction LoadSlvsSolve(std::string* why) {
  void* library = dlopen(KOPPEL_SLVS_LIBRARY, RTLD_NOW | RTLD_LOCAL);
  void* solve = library ? dlsym(library, "Slvs_Solve") : nullptr;
  if (!solve) *why = std::string("libslvs could not be loaded: ") + dlerror();
  return reinterpret_cast<SlvsSolveFunction>(solve);
}

class SlvsFourBar {
 public:
  explicit SlvsFourBar(SlvsSolveFunction solve) : solve_(solve) {
    const Mechanism m = SeedFourBar();
    const Eigen::Vector2d b0 = m.links[0].points[1].local;
    const double l1 = m.links[1].points[1].local.x(), l2 = m.links[2].points[1].local.x(), l3 = m.links[3].points[1].local.x();
    const Eigen::Vector2d k = m.links[2].points[2].local;
    const FourBarValues start = SeedFourBarClosedForm(0.0);
    const double psi = start.psi.v;
    const Eigen::Vector2d b = b0 + l3 * Eigen::Vector2d(std::cos(psi), std::sin(psi));
    // group 1: the workplane, A0, B0 and the crank point A (set per step); group 2: B and K
    params_ = {Slvs_MakeParam(1, 1, 0), Slvs_MakeParam(2, 1, 0), Slvs_MakeParam(3, 1, 0),                         // origin
               Slvs_MakeParam(4, 1, 1), Slvs_MakeParam(5, 1, 0), Slvs_MakeParam(6, 1, 0), Slvs_MakeParam(7, 1, 0),  // normal
               Slvs_MakeParam(10, 1, 0), Slvs_MakeParam(11, 1, 0),                                                  // A0
               Slvs_MakeParam(12, 1, l1), Slvs_MakeParam(13, 1, 0),                                                 // A
               Slvs_MakeParam(14, 1, b0.x()), Slvs_MakeParam(15, 1, b0.y()),                                       // B0
               Slvs_MakeParam(16, 2, b.x()), Slvs_MakeParam(17, 2, b.y()),                                         // B
               Slvs_MakeParam(18, 2, start.kx.v), Slvs_MakeParam(19, 2, start.ky.v)};                              // K
    entities_ = {Slvs_MakePoint3d(101, 1, 1, 2, 3), Slvs_MakeNormal3d(102, 1, 4, 5, 6, 7), Slvs_MakeWorkplane(200, 1, 101, 102),
                 Slvs_MakePoint2d(301, 1, 200, 10, 11), Slvs_MakePoint2d(302, 1, 200, 12, 13), Slvs_MakePoint2d(303, 1, 200, 14, 15),
                 Slvs_MakePoint2d(304, 2, 200, 16, 17), Slvs_MakePoint2d(305, 2, 200, 18, 19)};
    constraints_ = {Slvs_MakeConstraint(1, 2, SLVS_C_PT_PT_DISTANCE, 200, l2, 302, 304, 0, 0),
                    Slvs_MakeConstraint(2, 2, SLVS_C_PT_PT_DISTANCE, 200, l3, 303, 304, 0, 0),
                    Slvs_MakeConstraint(3, 2, SLVS_C_PT_PT_DISTANCE, 200, k.norm(), 302, 305, 0, 0),
                    Slvs_MakeConstraint(4, 2, SLVS_C_PT_PT_DISTANCE, 200, (k - Eigen::Vector2d(l2, 0)).norm(), 304, 305, 0, 0)};
    failed_.resize(constraints_.size());
    l1_ = l1;
  }

  // Solves at crank angle phi; false when libslvs does not converge.
  bool Solve(double phi) {
    params_[9].val = l1_ * std::cos(phi);
    params_[10].val = l1_ * std::sin(phi);
    Slvs_System sys{};
    sys.param = params_.data();
    sys.params = static_cast<int>(params_.size());
    sys.entity = entities_.data();
    sys.entities = static_cast<int>(entities_.size());
    sys.constraint = constraints_.data();
    sys.constraints = static_cast<int>(constraints_.size());
    sys.failed = failed_.data();
    sys.faileds = static_cast<int>(failed_.size());
    solve_(&sys, 2);
    return sys.result == SLVS_RESULT_OKAY;
  }
  double kx() const { return params_[15].val; }
  double ky() const { return params_[16].val; }

 private:
  std::vector<Slvs_Param> params_;
  std::vector<Slvs_Entity> entities_;
  std::vector<Slvs_Constraint> constraints_;
  std::vector<Slvs_hConstraint> failed_;
  SlvsSolveFunction solve_;
  double l1_ = 1.0;
};

void TimeSlvs(benchmark::State& state) {
  std::string why;
  const SlvsSolveFunction solve = LoadSlvsSolve(&why);
  if (!solve) {
    state.SkipWithError(why.c_str());
    return;
  }
  SlvsFourBar sketch(solve);
  const double step = DegToRad(1.0);
  double worst = 0.0;
  for (int i = 1; i <= kStepsPerTurn; ++i) {
    if (!sketch.Solve(i * step)) {
      state.SkipWithError("libslvs did not converge");
      return;
    }
    const FourBarValues v = SeedFourBarClosedForm(i * step);
    worst = std::max({worst, std::abs(sketch.kx() - v.kx.v), std::abs(sketch.ky() - v.ky.v)});
  }
  if (!(worst <= kAgreement * 10.0)) {
    state.SkipWithError(("libslvs and the closed form differ by " + std::to_string(worst)).c_str());
    return;
  }
  bool up = false;  // the check above ended at 360 deg
  for (auto _ : state) {
    for (int i = 0; i < kStepsPerTurn; ++i) {
      if (!sketch.Solve((up ? i + 1 : kStepsPerTurn - 1 - i) * step)) {
        state.SkipWithError("libslvs did not converge");
        return;
      }
    }
    up = !up;
  }
}

}  // namespace
}  // namespace slvs_bench
#endif

std::vector<Case> SlvsCases() {
  using namespace slvs_bench;
  Case slvs;
  slvs.name = "fourbar-slvs";
  slvs.per = Per::kStep;
  slvs.steps_per_iteration = 360;
#ifdef KOPPEL_HAVE_SLVS
  slvs.run = TimeSlvs;
#else
  slvs.skipped = true;
  slvs.note = "skipped: koppel was built without SolveSpace's libslvs (Debian libslvs1-dev)";
#endif
  Case positions;
  positions.name = "fourbar-positions";
  positions.per = Per::kStep;
  positions.steps_per_iteration = 360;
  positions.baseline = "fourbar-slvs";
  positions.run = TimeFourBarPositions;
  // the same walk against the closed form of the same positions (issue 25)
  Case closed_form;
  closed_form.name = "fourbar-positions-closed-form";
  closed_form.per = Per::kStep;
  closed_form.steps_per_iteration = 360;
  closed_form.run = TimeFourBarPositionsClosedForm;
  Case against_closed_form = positions;
  against_closed_form.name = "fourbar-positions-vs-closed-form";
  against_closed_form.baseline = "fourbar-positions-closed-form";
  return {slvs, positions, closed_form, against_closed_form};
}

}  // namespace koppel::bench
