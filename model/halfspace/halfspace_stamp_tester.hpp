// The half-space unit, stage 3: the stamp tester. In one cycle it evaluates the three edge
// functions at the S x S pixel centres of a stamp (box pixel (i0, j0) and the S - 1 columns and
// rows after it; pixels beyond Xmax or Ymax are masked off) and gives, per stamp row, the first
// and last covered column. A row of a triangle is convex, so a stamp row's coverage is one run.
#pragma once
#include <cstdint>

#include "halfspace/halfspace_setup.hpp"

namespace trirast {

struct HalfspaceStampRow {
  bool any = false;
  int64_t first = 0, last = 0;  // box-relative columns of the covered run (inclusive)
};

struct HalfspaceStampOut {
  HalfspaceStampRow row[4];  // rows 0..S-1 of the stamp
  uint64_t covered = 0;
};

class HalfspaceStampTester {
 public:
  explicit HalfspaceStampTester(const RasterConfig& cfg);
  // edges_inside (bit k: edge k holds the whole tile inside; 0 without tiles) masks those edges:
  // a tile's stamp values are tile-relative, UnitWidths::hs_stamp_value bits, which only the
  // edges that cross the tile fit.
  HalfspaceStampOut test(const HalfspaceSetupOut& s, int64_t i0, int64_t j0, unsigned edges_inside) const;

 private:
  int S_;
  UnitWidths w_;
};

}  // namespace trirast
