// The second-generation unit's corner stage (docs/improved2.md, "Architecture", C: the corner
// stage): vertex-relative corner values, E_L = A*(cx0 - vx) + B*(cy0 - vy) + bias per edge (no C:
// E vanishes at the edge's own vertex vx, vy), and E_R = E_L + Xmax*a. The same values as gen1's
// interface (E(c) + bias, unit/interface.hpp); the hardware forms them either as DSP products in
// one cycle or digit-serially, MSB first, 4 operand bits per cycle
// (rtl/common/trirast_corner_serial.sv, DigitBits 4: signed-digit pairs of two's complement operands),
// whose run length is digits().
#pragma once
#include <cstdint>

#include "common/config.hpp"
#include "common/setup.hpp"
#include "common/box_stage.hpp"
#include "common/corner_serial.hpp"

namespace trirast {

class Improved2CornerUnit {
 public:
  explicit Improved2CornerUnit(const RasterConfig& cfg);
  // E_L of edge k at the pixel centre of (x0, y0), relative to the edge's operand_vertex(k).
  int64_t corner_value(const TriangleSetup& t, int k, int64_t x0, int64_t y0) const;
  // The digit-serial unit's run length at (x0, y0): the fewest digits of 4 bits in which every
  // operand cx0 - vx, cy0 - vy of v0 and v1 fits as a two's complement number (its sign bit
  // included; at least 1): trirast_corner_serial's counter. Edges 0 and 2 take their operands
  // from v0, which lies on both, edge 1 from v1.
  int digits(const TriangleSetup& t, int64_t x0, int64_t y0) const;
  // Fills E_L and E_R of every edge of `box` (its a, b, x0, y0, Xmax already set) and checks them
  // against gen1's (`gen1`): a difference is a model bug (std::logic_error).
  void run(const TriangleSetup& t, BoxStageOut& box, const BoxStageOut& gen1) const;

  static constexpr int kDigitBits = kCornerSerialDigitBits;
  static constexpr int operand_vertex(int k) { return corner_operand_vertex(k); }

 private:
  RasterConfig cfg_;
};

}  // namespace trirast
