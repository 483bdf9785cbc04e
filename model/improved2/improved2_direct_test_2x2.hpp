// The second-generation unit's direct 2x2 test (rtl/improved2/trirast_improved2_direct_test_2x2.sv): a box of at most
// 2 x 2 pixel centres (Xmax <= 1, Ymax <= 1) is tested from the corner values alone, twelve sign
// tests E_L, E_L + a, E_L + b, E_L + a + b >= 0, and each of its (at most two) rows gives at most
// one span (a convex triangle covers a run). No lanes, no walkers.
#pragma once
#include <cstdint>

#include "common/box_stage.hpp"

namespace trirast {

struct Improved2DirectTestOut {
  bool valid[2];     // row j has a span
  int64_t begin[2];  // box-relative first covered column (0 or 1)
  int64_t end[2];    // one past the last (1 or 2)
};

class Improved2DirectTest2x2 {
 public:
  // True for a box the test takes instead of the lanes.
  static bool takes(const BoxStageOut& box) { return box.Xmax <= 1 && box.Ymax <= 1; }
  // The two rows' spans of a box that takes() (E_L with the bias, a, b of each edge).
  static Improved2DirectTestOut run(const BoxStageOut& box);
};

}  // namespace trirast
