#include "koppel/core/worker_threads.hpp"

#include "koppel/core/limits.hpp"

#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace koppel {
namespace {

// Under an address-space limit (ulimit -v) every thread takes address space before it does any
// work: its stack (8 MB unless `ulimit -s` says otherwise) and, on its first allocation, often a
// malloc arena of its own (glibc reserves 64 MB each, up to 8 per core). Near the limit an
// allocation in the middle of the work then fails, sooner or later as the threads happen to
// contend, where fewer threads would have had room. So under such a limit malloc keeps to one
// arena per core and the threads are as many as their stacks fit in a quarter of the limit.
int ThreadsUnderAddressLimit(int threads, int cores) {
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) != 0 || as.rlim_cur == RLIM_INFINITY) return threads;
  static std::once_flag arenas;
  std::call_once(arenas, [cores] { mallopt(M_ARENA_MAX, cores); });
  std::uint64_t stack = 8u << 20;
  if (rlimit s{}; getrlimit(RLIMIT_STACK, &s) == 0 && s.rlim_cur != RLIM_INFINITY && s.rlim_cur > 0) stack = s.rlim_cur;
  const std::uint64_t fit = static_cast<std::uint64_t>(as.rlim_cur) / 4 / stack;
  return static_cast<int>(std::clamp<std::uint64_t>(fit, 1, static_cast<std::uint64_t>(threads)));
}

}  // namespace

int RunOnThreads(int wanted, const std::function<void()>& work) {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int threads = ThreadsUnderAddressLimit(std::clamp(wanted > 0 ? wanted : cores, 1, kMaxThreads), cores);
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
