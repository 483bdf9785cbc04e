#include "improved/improved_edge_normalizer.hpp"

#include <stdexcept>
#include <string>

namespace trirast {

ImprovedEdgeNormalizer::ImprovedEdgeNormalizer(const RasterConfig& cfg) : w_(unit_widths(cfg)) {}

NormalizedEdge ImprovedEdgeNormalizer::run(const BoxStageEdge& e, int64_t Xmax, uint32_t tri) const {
  NormalizedEdge n{};
  n.horizontal = e.a == 0;
  n.mirror = e.a > 0;
  if (n.mirror) {
    // Left edge: i' = Xmax - i, so f(i', j) = E_R - i'*a + j*b.
    n.T = e.E_R;
    n.T1 = e.E_L;
    n.D = e.a;
  } else {
    // Right edge (or horizontal, D = 0): i' = i, f(i', j) = E_L - i'*(-a) + j*b.
    n.T = e.E_L;
    n.T1 = e.E_R;
    n.D = -e.a;
  }
  // Row direction and slope magnitude.
  n.dir_down = e.b >= 0;
  n.s = n.dir_down ? e.b : -e.b;
  // Widths of the register's fields.
  check_signed(n.T, w_.edge_value, tri, "T", "edge value");
  check_signed(n.T1, w_.edge_value, tri, "T1", "edge value");
  check_unsigned(n.D, w_.step, tri, "D", "x step");
  check_unsigned(n.s, w_.step, tri, "s", "y step");
  // T1 is the same function at the far column (E_R = E_L + Xmax*a makes it so).
  if (n.T1 != n.T - Xmax * n.D)
    throw std::logic_error("triangle " + std::to_string(tri) + ": T1 != T - Xmax*D");
  return n;
}

}  // namespace trirast
