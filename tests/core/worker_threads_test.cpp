// RunOnThreads (core/src/worker_threads.cpp) against its definition in
// worker_threads.hpp: `work` runs once on each of the threads it reports, the calling thread
// among them; 0 asks for one per core (std::thread::hardware_concurrency, capped at
// kMaxThreads); work pulled from a shared counter is done exactly once whatever the count.
#include "koppel/core/worker_threads.hpp"

#include "koppel/core/limits.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

namespace koppel::worker_threads_test {
namespace {

// What each run of `work` saw: its thread's id.
struct Runs {
  std::mutex mutex;
  std::vector<std::thread::id> ids;
  void Add() {
    const std::lock_guard<std::mutex> lock(mutex);
    ids.push_back(std::this_thread::get_id());
  }
};

}  // namespace

TEST_CASE("RunOnThreads runs the work once per thread it reports, the caller among them", "[synthesis][threads]") {
  for (const int wanted : {1, 2, 4}) {
    INFO("wanted " << wanted);
    Runs runs;
    const int ran = RunOnThreads(wanted, [&] { runs.Add(); });
    // a few threads can always be made here: the count asked for, each run on its own thread
    CHECK(ran == wanted);
    CHECK(runs.ids.size() == static_cast<size_t>(ran));
    CHECK(std::set<std::thread::id>(runs.ids.begin(), runs.ids.end()).size() == runs.ids.size());
    CHECK(std::count(runs.ids.begin(), runs.ids.end(), std::this_thread::get_id()) == 1);
  }
}

TEST_CASE("RunOnThreads(0) runs one thread per core, at most kMaxThreads", "[synthesis][threads]") {
  // the definition: hardware_concurrency, 1 when it is unknown (0), clamped to kMaxThreads
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::atomic<int> calls{0};
  const int ran = RunOnThreads(0, [&] { ++calls; });
  CHECK(ran == std::min(cores, kMaxThreads));
  CHECK(calls == ran);
  // the largest count allowed is honoured too (threads that cannot be made are not an error,
  // but every thread reported ran the work)
  std::atomic<int> most{0};
  const int ran_most = RunOnThreads(kMaxThreads, [&] { ++most; });
  CHECK(ran_most >= 1);
  CHECK(ran_most <= kMaxThreads);
  CHECK(most == ran_most);
}

TEST_CASE("RunOnThreads: items pulled from a shared counter are each done exactly once", "[synthesis][threads]") {
  // the pattern of the atlas, motion, path and fit searches: each thread takes the next item
  // until none is left; reference: every item's count is 1, the sum is the closed form n(n-1)/2
  constexpr int kItems = 10000;
  for (const int wanted : {1, 3, 8}) {
    INFO("wanted " << wanted);
    std::vector<std::atomic<int>> done(kItems);
    std::atomic<int> next{0};
    std::atomic<long long> sum{0};
    RunOnThreads(wanted, [&] {
      for (int i; (i = next.fetch_add(1)) < kItems;) {
        ++done[i];
        sum += i;
      }
    });
    CHECK(std::all_of(done.begin(), done.end(), [](const std::atomic<int>& d) { return d.load() == 1; }));
    CHECK(sum == static_cast<long long>(kItems) * (kItems - 1) / 2);
  }
}

}  // namespace koppel::worker_threads_test
