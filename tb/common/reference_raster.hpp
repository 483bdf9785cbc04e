// A deliberately simple, independent implementation of docs/coverage-rule.md, used only by tests to
// check the engines: its own snapping, 128-bit edge functions from the vertices, a per-pixel test
// of every pixel near the triangle. Slow and obvious on purpose.
#pragma once
#include <cstdint>
#include <vector>

#include "common/config.hpp"
#include "common/setup.hpp"
#include "common/span.hpp"
#include "scene/rng.hpp"

namespace trirast::test {

// Spans of every triangle of the scene, sorted, by the rule applied pixel by pixel.
// Triangles that the rule gives no pixels (zero area, culled) produce nothing.
SpanList reference_raster(const std::vector<InputTriangle>& tris, const RasterConfig& cfg);

// Small deterministic PRNG for tests: splitmix64 (scene/rng.hpp), the same sequence on every
// platform; no std distributions (implementation-defined).
struct TestRng {
  uint64_t state;
  explicit TestRng(uint64_t seed) : state(seed) {}
  uint64_t next() { return splitmix64(state); }
  // Uniform integer in [lo, hi] (inclusive), hi - lo < 2^63.
  int64_t range(int64_t lo, int64_t hi) { return lo + int64_t(next() % uint64_t(hi - lo + 1)); }
  // A value of a random bit length 1..max_bits, so small and large magnitudes both occur.
  int64_t bits(int max_bits) {
    const int b = int(range(1, max_bits));
    return int64_t(next() & ((uint64_t(1) << b) - 1));
  }
};

// Random triangles with vertices on the 1/2^grid_bits pixel grid within [lo, hi) pixels.
std::vector<InputTriangle> random_grid_triangles(TestRng& rng, int count, double lo_x, double hi_x,
                                                 double lo_y, double hi_y, int grid_bits,
                                                 double max_size);

}  // namespace trirast::test
