// Sweep cost against the hand-written closed form of seed 000's slider-crank (s, s', s'' per
// input), measured in the same process; prints the ratio per sample at the end.
//   build/tools/koppel_bench [--benchmark_min_time=0.5]
#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace {

using namespace koppel;

constexpr int kSamples = 361;  // a full turn at 1 degree

Mechanism SliderCrank(double l1, double l2, double e) {
  Mechanism m;
  m.name = "bench";
  m.links = {{"frame", true, {{"A0", {0, -e}}, {"F", {0, 0}}}},
             {"crank", false, {{"A0", {0, 0}}, {"A", {0, -l1}}}},
             {"coupler", false, {{"A", {0, 0}}, {"B", {l2, 0}}}},
             {"slider", false, {{"B", {0, 0}}}}};
  Joint a0{"A0", JointType::kRevolute, 0, 1, 0, 0}, a{"A", JointType::kRevolute, 1, 2, 1, 0}, b{"B", JointType::kRevolute, 2, 3, 1, 0};
  Joint s{"S", JointType::kPrismatic, 0, 3, 1, 0};
  m.joints = {a0, a, b, s};
  m.drive.joint = 0;
  Output out;
  out.name = "s";
  out.joint = 3;
  m.outputs = {out};
  m.hint.points = {{{3, 0}, {2, 0}}};
  return m;
}

// seed 000: s/l1 = sin phi + cos psi / lambda, s' and s'' as printed
void ClosedForm(benchmark::State& state) {
  const double l1 = 1, l2 = 2.6, e = 0.8, lambda = l1 / l2, eps = e / l2;
  for (auto _ : state) {
    double sum = 0;
    for (int i = 0; i < kSamples; ++i) {
      const double phi = DegToRad(i);
      const double sin_psi = -lambda * std::cos(phi) - eps, cos_psi = std::sqrt(1 - sin_psi * sin_psi);
      const double psi = std::atan2(sin_psi, cos_psi);
      sum += l1 * (std::sin(phi) + cos_psi / lambda) + l1 * std::cos(phi + psi) / cos_psi -
             l1 * (std::sin(phi + psi) / cos_psi + lambda * std::sin(phi) * std::sin(phi) / (cos_psi * cos_psi * cos_psi));
    }
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(ClosedForm);

void KoppelSweep(benchmark::State& state) {
  const Mechanism m = SliderCrank(1, 2.6, 0.8);
  SweepOptions o;
  o.from = 0;
  o.to = 2 * kPi;
  o.step = DegToRad(1);
  o.order = 2;
  for (auto _ : state) {
    const SweepResult r = Sweep(m, o);
    benchmark::DoNotOptimize(r.outputs.data());
  }
}
BENCHMARK(KoppelSweep);

// Collects the time per iteration of each benchmark to print ratios against the closed form.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) seconds_[r.benchmark_name()] = r.GetAdjustedRealTime();
    ConsoleReporter::ReportRuns(runs);
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    const auto base = seconds_.find("ClosedForm");
    if (base == seconds_.end()) return;
    for (const auto& [name, t] : seconds_)
      std::printf("ratio %s / ClosedForm = %.1f (per sample: %.3g vs %.3g time units)\n", name.c_str(), t / base->second, t / kSamples,
                  base->second / kSamples);
  }

 private:
  std::map<std::string, double> seconds_;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}
