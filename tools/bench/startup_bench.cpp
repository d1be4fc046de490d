// The start-up of the koppel executable (issue 25): this very program (/proc/self/exe) spawned
// with posix_spawn and waited for, per run, its output thrown away: `koppel --version` against a
// budget of 10 ms, and `koppel analyze` of a small file (the catalog's crank-rocker, default
// range: 361 rows) against twice the version's time. Wall time: the work is another process's.
#include "bench.hpp"
#include "koppel/catalog/catalog.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <string>
#include <vector>

extern char** environ;

namespace koppel::bench {
namespace startup_bench {  // this file's own names, apart from the other benchmarks' in a unity build
namespace {

// Runs /proc/self/exe with `args`, standard output and error to /dev/null; empty when it exited
// with 0, else what went wrong.
std::string RunKoppel(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  std::string program = "koppel";
  argv.push_back(program.data());
  std::vector<std::string> copies = args;
  for (std::string& a : copies) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) return "cannot start /proc/self/exe (error " + std::to_string(error) + ")";
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return "cannot wait for koppel";
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  return WIFEXITED(status) ? "koppel exited with " + std::to_string(WEXITSTATUS(status)) : "koppel ended by a signal";
}

void TimeStartup(benchmark::State& state, const std::vector<std::string>& args) {
  for (auto _ : state) {
    if (const std::string why = RunKoppel(args); !why.empty()) {
      state.SkipWithError(why.c_str());
      return;
    }
  }
}

}  // namespace
}  // namespace startup_bench

std::vector<Case> StartupCases() {
  using namespace startup_bench;
  Case version;
  version.name = "startup-version";
  version.per = Per::kRun;
  version.budget_ns = 10e6;
  version.threaded = true;  // wall time: the time is the child's
  version.run = [](benchmark::State& s) { TimeStartup(s, {"--version"}); };
  Case analyze;
  analyze.name = "startup-analyze";
  analyze.per = Per::kRun;
  analyze.baseline = "startup-version";
  analyze.baseline_factor = 2.0;
  analyze.threaded = true;
  analyze.run = [](benchmark::State& s) { TimeStartup(s, {"analyze", DefaultCatalogDirectory() + "/crank-rocker.yaml"}); };
  return {version, analyze};
}

}  // namespace koppel::bench
