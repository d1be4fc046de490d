#include "worker_threads.hpp"

#include "koppel/core/limits.hpp"

#include <algorithm>
#include <system_error>
#include <thread>
#include <vector>

namespace koppel {

int RunOnThreads(int wanted, const std::function<void()>& work) {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int threads = std::clamp(wanted > 0 ? wanted : cores, 1, kMaxThreads);
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (int t = 1; t < threads; ++t) {
    // under `ulimit -v` or a thread limit creation throws: carry on with fewer
    try {
      pool.emplace_back(work);
    } catch (const std::system_error&) {
      break;
    }
  }
  work();
  for (std::thread& t : pool) t.join();
  return static_cast<int>(pool.size()) + 1;
}

}  // namespace koppel
