#include "unit/unit_widths.hpp"

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
  return w;
}

namespace {

[[noreturn]] void throw_width(int64_t v, int bits, uint32_t tri, const char* name, const char* kind,
                              const char* what) {
  throw WidthError("triangle " + std::to_string(tri) + ": " + name + " = " + std::to_string(v) +
                   " does not fit " + std::to_string(bits) + "-bit " + kind + " " + what);
}

}  // namespace

void check_signed(int64_t v, int bits, uint32_t tri, const char* name, const char* what) {
  if (!fits_signed(v, bits)) throw_width(v, bits, tri, name, "signed", what);
}

void check_unsigned(int64_t v, int bits, uint32_t tri, const char* name, const char* what) {
  if (!fits_unsigned(v, bits)) throw_width(v, bits, tri, name, "unsigned", what);
}

}  // namespace trirast
