// How many seeded random mechanisms a property test walks: all of them in the Release build,
// one in five (at least 10) in the checked build, whose sanitizers make each walk 5 to 20 times
// slower and which looks for memory errors, not for the one mechanism in a thousand that the
// Release build's full count is there to catch.
#pragma once

namespace koppel::test {

#if defined(KOPPEL_CHECKED_BUILD)
inline constexpr bool kCheckedBuild = true;
#else
inline constexpr bool kCheckedBuild = false;
#endif

constexpr int SeedCount(int release_count) {
#if defined(KOPPEL_CHECKED_BUILD)
  const int share = release_count / 5;
  return release_count < 10 ? release_count : (share < 10 ? 10 : share);
#else
  return release_count;
#endif
}

// Whether the index-th case of a long table of cases is walked: every one in the Release build,
// every fifth (0, 5, 10 ...) in the checked build, for the same reason.
constexpr bool InCheckedShare(int index) {
#if defined(KOPPEL_CHECKED_BUILD)
  return index % 5 == 0;
#else
  (void)index;
  return true;
#endif
}

}  // namespace koppel::test
