// The half-space unit (docs/unit.md, "The half-space unit"), stage 1: box and edge setup at the
// box corner. The same inputs and values as the improved unit's interface (the corner value, the
// per-pixel steps a = A*u and b = B*u), plus the value at the first tile of a right-to-left band
// (the zig-zag walk's start), E_L + (n-1)*U*a. The hardware forms both corner values from
// products (corner form dsp) or with the digit-serial corner unit (corner form radix16,
// common/corner_serial.hpp), whose run lengths the stage then records.
#pragma once
#include <cstdint>

#include "common/config.hpp"
#include "common/setup.hpp"
#include "common/box_stage.hpp"
#include "common/unit_widths.hpp"

namespace trirast {

// The unit's build parameters, from the configuration.
struct HalfspaceParams {
  int stamp;    // S: pixels per stamp side (1, 2, 4)
  int tile;     // T: pixels per tile side (8, 16), 0 = no tiles
  HalfspaceWalk walk;  // tile order
  int corner_form = 0;  // the set-up's corner values: 0 products, 1 radix 16 (cycles only)
  // U: the side of the walker's unit (a tile, or a stamp when there are no tiles) and the
  // height of a band.
  int unit() const { return tile > 0 ? tile : stamp; }
  static HalfspaceParams from(const RasterConfig& cfg) {
    return {cfg.halfspace.stamp, cfg.halfspace.tile, cfg.halfspace.walk, cfg.halfspace.corner_form};
  }
};

// One edge at the box corner: E(i, j) = E0 + i*a + j*b >= 0 means box pixel (i, j) is inside
// (the top-left bias is folded into E0).
struct HalfspaceEdge {
  int64_t a;    // A*u                                   (p + F + 1 signed)
  int64_t b;    // B*u                                   (p + F + 1 signed)
  int64_t E0;   // E(centre of box pixel (0, 0)) + bias  (2p + 2 signed)
  int64_t Eend; // E0 + (n - 1)*U*a: the last unit of a band's row 0 (2p + 2 signed)
};

// The setup stage's output register (the hand-off to the walk stage).
struct HalfspaceSetupOut {
  uint32_t tri = 0;
  bool empty = true;        // no pixel centre in the box: retires with no span
  int32_t x0 = 0, y0 = 0;   // box origin in pixels
  int64_t Xmax = 0, Ymax = 0;  // box-relative extent (box_bits unsigned)
  int64_t units = 0;        // n = ceil((Xmax + 1) / U): units per band
  int64_t bands = 0;        // ceil((Ymax + 1) / U)
  HalfspaceEdge edge[3];
  // Corner form radix16, the digit-serial corner unit's runs (common/corner_serial.hpp): run 1
  // forms E0 in corner_digits_e0 digit cycles, run 2 E_end in corner_digits_eend (0: no run 2,
  // the box is one unit wide and E_end = E0). Both 0 in corner form dsp.
  int corner_digits_e0 = 0, corner_digits_eend = 0;
};

class HalfspaceSetupStage {
 public:
  explicit HalfspaceSetupStage(const RasterConfig& cfg);
  HalfspaceSetupOut run(const TriangleSetup& t) const;

 private:
  RasterConfig cfg_;
  HalfspaceParams p_;
  UnitWidths w_;
  BoxStage interface_;
};

}  // namespace trirast
