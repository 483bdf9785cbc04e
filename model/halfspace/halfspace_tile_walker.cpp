#include "halfspace/halfspace_tile_walker.hpp"

namespace trirast {

HalfspaceTileWalker::HalfspaceTileWalker(const RasterConfig& cfg) : p_(HalfspaceParams::from(cfg)), w_(unit_widths(cfg)) {}

HalfspaceUnitTest HalfspaceTileWalker::classify(const HalfspaceSetupOut& s, int64_t i0, int64_t j0) const {
  const int64_t d = p_.unit() - 1;  // far corner offset: (U - 1) pixels
  unsigned edges_inside = 0;
  for (int k = 0; k < 3; ++k) {
    const HalfspaceEdge& e = s.edge[k];
    const int64_t c00 = e.E0 + i0 * e.a + j0 * e.b;
    const int64_t c[4] = {c00, c00 + d * e.a, c00 + d * e.b, c00 + d * e.a + d * e.b};
    int inside = 0;
    for (int64_t v : c) {
      check_signed(v, w_.hs_edge_value, s.tri, "corner E", "half-space corner value");
      inside += v >= 0;
    }
    if (inside == 0) return {HalfspaceClass::Reject, edges_inside};
    if (inside == 4) edges_inside |= 1u << k;
  }
  // A stamp's pixels are tested one by one: only a tile is accepted whole.
  return {(edges_inside == 7 && p_.tile > 0) ? HalfspaceClass::Accept : HalfspaceClass::Partial,
          edges_inside};
}

}  // namespace trirast
