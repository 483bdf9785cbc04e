#include "common/unit_widths.hpp"

#include <algorithm>
#include <string>

namespace trirast {

UnitWidths unit_widths(const RasterConfig& cfg) {
  UnitWidths w;
  w.frac = cfg.frac_bits();
  w.vertex = cfg.vertex_bits();     // p = coord_int_bits + F
  w.edge_coef = w.vertex + 1;       // A = a.y - b.y of two p-bit values
  w.step = w.vertex + w.frac;       // |A| < 2^p, times u = 2^F
  w.edge_value = 2 * w.vertex + 2;  // docs/coverage-rule.md: E needs 2p + 2 bits
  w.box = cfg.box_bits;             // box <= 2^box_bits pixels
  w.quotient = cfg.box_bits + 1;    // Q: a pixel count in the box, or "beyond the box"
  w.remainder = w.step;             // 0 <= r < D, and D has p + F bits
  w.walker_x = w.quotient + 2;      // X' in [-(2^Q + 1), 2^Q + 2^box_bits)
  w.numerator = w.edge_value;       // |edge value| of a 2p+2-bit signed value
  w.hs_edge_value = hs_edge_bits(cfg, cfg.halfspace.tile > 0 ? cfg.halfspace.tile : cfg.halfspace.stamp);
  int log2_tile = 0;
  while ((1 << log2_tile) < cfg.halfspace.tile) ++log2_tile;
  w.hs_stamp_value = cfg.halfspace.tile > 0 ? w.edge_coef + log2_tile + 1 + w.frac : w.edge_value;
  return w;
}

int hs_edge_bits(const RasterConfig& cfg, int unit_side) {
  // In frac_bits() units (u = 2^F per pixel, h = u / 2), on one axis: a vertex lies in
  // [-L u, L u) (L = 2^(coord_int_bits - 1), L u = 2^(p-1)); the box's pixels x0..x0 + Xmax lie in
  // the viewport, x0 + Xmax < L (the viewport port), Xmax < 2^box_bits; the units start at
  // x0 + k U <= x0 + Xmax, so a corner is pixel x0 + i with i < R = Xmax + 1 rounded up to U.
  //   x0 = 0 (the box clipped, a vertex anywhere left): distance <= (R - 1) u + h + L u,
  //          R <= roundup(min(2^box_bits, L), U);
  //   x0 > 0 (pixel x0 - 1's centre lies left of every vertex): distance < R u,
  //          R <= roundup(min(2^box_bits, L - 1), U).
  // Both are at most 2^p - h (the pixels' own bound, 2p + 2 bits) unless the units reach past
  // the viewport's largest extent, i.e. U > L (coord_int_bits <= 4). With |A|, |B| <= 2^p - 1:
  // |E| <= 2 (2^p - 1) reach + 1 (the top-left bias).
  const int p = cfg.vertex_bits(), F = cfg.frac_bits();
  const int64_t u = int64_t(1) << F, h = u / 2, L = cfg.coord_limit_px();
  const int64_t box = int64_t(1) << cfg.box_bits, U = unit_side;
  auto roundup = [U](int64_t v) { return (v + U - 1) / U * U; };
  const int64_t clipped = (roundup(std::min(box, L)) - 1) * u + h + L * u;
  const int64_t unclipped = roundup(std::min(box, L - 1)) * u;
  const int64_t reach = std::max(clipped, unclipped);
  // In 128 bits: a configuration RasterConfig accepts can need more than 63 (p up to 32, reach
  // up to 2^33); the caller refuses those (HalfspaceUnit: WidthError), so they must not wrap here.
  const __int128 bound = __int128(2) * ((__int128(1) << p) - 1) * reach + 1;
  int bits = 0;
  while ((bound >> bits) != 0) ++bits;
  return bits + 1;  // magnitude bits + sign
}

// Out-of-line copies of the inline checks, for code compiled against the header's older,
// non-inline declarations (the Verilated RTL models a build may take prebuilt from another tree,
// TRIRAST_RTL_MODELS_FROM).
[[maybe_unused]] __attribute__((used)) void (*const keep_check_signed)(int64_t, int, uint32_t,
                                                                       const char*, const char*) =
    &check_signed;
[[maybe_unused]] __attribute__((used)) void (*const keep_check_unsigned)(int64_t, int, uint32_t,
                                                                         const char*,
                                                                         const char*) =
    &check_unsigned;

void throw_width(int64_t v, int bits, uint32_t tri, const char* name, const char* kind,
                 const char* what) {
  throw WidthError("triangle " + std::to_string(tri) + ": " + name + " = " + std::to_string(v) +
                   " does not fit " + std::to_string(bits) + "-bit " + kind + " " + what);
}

}  // namespace trirast
