// Synthesis as the commands run it, each against its time budget (issue 16): one dead-centre
// synthesis with the mu_min optimisation (synth deadcentre crank-rocker --phi0 164 --psi0 60),
// the 30 x 30 crank-rocker chart on every core (synth chart --phi0 150:208:2 --psi0 20:78:2), and
// a path fit with 32 starts (five precision points of seed 003's coupler point, synth fit).
#include "bench.hpp"

#include "koppel/catalog/catalog.hpp"
#include "koppel/catalog/fit_problem.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/synthesis/deadcentre_synthesis.hpp"
#include "koppel/synthesis/path_synthesis.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>
#include <unistd.h>

namespace koppel::bench {
namespace synthesis_bench {  // this file's own names, apart from the other benchmarks' in a unity build
namespace {

void TimeDeadCentre(benchmark::State& state) {
  CrankRockerRequest request;
  request.phi0 = DegToRad(164);
  request.psi0 = DegToRad(60);
  for (auto _ : state) {
    const CrankRockerDesign design = BestCrankRocker(request);
    if (!design.ok()) {
      state.SkipWithError(design.message.c_str());
      return;
    }
    benchmark::DoNotOptimize(design.mu_min);
  }
}

void TimeChart(benchmark::State& state) {
  std::vector<CrankRockerRequest> requests;
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 30; ++j) {
      CrankRockerRequest r;
      r.phi0 = DegToRad(150 + 2 * i);
      r.psi0 = DegToRad(20 + 2 * j);
      requests.push_back(r);
    }
  }
  std::vector<CrankRockerDesign> designs(requests.size());
  for (auto _ : state) {
    std::atomic<size_t> next{0};
    auto work = [&] {
      for (size_t i = next++; i < requests.size(); i = next++) designs[i] = BestCrankRocker(requests[i]);
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < std::max(1u, std::thread::hardware_concurrency()); ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
  }
  int ok = 0;
  for (const CrankRockerDesign& d : designs) ok += d.ok();
  if (ok == 0) state.SkipWithError("no design in the chart");
}

// The problem file of tests/data/fit-mzc-precision-points.yaml with 32 starts, next to nothing:
// the mechanism is the catalog's entry, named by its absolute path.
const char* kFitProblem = R"(mechanism: {CATALOG}/mzc-crank-rocker.yaml
parameters:
  l3: {start: 4.0, lower: 3.5, upper: 5}
  k: {start: 7.5, lower: 6, upper: 9}
starts: 32
targets:
  - {point: K, input: 0, at: [1.65016198276, 8.30793198339]}
  - {point: K, input: 72, at: [3.8001497422, 8.51785482083]}
  - {point: K, input: 144, at: [2.73804645682, 8.12852694775]}
  - {point: K, input: 216, at: [0.817414850996, 7.5852902947]}
  - {point: K, input: 288, at: [-0.291263043332, 7.36062853072]}
)";

void TimeFit(benchmark::State& state) {
  std::string text = kFitProblem;
  text.replace(text.find("{CATALOG}"), 9, DefaultCatalogDirectory());
  char folder[] = "/tmp/koppel-bench-XXXXXX";
  if (!mkdtemp(folder)) {
    state.SkipWithError("cannot make a temporary folder");
    return;
  }
  const std::filesystem::path path = std::filesystem::path(folder) / "fit.yaml";
  std::ofstream(path) << text;
  FitProblem problem;
  try {
    problem = ReadFitProblem(path.string());
  } catch (const std::exception& e) {
    std::filesystem::remove_all(folder);
    state.SkipWithError((std::string("the fit problem: ") + e.what()).c_str());
    return;
  }
  std::filesystem::remove_all(folder);
  for (auto _ : state) {
    const FitReport report = Fit(problem.builder, problem.parameters, problem.targets, problem.options);
    if (report.status != FitStatus::kConverged) {
      state.SkipWithError(("the fit did not converge: " + report.message).c_str());
      return;
    }
  }
}

// The literature's path-synthesis problems as `koppel synth path` runs them with the design files
// of tests/data/benchmarks (the papers' bounds, a crank), against the 30 s a problem
// the synthesis is given: the five points of Kunjur and Krishnamurty (A0 at the origin, frame
// along +x, crank angles 30..90 deg) and the 18-point closed curve of Cabrera et al. (20 deg steps).
PathRequest KunjurFivePoints() {
  PathRequest r;
  r.points = {{3, 3}, {2.759, 3.363}, {2.372, 3.663}, {1.890, 3.862}, {1.355, 3.943}};
  for (double phi : {30, 45, 60, 75, 90}) r.timing.push_back(DegToRad(phi));
  r.space.a0 = Eigen::Vector2d(0, 0);
  r.space.frame_angle = 0;
  r.space.lengths = std::make_pair(0.0, 50.0);
  r.space.coupler_point = std::make_pair(-50.0, 50.0);
  r.space.input = InputTurn::kCrank;
  return r;
}

PathRequest CabreraEighteenPoints() {
  PathRequest r;
  r.points = {{0.5, 1.1}, {0.4, 1.1}, {0.3, 1.1},  {0.2, 1.0}, {0.1, 0.9},   {0.005, 0.75}, {0.02, 0.6}, {0, 0.5},  {0, 0.4},
              {0.03, 0.3}, {0.1, 0.25}, {0.15, 0.2}, {0.2, 0.3}, {0.3, 0.4}, {0.4, 0.5},    {0.5, 0.7},  {0.6, 0.9}, {0.6, 1.0}};
  r.timing_step = DegToRad(20);
  r.space.lengths = std::make_pair(0.0, 50.0);
  r.space.pivots_x = r.space.pivots_y = r.space.coupler_point = std::make_pair(-50.0, 50.0);
  r.space.input = InputTurn::kCrank;
  return r;
}

void TimeTimedPath(benchmark::State& state, const PathRequest& request) {
  for (auto _ : state) {
    const PathResult result = SynthesisePathGlobally(request);
    if (!result.ok()) {
      state.SkipWithError(result.message.c_str());
      return;
    }
    state.counters["sse"] = result.linkages.front().sse;
  }
}
// The untimed two: six points on a line (an open stretch, lengths 5..60) and the ellipse's ten
// points (the last repeating the first, lengths 5..80), both with a crank, pivots and K within the
// lengths' bound either way.
PathRequest UntimedProblem(std::vector<Eigen::Vector2d> points, bool open, double shortest, double longest) {
  PathRequest r;
  r.points = std::move(points);
  r.open = open;
  r.space.lengths = std::make_pair(shortest, longest);
  r.space.pivots_x = r.space.pivots_y = r.space.coupler_point = std::make_pair(-longest, longest);
  r.space.input = InputTurn::kCrank;
  return r;
}

void TimeKunjur(benchmark::State& state) { TimeTimedPath(state, KunjurFivePoints()); }
void TimeSixCollinear(benchmark::State& state) {
  TimeTimedPath(state, UntimedProblem({{20, 20}, {20, 25}, {20, 30}, {20, 35}, {20, 40}, {20, 45}}, true, 5, 60));
}
void TimeEllipse(benchmark::State& state) {
  TimeTimedPath(state, UntimedProblem({{20, 10}, {17.66, 15.142}, {11.736, 17.878}, {5, 16.928}, {0.60307, 12.736}, {0.60307, 7.2638},
                                       {5, 3.0718}, {11.736, 2.1215}, {17.66, 4.8577}, {20, 10}},
                                      false, 5, 80));
}
void TimeCabrera(benchmark::State& state) { TimeTimedPath(state, CabreraEighteenPoints()); }

Case RunCase(std::string name, double budget_ms, void (*run)(benchmark::State&), bool threaded) {
  Case c;
  c.name = std::move(name);
  c.per = Per::kRun;
  c.budget_ns = budget_ms * 1e6;
  c.threaded = threaded;
  c.run = run;
  return c;
}

}  // namespace
}  // namespace synthesis_bench

std::vector<Case> SynthesisCases() {
  using namespace synthesis_bench;
  return {RunCase("deadcentre-synthesis", 5, TimeDeadCentre, false), RunCase("chart-30x30", 2000, TimeChart, true),
          RunCase("fit-32-starts", 1000, TimeFit, true), RunCase("path-timed-5-points", 30'000, TimeKunjur, true),
          RunCase("path-timed-18-points", 30'000, TimeCabrera, true), RunCase("path-free-6-points", 30'000, TimeSixCollinear, true),
          RunCase("path-free-ellipse", 30'000, TimeEllipse, true)};
}

}  // namespace koppel::bench
