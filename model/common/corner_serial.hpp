// The digit-serial corner unit (rtl/common/trirast_corner_serial.sv), shared by the
// second-generation improved unit (its iCE40 corner form) and the half-space unit's set-up stage:
// vertex-relative corner values E = A*(cx - vx) + B*(cy - vy) + bias per edge (no C: E vanishes
// at the edge's own vertex), formed MSB first, kCornerSerialDigitBits operand bits per cycle, in
// corner_serial_digits() cycles after the run's start.
#pragma once
#include <cstdint>

#include "common/config.hpp"
#include "common/setup.hpp"

namespace trirast {

constexpr int kCornerSerialDigitBits = 4;  // radix 16

// The vertex edge k's operands are taken from: v0 lies on edges 0 (v0 -> v1) and 2 (v2 -> v0),
// so the hardware forms two operand pairs, v0's and v1's.
constexpr int corner_operand_vertex(int k) { return k == 1 ? 1 : 0; }

// E of edge k at the pixel centre of (x, y), relative to the edge's corner_operand_vertex(k), with
// the top-left bias: the same value as the interface's E(c) + bias.
int64_t corner_serial_value(const TriangleSetup& t, int k, int64_t x, int64_t y,
                            const RasterConfig& cfg);

// A run's length at pixel (x, y): the fewest digits of kCornerSerialDigitBits bits in which every
// operand cx - vx, cy - vy of v0 and v1 fits as a two's complement number (its sign bit included;
// at least 1): the unit's digit counter. A second run at (x1, y) keeps the first run's y operands,
// so its length is corner_serial_digits(t, x1, y).
int corner_serial_digits(const TriangleSetup& t, int64_t x, int64_t y, const RasterConfig& cfg);

}  // namespace trirast
