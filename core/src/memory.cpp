#include "koppel/core/memory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace koppel {

MemoryLimit UsableMemory() {
  MemoryLimit limit;
  auto consider = [&](std::uint64_t bytes, const char* source) {
    if (bytes < limit.bytes) limit = {bytes, source};
  };
  if (rlimit as{}; getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) consider(as.rlim_cur, "ulimit -v");
  // cgroup v2: "max" when unlimited
  if (std::ifstream cgroup("/sys/fs/cgroup/memory.max"); cgroup) {
    std::uint64_t bytes = 0;
    if (cgroup >> bytes) consider(bytes, "cgroup memory.max");
  }
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0) consider(static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page), "physical memory");
  return limit;
}

std::string FormatBytes(double bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB"};
  char text[32];
  for (int u = 0;; ++u, bytes /= 1000.0) {
    std::snprintf(text, sizeof text, u == 0 || bytes >= 1000.0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
    // the unit is chosen on the number as printed: 999 999 bytes is "1 MB", not "1e+03 kB"
    if (u == 5 || std::strtod(text, nullptr) < 1000.0) return text;
  }
}

}  // namespace koppel
