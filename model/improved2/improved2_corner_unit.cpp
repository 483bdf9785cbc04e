#include "improved2/improved2_corner_unit.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/fixed_point.hpp"

namespace trirast {

namespace {
// unsigned_bits (fixed_point.hpp) without its loop: at least 1, else the position of the top bit
// plus one.
inline int bits_of(uint64_t v) { return v == 0 ? 1 : 64 - __builtin_clzll(v); }
}  // namespace

Improved2CornerUnit::Improved2CornerUnit(const RasterConfig& cfg) : cfg_(cfg) {}

int64_t Improved2CornerUnit::corner_value(const TriangleSetup& t, int k, int64_t x0, int64_t y0) const {
  const int v = operand_vertex(k);
  const int64_t dx = pixel_centre(x0, cfg_) - t.v[v].x;
  const int64_t dy = pixel_centre(y0, cfg_) - t.v[v].y;
  return t.edge[k].A * dx + t.edge[k].B * dy + t.edge[k].bias;
}

int Improved2CornerUnit::digits(const TriangleSetup& t, int64_t x0, int64_t y0) const {
  // d fits in m signed bits exactly when d (d >= 0) or ~d (d < 0) has at most m - 1 bits.
  uint64_t any = 0;
  for (int v = 0; v < 2; ++v) {  // the operands of v0 and v1 (operand_vertex)
    const int64_t dx = pixel_centre(x0, cfg_) - t.v[v].x;
    const int64_t dy = pixel_centre(y0, cfg_) - t.v[v].y;
    any |= uint64_t(dx < 0 ? ~dx : dx) | uint64_t(dy < 0 ? ~dy : dy);
  }
  const int bits = bits_of(any) + 1;  // the sign bit
  return (bits + kDigitBits - 1) / kDigitBits;
}

void Improved2CornerUnit::run(const TriangleSetup& t, BoxStageOut& box, const BoxStageOut& gen1) const {
  for (int k = 0; k < 3; ++k) {
    BoxStageEdge& e = box.edge[k];
    e.E_L = corner_value(t, k, box.x0, box.y0);
    e.E_R = e.E_L + box.Xmax * e.a;
    if (e.E_L != gen1.edge[k].E_L || e.E_R != gen1.edge[k].E_R)
      throw std::logic_error("triangle " + std::to_string(t.index) + ": edge " + std::to_string(k) +
                             ": vertex-relative corner values differ from the interface's");
  }
}

}  // namespace trirast
