// Deterministic random numbers for the built-in scenes: xoshiro256** seeded through splitmix64,
// with our own integer -> double mapping. The standard distributions are implementation-defined,
// so they are never used: the same seed must give the same scene on every compiler and library.
#pragma once
#include <cstdint>

namespace trirast {

// splitmix64 (Steele, Lea, Flood): expands one 64-bit seed into well-mixed state words.
inline uint64_t splitmix64(uint64_t& state) {
  uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// xoshiro256** (Blackman, Vigna).
class SceneRng {
 public:
  explicit SceneRng(uint64_t seed) {
    uint64_t sm = seed;
    for (uint64_t& word : s_) word = splitmix64(sm);
  }

  uint64_t next_u64() {
    const uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  // Uniform in [0, 1): the top 53 bits scaled by 2^-53 (exact, no rounding).
  double unit() { return double(next_u64() >> 11) * 0x1.0p-53; }

  // Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }

  // Integer in [0, n) by multiply-high (Lemire, without the rejection step; the bias of at most
  // n / 2^64 is irrelevant here). n must be > 0.
  uint64_t below(uint64_t n) {
    return uint64_t((static_cast<unsigned __int128>(next_u64()) * n) >> 64);
  }

 private:
  static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  uint64_t s_[4];
};

}  // namespace trirast
