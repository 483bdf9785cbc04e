// Stage 1 of the unit, `interface`: takes a set-up triangle, computes its pixel bounding box and
// the box-relative edge terms every later stage works with (docs/unit.md, section 1).
#pragma once
#include <cstdint>

#include "common/config.hpp"
#include "common/setup.hpp"
#include "common/unit_widths.hpp"

namespace trirast {

// One edge in box-relative form: E(i, j) = E_L + i*a + j*b (bias folded into E_L and E_R).
struct BoxStageEdge {
  int64_t a;    // A*u: step of E per pixel along i              (p + F + 1 signed)
  int64_t b;    // B*u: step of E per row along j                (p + F + 1 signed)
  int64_t E_L;  // E(c(x0, y0)) + bias: top-left pixel centre    (2p + 2 signed)
  int64_t E_R;  // E(c(x1, y0)) + bias = E_L + Xmax*a            (2p + 2 signed)
};

// The interface's output register: what it hands to the three edge normalizers.
struct BoxStageOut {
  uint32_t tri;        // scene index of the triangle
  bool empty;          // no pixel centre in the clipped box: retire with no span
  int32_t x0, y0;      // box origin in pixels
  int64_t Xmax, Ymax;  // x1 - x0, y1 - y0                    (box_bits unsigned)
  BoxStageEdge edge[3];
};

class BoxStage {
 public:
  explicit BoxStage(const RasterConfig& cfg);
  // Computes the box (checked against the setup's), the width checks, and the edge terms.
  BoxStageOut run(const TriangleSetup& t) const;

 private:
  // First and last pixel whose centre lies in [lo, hi], clipped to [0, limit).
  void centre_range(int64_t lo, int64_t hi, int64_t limit, int64_t& first, int64_t& last) const;

  RasterConfig cfg_;
  UnitWidths w_;
};

}  // namespace trirast
