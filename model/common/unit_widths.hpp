// Bit widths of every value in the improved-Bresenham unit, derived from the configuration
// (docs/unit.md, "Widths"). One source of truth: the stages, the SystemC model and the RTL
// package all read these numbers. Every stage checks its values against them and throws a
// WidthError naming the triangle and the value; nothing wraps silently.
#pragma once
#include <cstdint>

#include "common/config.hpp"
#include "common/fixed_point.hpp"

namespace trirast {

struct UnitWidths {
  int frac;        // F: fractional bits of the arithmetic (S, or 1 when S = 0)
  int vertex;      // p: signed bits of a vertex coordinate
  int edge_coef;   // p + 1: signed bits of A and B
  int step;        // p + F: unsigned bits of D and s (|A|*u, |B|*u)
  int edge_value;  // 2p + 2: signed bits of E_L, E_R, T, T1 and the column walk's values
  int box;         // box_bits: unsigned bits of i, j, Xmax, Ymax
  int quotient;    // Q = box_bits + 1: unsigned quotient bits (plus a saturation flag)
  int remainder;   // p + F: unsigned bits of a remainder or Bresenham error e
  int walker_x;    // Q + 2: signed bits of the walker's bound X'
  int numerator;   // 2p + 2: unsigned bits of a divider numerator (a magnitude of an edge value)
  // The half-space unit's edge values at the corners of its U x U units (U = --tile, or --stamp
  // without tiles), which lie up to U - 1 pixels past the box and so past the coordinate range:
  // hs_edge_bits(cfg, U): 2p + 2 unless U > 2^(coord_int_bits - 1), i.e. the units reach past
  // the largest viewport (coord_int_bits <= 4 with tiles).
  int hs_edge_value;
  // With tiles, a partial tile's stamp values of an edge that crosses the tile (not all four
  // corners inside it): tile-relative, between the smallest and the largest corner, whose spread
  // (T - 1)(|A| + |B|) u < 2^(p + 1 + log2 T + F): p + 2 + log2 T + F signed bits. An edge that
  // holds the whole tile inside is masked, not summed. Without tiles: edge_value.
  int hs_stamp_value;
};

// Signed bits of every edge value the half-space unit forms at a unit corner for unit side U:
// |E| <= 2 (2^p - 1) reach + 1, with reach the farthest a corner (up to U - 1 pixels past the
// box) lies from a vertex on one axis, from the coordinate range, the viewport and the box size
// (unit_widths.cpp derives it; docs/unit.md).
int hs_edge_bits(const RasterConfig& cfg, int unit_side);

// The widths for one configuration.
UnitWidths unit_widths(const RasterConfig& cfg);

// Throws the WidthError of check_signed / check_unsigned (kind "signed" or "unsigned").
[[noreturn]] void throw_width(int64_t v, int bits, uint32_t tri, const char* name, const char* kind,
                              const char* what);
// Throws WidthError("triangle N: <name> = V does not fit W-bit signed <what>") unless v fits.
// Inline: the bit-accurate datapath calls it for every register it loads (a call per check
// was about 7 % of the SystemC models' instructions, callgrind).
inline void check_signed(int64_t v, int bits, uint32_t tri, const char* name, const char* what) {
  if (__builtin_expect(!fits_signed(v, bits), 0)) throw_width(v, bits, tri, name, "signed", what);
}
// Same for an unsigned field (a negative value never fits).
inline void check_unsigned(int64_t v, int bits, uint32_t tri, const char* name, const char* what) {
  if (__builtin_expect(!fits_unsigned(v, bits), 0)) throw_width(v, bits, tri, name, "unsigned", what);
}

}  // namespace trirast
