// printf's %.12g (core/src/number_text.cpp, WriteG12) against its reference, the standard
// library's std::to_chars(general, 12) (C++17 [charconv.to.chars]: as printf "%.*g" in the C
// locale): byte for byte on random bit patterns, on every decade either side of the fast path's
// bounds, next to the roundings' edges (9.999999999995 10^e, where 12 digits carry into 13), and
// on exact binary ties (M + 1/2 with 12-digit M, odd multiples of 2^-j), where the rounding must
// go half to even as printf's does.
#include "koppel/core/number_text.hpp"

#include <catch2/catch.hpp>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

namespace koppel::number_text_test {
namespace {

std::string Fast(double x) {
  char text[kG12Chars];
  return std::string(text, WriteG12(text, x));
}

std::string Reference(double x) {
  char text[64];
  return std::string(text, std::to_chars(text, text + sizeof text, x, std::chars_format::general, 12).ptr);
}

// Counts the values whose text differs (and shows the first few).
struct Comparison {
  int checked = 0, differ = 0;
  void Check(double x) {
    ++checked;
    const std::string fast = Fast(x), reference = Reference(x);
    if (fast != reference && ++differ <= 5) FAIL_CHECK(Reference(x) << " written as " << fast);
  }
};

}  // namespace

TEST_CASE("WriteG12 writes the bytes of to_chars' %.12g on random doubles", "[number_text]") {
  std::mt19937_64 random(20261127);
  Comparison c;
  for (int i = 0; i < 200000; ++i) {  // every exponent, subnormals, infinities and NaN included
    c.Check(std::bit_cast<double>(random()));
  }
  std::uniform_real_distribution<double> mantissa(1, 10);
  for (int e = -14; e <= 14; ++e) {  // each decade, the fast path's bounds 1e-11 and 1e12 among them
    for (int i = 0; i < 5000; ++i) {
      const double x = mantissa(random) * std::pow(10.0, e);
      c.Check(x);
      c.Check(-x);
    }
  }
  for (double x : {0.0, -0.0, 1.0, -1.0, 0.1, 1e-5, 1e-4, 1e11, 1e12, 5e-324, 1.7976931348623157e308}) c.Check(x);
  CHECK(c.checked > 400000);
  CHECK(c.differ == 0);
}

TEST_CASE("WriteG12 rounds like %.12g at the edges: a carry into 13 digits, the switch to exponents, exact ties", "[number_text]") {
  Comparison c;
  for (int e = -13; e <= 13; ++e) {
    const double p = std::pow(10.0, e);
    for (double f : {1.0, 1 - 5e-13, 1 - 5e-12, 1 + 5e-12, 1 - 1e-12}) {
      double down = p * f, up = p * f;
      for (int step = 0; step < 50; ++step) {  // 50 neighbouring doubles each way
        c.Check(down);
        c.Check(up);
        down = std::nextafter(down, 0.0);
        up = std::nextafter(up, INFINITY);
      }
    }
  }
  std::mt19937_64 random(7);
  std::uniform_int_distribution<std::int64_t> twelve_digits(100'000'000'000, 999'999'999'999);
  for (int i = 0; i < 2000; ++i) {
    const std::int64_t m = twelve_digits(random);
    c.Check(static_cast<double>(m) + 0.5);  // a tie at 12 digits: half to even
    for (int j = 1; j < 40; ++j) c.Check(std::ldexp(static_cast<double>(2 * m + 1), -j));  // ties among them
    double x = static_cast<double>(m * 10 + 5);  // 13 digits ending in 5, and a tenth of it ...
    for (int j = 0; j < 20; ++j, x /= 10) {
      c.Check(x);
      c.Check(std::nextafter(x, 0.0));
      c.Check(std::nextafter(x, INFINITY));
    }
  }
  CHECK(c.differ == 0);
  CHECK(Fast(999999999999.5) == "1e+12");  // ties to even carry into the next decade
  CHECK(Fast(123456789012.5) == "123456789012");
  CHECK(Fast(123456789013.5) == "123456789014");
  CHECK(Fast(0.0001) == "0.0001");
  CHECK(Fast(0.00001) == "1e-05");
}

}  // namespace koppel::number_text_test
