// How much memory this process may have: what work that holds its results in memory (an atlas
// build) checks its estimate against before it starts, so that it ends with a figure (exit 2)
// instead of std::bad_alloc after minutes of work.
#pragma once

#include <cstdint>
#include <string>

namespace koppel {

struct MemoryLimit {
  std::uint64_t bytes = UINT64_MAX;  // UINT64_MAX: no limit found
  std::string source;                // what sets it: "ulimit -v", "physical memory", "cgroup memory.max"
};

// The least of the address-space limit (ulimit -v), the cgroup's memory.max and the physical
// memory: the most a process can hold, not what is free at the moment.
MemoryLimit UsableMemory();

// "13.2 GB": bytes in decimal units with three digits.
std::string FormatBytes(double bytes);

}  // namespace koppel
