#include "koppel/core/number_text.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cstdint>

namespace koppel {
namespace {

using U128 = unsigned __int128;

constexpr int kDigits = 12;
constexpr int kMaxScale = 22;  // 10^22 * 2^53 < 2^127: the product m 10^k fits in 128 bits
constexpr std::uint64_t kLow = 100'000'000'000;         // 10^11: the smallest 12-digit number
constexpr std::uint64_t kHigh = 1'000'000'000'000;      // 10^12

constexpr std::array<U128, kMaxScale + 1> Powers() {
  std::array<U128, kMaxScale + 1> p{};
  p[0] = 1;
  for (int k = 1; k <= kMaxScale; ++k) p[k] = p[k - 1] * 10;
  return p;
}
constexpr std::array<U128, kMaxScale + 1> kPowerOf10 = Powers();

// "00" .. "99"
constexpr std::array<char, 200> Pairs() {
  std::array<char, 200> p{};
  for (int i = 0; i < 100; ++i) {
    p[2 * i] = static_cast<char>('0' + i / 10);
    p[2 * i + 1] = static_cast<char>('0' + i % 10);
  }
  return p;
}
constexpr std::array<char, 200> kPairs = Pairs();

// the six digits of x < 10^6, leading zeros included, two at a time
void WriteSixDigits(char* out, std::uint32_t x) {
  const std::uint32_t a = x / 10000, b = x % 10000;
  const std::uint32_t b1 = b / 100, b2 = b % 100;
  out[0] = kPairs[2 * a];
  out[1] = kPairs[2 * a + 1];
  out[2] = kPairs[2 * b1];
  out[3] = kPairs[2 * b1 + 1];
  out[4] = kPairs[2 * b2];
  out[5] = kPairs[2 * b2 + 1];
}

char* General(char* out, double value) {
  return std::to_chars(out, out + kG12Chars, value, std::chars_format::general, kDigits).ptr;
}

// The 12 significant digits of |value| = m 2^q exactly (the digits' decimal exponent in *e),
// rounded half to even; false where this range's arithmetic does not reach (then to_chars).
bool RoundTo12Digits(std::uint64_t bits, std::uint64_t* rounded, int* exponent) {
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  if (biased == 0 || biased == 0x7ff) return false;  // zero, subnormal, inf, nan
  // value = +-m 2^q exactly, 2^52 <= m < 2^53
  const std::uint64_t m = (bits & ((std::uint64_t{1} << 52) - 1)) | (std::uint64_t{1} << 52);
  const int q = biased - 1075;
  // the decimal exponent e of |value| is floor(log10 2^(q+52)) or one more (78913 / 2^18 ~ log10 2)
  int e = ((q + 52) * 78913) >> 18;
  int k = kDigits - 1 - e;  // |value| 10^k has 12 digits before the point (or 13, then e is one more)
  if (k < 0 || k > kMaxScale || q >= 0) return false;
  const int shift = -q;  // 12 <= shift <= 127 in this range
  U128 product = static_cast<U128>(m) * kPowerOf10[k];
  std::uint64_t digits = static_cast<std::uint64_t>(product >> shift);
  if (digits >= kHigh) {
    ++e;
    if (--k < 0) return false;
    product = static_cast<U128>(m) * kPowerOf10[k];
    digits = static_cast<std::uint64_t>(product >> shift);
  }
  if (digits < kLow || digits >= kHigh) return false;  // never: the estimate is off by at most one
  // round the exact remainder half to even
  const U128 remainder = product & ((U128{1} << shift) - 1), half = U128{1} << (shift - 1);
  if (remainder > half || (remainder == half && (digits & 1) != 0)) ++digits;
  if (digits == kHigh) {  // 999999999999.5 -> 1000000000000
    digits = kLow;
    ++e;
  }
  *rounded = digits;
  *exponent = e;
  return true;
}

// %g's layout of the n significant digits d (trailing zeros dropped) with decimal exponent e:
// d.ddde-XX (at least two exponent digits) below 1e-4 or from 1e12, else fixed.
char* LayOut(char* out, const char* d, int n, int e) {
  if (e < -4 || e >= kDigits) {
    *out++ = d[0];
    if (n > 1) {
      *out++ = '.';
      for (int i = 1; i < n; ++i) *out++ = d[i];
    }
    *out++ = 'e';
    *out++ = e < 0 ? '-' : '+';
    const int x = e < 0 ? -e : e;  // at most 12 here
    *out++ = static_cast<char>('0' + x / 10);
    *out++ = static_cast<char>('0' + x % 10);
    return out;
  }
  if (e < 0) {  // 0.000ddd
    *out++ = '0';
    *out++ = '.';
    for (int i = -1; i > e; --i) *out++ = '0';
    for (int i = 0; i < n; ++i) *out++ = d[i];
    return out;
  }
  for (int i = 0; i <= e; ++i) *out++ = i < n ? d[i] : '0';  // the whole part
  if (n > e + 1) {
    *out++ = '.';
    for (int i = e + 1; i < n; ++i) *out++ = d[i];
  }
  return out;
}

}  // namespace

char* WriteG12(char* out, double value) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(value);
  std::uint64_t digits = 0;
  int e = 0;
  if (!RoundTo12Digits(bits, &digits, &e)) return General(out, value);
  char d[kDigits];
  WriteSixDigits(d, static_cast<std::uint32_t>(digits / 1'000'000));
  WriteSixDigits(d + 6, static_cast<std::uint32_t>(digits % 1'000'000));
  int n = kDigits;  // significant digits without the trailing zeros (%g drops them)
  while (n > 1 && d[n - 1] == '0') --n;
  if (bits >> 63) *out++ = '-';
  return LayOut(out, d, n, e);
}

}  // namespace koppel
