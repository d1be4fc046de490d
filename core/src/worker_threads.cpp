#include "koppel/core/worker_threads.hpp"

#include "koppel/core/limits.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace koppel {

int RunOnThreads(int wanted, const std::function<void()>& work) {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int threads = std::clamp(wanted > 0 ? wanted : cores, 1, kMaxThreads);
  // an exception leaving a thread's function ends the process (std::terminate): each thread keeps
  // its own, and the caller rethrows the first once all have joined (std::bad_alloc under
  // `ulimit -v` becomes a message, not SIGABRT)
  std::mutex mutex;
  std::exception_ptr first;
  auto guarded = [&] {
    try {
      work();
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!first) first = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (int t = 1; t < threads; ++t) {
    // under `ulimit -v` or a thread limit creation throws: carry on with fewer
    try {
      pool.emplace_back(guarded);
    } catch (const std::system_error&) {
      break;
    }
  }
  guarded();
  for (std::thread& t : pool) t.join();
  if (first) std::rethrow_exception(first);
  return static_cast<int>(pool.size()) + 1;
}

}  // namespace koppel
