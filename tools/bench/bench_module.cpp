// The module libkoppel_bench.so (bench_module.hpp): the cases of bench_cases.cpp run by Google
// Benchmark in this process, so that the baselines run beside the cases they are compared with.
#include "bench.hpp"

#include <stdexcept>

namespace koppel::bench {
namespace bench_module {  // this file's own names, apart from the other benchmarks' in a unity build
namespace {

const Host* current_host = nullptr;

// Collects every run, telling the host as each case finishes.
class Collector : public benchmark::BenchmarkReporter {
 public:
  explicit Collector(const Host& host) : host_(host) {}
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) {
      if (r.run_type != Run::RT_Iteration) continue;
      Measured& m = measured_[r.run_name.function_name];
      m.ran = true;
      if (r.error_occurred) {
        m.error = r.error_message;
      } else if (r.iterations > 0) {
        m.cpu_ns = r.cpu_accumulated_time / static_cast<double>(r.iterations) * 1e9;
        m.wall_ns = r.real_accumulated_time / static_cast<double>(r.iterations) * 1e9;
      }
      if (host_.done) host_.done(r.run_name.function_name);
    }
  }
  std::map<std::string, Measured>& measured() { return measured_; }

 private:
  const Host& host_;
  std::map<std::string, Measured> measured_;
};

std::vector<CaseInfo> Cases() {
  std::vector<CaseInfo> infos;
  for (const Case& c : AllCases()) infos.push_back(c);
  return infos;
}

std::map<std::string, Measured> Run(const std::set<std::string>& wanted, double min_time, const Host& host) {
  // the cases hold what they time until the run ends
  const std::vector<Case> cases = AllCases();
  int argc = 1;
  char program[] = "koppel";
  char* argv[] = {program, nullptr};
  benchmark::Initialize(&argc, argv);
  for (const Case& c : cases) {
    if (!wanted.count(c.name) || c.skipped) continue;
    benchmark::internal::Benchmark* b = benchmark::RegisterBenchmark(c.name.c_str(), c.run)->MinTime(min_time);
    if (c.threaded) b->UseRealTime();
  }
  Collector collector(host);
  current_host = &host;
  benchmark::RunSpecifiedBenchmarks(&collector);
  current_host = nullptr;
  benchmark::ClearRegisteredBenchmarks();
  benchmark::Shutdown();
  return collector.measured();
}

const BenchModuleTable kTable{{KOPPEL_MODULE_VERSION}, &Cases, &Run};

}  // namespace
}  // namespace bench_module

const Host& CurrentHost() {
  if (!bench_module::current_host) throw std::logic_error("koppel bench: a benchmark ran outside the module's run");
  return *bench_module::current_host;
}

}  // namespace koppel::bench

extern "C" __attribute__((visibility("default"))) const koppel::ModuleTable* koppel_bench_module() { return &koppel::bench::bench_module::kTable; }
