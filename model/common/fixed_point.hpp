// Fixed-point helpers shared by every engine: mathematical floor/ceil division and width checks.
// C++ '/' truncates toward zero; the raster rule needs floor and ceil (docs/coverage-rule.md).
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>

namespace trirast {

// floor(n / d) for d > 0, any sign of n.
constexpr int64_t floor_div(int64_t n, int64_t d) {
  int64_t q = n / d;
  return (n % d != 0 && n < 0) ? q - 1 : q;
}

// ceil(n / d) for d > 0, any sign of n.
constexpr int64_t ceil_div(int64_t n, int64_t d) {
  int64_t q = n / d;
  return (n % d != 0 && n > 0) ? q + 1 : q;
}

// Number of bits a two's-complement signed value needs (sign bit included).
constexpr int signed_bits(int64_t v) {
  int bits = 1;
  while (v < -(int64_t(1) << (bits - 1)) || v >= (int64_t(1) << (bits - 1))) ++bits;
  return bits;
}

// Number of bits an unsigned (non-negative) value needs; 0 needs 1 bit.
constexpr int unsigned_bits(uint64_t v) {
  int bits = 1;
  while (bits < 64 && (v >> bits) != 0) ++bits;
  return bits;
}

constexpr bool fits_signed(int64_t v, int bits) {
  return bits >= 64 || (v >= -(int64_t(1) << (bits - 1)) && v < (int64_t(1) << (bits - 1)));
}

constexpr bool fits_unsigned(int64_t v, int bits) {
  return v >= 0 && (bits >= 63 || v < (int64_t(1) << bits));
}

// Raised when a value does not fit the width a hardware stage was configured with.
class WidthError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace trirast
