// "No heap allocation inside a sweep": the number of allocations of a sweep must not grow with
// its number of samples. Counts every operator new of this test executable (harmless for the
// other tests, which only see a counter go up), and, outside the sanitizer build (whose runtime
// owns malloc), every malloc, calloc and realloc too: Eigen's dynamic matrices and temporaries
// come from malloc, not from operator new.
#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> g_allocations{0};
}

#if !defined(__SANITIZE_ADDRESS__)
// glibc's own allocator under its exported internal names; the definitions below replace the
// process's malloc family (the executable's symbols come first in the lookup).
extern "C" void* __libc_malloc(std::size_t size);
extern "C" void* __libc_calloc(std::size_t count, std::size_t size);
extern "C" void* __libc_realloc(void* p, std::size_t size);
extern "C" void* malloc(std::size_t size) {
  ++g_allocations;
  return __libc_malloc(size);
}
extern "C" void* calloc(std::size_t count, std::size_t size) {
  ++g_allocations;
  return __libc_calloc(count, size);
}
extern "C" void* realloc(void* p, std::size_t size) {
  ++g_allocations;
  return __libc_realloc(p, size);
}
#endif

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// the nothrow form too (Catch2 uses it): every block the replaced delete frees comes from malloc,
// which AddressSanitizer checks (alloc-dealloc-mismatch otherwise)
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  ++g_allocations;
  return std::malloc(size == 0 ? 1 : size);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace koppel::sweep_allocation_test {

TEST_CASE("a sweep allocates the same whether it has 361 or 3601 samples", "[sweep][allocation]") {
  const Mechanism m = test::ProportionalLinkage(1.0, 0.5, 1.83);  // 15 coordinates, two loops
  long counts[2];
  int k = 0;
  for (double step : {1.0, 0.1}) {
    SweepOptions o;
    o.step = DegToRad(step);
    o.order = 4;
    const long before = g_allocations;
    const SweepResult r = Sweep(m, o);
    counts[k++] = g_allocations - before;
    REQUIRE(r.complete());
  }
  INFO("allocations: " << counts[0] << " and " << counts[1]);
  CHECK(counts[0] == counts[1]);
}

}  // namespace koppel::sweep_allocation_test
