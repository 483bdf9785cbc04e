// The second-generation unit's redesigned lane (rtl/improved2/trirast_improved2_edge_lane.sv: gen1's normalizer
// folded into the load, boundary mode step, adaptive divider): its results are gen1's normalizer
// + lane's wherever the walker reads them (tb/improved2/improved2_edge_lane_tb.sv), so the model takes
// those from gen1's classes; what is its own is the cycle count, computed here.
//
// From the cycle after the load to the first cycle the lane is done (trirast_improved2_edge_lane.sv's header):
//   horizontal edge:                       T + 1
//   otherwise:  max(ms, T) + 1 + (enters ? me : 0)
// with T the traversal's row steps (the column value u = T, dir +, or ~T1 = -T1 - 1, dir -, plus
// s per row until u >= 0 or past row Ymax), m = max(1, bits(Xmax)) + 1 the iterations of a
// division, and a division's iterations ms (slope s / D), me (entry u / D) = 2 when it saturates
// (n >= D * 2^m: it stops after its second iteration), m otherwise. The 1 is the entry
// division's set-up cycle folded into the decision (the slope's set-up is the cycle after the
// load, counted in max(ms, T) + 1).
#pragma once
#include <cstdint>

#include "improved/improved_edge_normalizer.hpp"

namespace trirast {

struct Improved2LaneWork {
  int m = 0;            // iterations of an x division
  int64_t steps = 0;    // T: traversal row steps
  bool enters = false;  // the edge enters the box (an entry division runs)
  bool slope_saturated = false;
  bool entry_saturated = false;
  uint64_t iterations = 0;  // divider iterations run (slope + entry)
  uint64_t cycles = 0;      // L_k: from the cycle after the load to the first done cycle
};

class Improved2EdgeLane {
 public:
  // The lane's own traversal, then its cycles: traverse() + from_traversal().
  static Improved2LaneWork run(const NormalizedEdge& n, int64_t Xmax, int64_t Ymax);
  // The traversal's row steps T (Ymax + 1 when the edge never enters the box), one step per
  // loop iteration as the lane takes them.
  static int64_t traverse(const NormalizedEdge& n, int64_t Ymax);
  // The lane's work and cycles given its traversal's row steps T (the column value after them is
  // u0 + T*s, u0 the start value): Improved2Unit takes T from gen1's walker, which traverses the
  // same rows, and compares it with traverse() when it cross-checks (Improved2Unit's check).
  static Improved2LaneWork from_traversal(const NormalizedEdge& n, int64_t Xmax, int64_t Ymax,
                                          int64_t steps);
};

}  // namespace trirast
