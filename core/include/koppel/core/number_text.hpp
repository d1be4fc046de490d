// Numbers as text: printf's "%.12g" of a double, the form of every number koppel's CSV holds
// (12 significant digits: enough for a paper, short enough for a spreadsheet).
#pragma once

namespace koppel {

// Room WriteG12 may use: sign, 12 digits, point, "e-308".
inline constexpr int kG12Chars = 24;

// Writes "%.12g" of `value` at `out` (kG12Chars of room) and returns the end: exactly the bytes of
// std::to_chars(out, end, value, std::chars_format::general, 12), which it calls for the values
// its exact fast path does not cover (|value| outside [1e-11, 1e12), subnormal, non-finite). The
// fast path rounds the exact binary value to 12 digits in 128-bit integers (half to even, as
// printf), several times faster than the general algorithm: analyze writes millions of numbers.
char* WriteG12(char* out, double value);

}  // namespace koppel
