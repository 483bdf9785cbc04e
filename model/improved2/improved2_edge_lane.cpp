#include "improved2/improved2_edge_lane.hpp"

#include <algorithm>

#include "common/fixed_point.hpp"

namespace trirast {

namespace {
// unsigned_bits (fixed_point.hpp) without its loop: at least 1, else the position of the top bit
// plus one.
inline int bits_of(uint64_t v) { return v == 0 ? 1 : 64 - __builtin_clzll(v); }
}  // namespace

int64_t Improved2EdgeLane::traverse(const NormalizedEdge& n, int64_t Ymax) {
  // The traversal: dir - keeps u = ~v, so both directions add s and "entered" is u >= 0.
  int64_t u = n.dir_down ? n.T : -n.T1 - 1;
  int64_t j = 0;
  while (u < 0 && j <= Ymax) {
    u += n.s;
    ++j;
  }
  return j;
}

Improved2LaneWork Improved2EdgeLane::from_traversal(const NormalizedEdge& n, int64_t Xmax,
                                                    int64_t Ymax, int64_t steps) {
  Improved2LaneWork w;
  w.m = std::max(1, bits_of(uint64_t(Xmax))) + 1;
  const int64_t j = steps;
  const int64_t u = (n.dir_down ? n.T : -n.T1 - 1) + j * n.s;  // the column value after T steps
  w.steps = j;
  w.enters = j <= Ymax;
  if (n.horizontal) {
    w.cycles = uint64_t(j) + 1;
    return w;
  }
  const int64_t limit = n.D << w.m;  // a quotient of 2^m or more saturates
  w.slope_saturated = n.s >= limit;
  const int ms = w.slope_saturated ? 2 : w.m;
  int me = 0;
  if (w.enters) {
    w.entry_saturated = u >= limit;
    me = w.entry_saturated ? 2 : w.m;
  }
  w.iterations = uint64_t(ms + me);
  w.cycles = uint64_t(std::max<int64_t>(ms, j)) + 1 + uint64_t(me);
  return w;
}

Improved2LaneWork Improved2EdgeLane::run(const NormalizedEdge& n, int64_t Xmax, int64_t Ymax) {
  return from_traversal(n, Xmax, Ymax, traverse(n, Ymax));
}

}  // namespace trirast
