// Stage 2 of the unit, `edge_normalizer` (x3): turns an edge into the paper's one form
// f(i', j) = T - i'*D + j*b >= 0 with D > 0, i.e. the bound i' <= X'(j) = floor((T + j*b) / D),
// by mirroring x; and restores real span bounds from X' at the end (docs/unit.md, section 2).
#pragma once
#include <cstdint>

#include "common/box_stage.hpp"
#include "common/unit_widths.hpp"

namespace trirast {

// The normalizer's output register for one edge.
struct NormalizedEdge {
  bool horizontal;  // a == 0: no x bound, the row is wholly in or out (D = 0)
  bool mirror;      // a > 0: a left edge, i' = Xmax - i, bounds the span's begin
  bool dir_down;    // dir +: b >= 0, X' grows down the box; dir -: b < 0
  int64_t T;        // f at column i' = 0, row 0          (2p + 2 signed)
  int64_t T1;       // f at column i' = Xmax, row 0       (2p + 2 signed)
  int64_t D;        // |a|                                (p + F unsigned)
  int64_t s;        // |b|                                (p + F unsigned)
};

class ImprovedEdgeNormalizer {
 public:
  explicit ImprovedEdgeNormalizer(const RasterConfig& cfg);
  // Mirrors and splits signs off one box-relative edge of a box Xmax + 1 pixels wide.
  NormalizedEdge run(const BoxStageEdge& e, int64_t Xmax, uint32_t tri) const;

  // Restores a box-relative span bound from a bound X' on the normalized column i':
  // non-mirrored: x_end = X' + 1 (exclusive); mirrored: x_begin = Xmax - X'.
  static int64_t restore(const NormalizedEdge& n, int64_t Xprime, int64_t Xmax) {
    return n.mirror ? Xmax - Xprime : Xprime + 1;
  }

 private:
  UnitWidths w_;
};

}  // namespace trirast
