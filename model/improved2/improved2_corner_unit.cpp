#include "improved2/improved2_corner_unit.hpp"

#include <stdexcept>
#include <string>

namespace trirast {

Improved2CornerUnit::Improved2CornerUnit(const RasterConfig& cfg) : cfg_(cfg) {}

int64_t Improved2CornerUnit::corner_value(const TriangleSetup& t, int k, int64_t x0, int64_t y0) const {
  return corner_serial_value(t, k, x0, y0, cfg_);
}

int Improved2CornerUnit::digits(const TriangleSetup& t, int64_t x0, int64_t y0) const {
  return corner_serial_digits(t, x0, y0, cfg_);
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
