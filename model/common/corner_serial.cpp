#include "common/corner_serial.hpp"

namespace trirast {

namespace {
// unsigned_bits (fixed_point.hpp) without its loop: at least 1, else the position of the top bit
// plus one.
inline int bits_of(uint64_t v) { return v == 0 ? 1 : 64 - __builtin_clzll(v); }
}  // namespace

int64_t corner_serial_value(const TriangleSetup& t, int k, int64_t x, int64_t y,
                            const RasterConfig& cfg) {
  const int v = corner_operand_vertex(k);
  const int64_t dx = pixel_centre(x, cfg) - t.v[v].x;
  const int64_t dy = pixel_centre(y, cfg) - t.v[v].y;
  return t.edge[k].A * dx + t.edge[k].B * dy + t.edge[k].bias;
}

int corner_serial_digits(const TriangleSetup& t, int64_t x, int64_t y, const RasterConfig& cfg) {
  // d fits in m signed bits exactly when d (d >= 0) or ~d (d < 0) has at most m - 1 bits.
  uint64_t any = 0;
  for (int v = 0; v < 2; ++v) {  // the operands of v0 and v1 (corner_operand_vertex)
    const int64_t dx = pixel_centre(x, cfg) - t.v[v].x;
    const int64_t dy = pixel_centre(y, cfg) - t.v[v].y;
    any |= uint64_t(dx < 0 ? ~dx : dx) | uint64_t(dy < 0 ? ~dy : dy);
  }
  const int bits = bits_of(any) + 1;  // the sign bit
  return (bits + kCornerSerialDigitBits - 1) / kCornerSerialDigitBits;
}

}  // namespace trirast
