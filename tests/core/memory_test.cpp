// How much memory the process may have (memory.hpp): UsableMemory against its definition (the
// least of ulimit -v, the cgroup's memory.max and the physical memory, read here independently),
// and FormatBytes on hand-worked figures (decimal units, three significant digits).
#include "koppel/core/memory.hpp"

#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <fstream>

namespace koppel::memory_test {
namespace {

std::uint64_t PhysicalMemory() {
  return static_cast<std::uint64_t>(sysconf(_SC_PHYS_PAGES)) * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

// The cgroup v2 limit, UINT64_MAX when "max" or absent.
std::uint64_t CgroupLimit() {
  std::ifstream in("/sys/fs/cgroup/memory.max");
  std::uint64_t bytes = 0;
  return in && (in >> bytes) ? bytes : UINT64_MAX;
}

}  // namespace

TEST_CASE("UsableMemory is the least of ulimit -v, the cgroup's limit and the physical memory", "[memory]") {
  rlimit as{};
  REQUIRE(getrlimit(RLIMIT_AS, &as) == 0);
  const std::uint64_t ulimit = as.rlim_cur == RLIM_INFINITY ? UINT64_MAX : as.rlim_cur;
  const std::uint64_t least = std::min({ulimit, CgroupLimit(), PhysicalMemory()});
  const MemoryLimit limit = UsableMemory();
  CHECK(limit.bytes == least);
  // the source names the limit that is the least
  if (least == PhysicalMemory() && least < ulimit && least < CgroupLimit()) CHECK(limit.source == "physical memory");
  if (least == ulimit && least < CgroupLimit() && least < PhysicalMemory()) CHECK(limit.source == "ulimit -v");
  if (least == CgroupLimit() && least < ulimit && least < PhysicalMemory()) CHECK(limit.source == "cgroup memory.max");
  // there is always physical memory: a limit is found
  CHECK(limit.bytes < UINT64_MAX);
  CHECK_FALSE(limit.source.empty());
}

#if !defined(__SANITIZE_ADDRESS__)
// (an address-space limit cannot be set under AddressSanitizer, whose shadow memory exceeds it)
TEST_CASE("a ulimit -v below the other limits is the one UsableMemory reports", "[memory]") {
  rlimit saved{};
  REQUIRE(getrlimit(RLIMIT_AS, &saved) == 0);
  // one page below the least of the others: still far above what this process maps
  const std::uint64_t others = std::min(CgroupLimit(), PhysicalMemory());
  const std::uint64_t wanted = others - static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
  if (saved.rlim_max != RLIM_INFINITY && saved.rlim_max < wanted) return;  // may not be raised to; nothing to test
  rlimit lowered = saved;
  lowered.rlim_cur = wanted;
  REQUIRE(setrlimit(RLIMIT_AS, &lowered) == 0);
  const MemoryLimit limit = UsableMemory();
  REQUIRE(setrlimit(RLIMIT_AS, &saved) == 0);
  CHECK(limit.bytes == wanted);
  CHECK(limit.source == "ulimit -v");
}
#endif

TEST_CASE("FormatBytes writes decimal units with three significant digits", "[memory]") {
  // hand-worked: whole bytes below 1000, then 1000 per unit
  CHECK(FormatBytes(0) == "0 bytes");
  CHECK(FormatBytes(999) == "999 bytes");
  CHECK(FormatBytes(1000) == "1 kB");
  CHECK(FormatBytes(1500) == "1.5 kB");
  CHECK(FormatBytes(1234567) == "1.23 MB");
  CHECK(FormatBytes(13.2e9) == "13.2 GB");
  CHECK(FormatBytes(2.5e12) == "2.5 TB");
  CHECK(FormatBytes(7e15) == "7 PB");
  // the unit is chosen on the number as printed: never "1e+03 kB" at a unit's boundary
  CHECK(FormatBytes(999.5) == "1 kB");
  CHECK(FormatBytes(999999) == "1 MB");
  CHECK(FormatBytes(999.6e6) == "1 GB");
  CHECK(FormatBytes(3e18) == "3000 PB");
}

}  // namespace koppel::memory_test
