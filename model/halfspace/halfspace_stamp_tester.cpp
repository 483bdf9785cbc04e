#include "halfspace/halfspace_stamp_tester.hpp"

namespace trirast {

HalfspaceStampTester::HalfspaceStampTester(const RasterConfig& cfg) : S_(cfg.halfspace.stamp), w_(unit_widths(cfg)) {}

HalfspaceStampOut HalfspaceStampTester::test(const HalfspaceSetupOut& s, int64_t i0, int64_t j0,
                                             unsigned edges_inside) const {
  HalfspaceStampOut o;
  for (int dj = 0; dj < S_; ++dj) {
    const int64_t j = j0 + dj;
    if (j > s.Ymax) break;
    HalfspaceStampRow& r = o.row[dj];
    for (int di = 0; di < S_; ++di) {
      const int64_t i = i0 + di;
      if (i > s.Xmax) break;
      bool in = true;
      for (int k = 0; k < 3; ++k) {
        if (edges_inside >> k & 1u) continue;
        const HalfspaceEdge& e = s.edge[k];
        const int64_t v = e.E0 + i * e.a + j * e.b;
        check_signed(v, w_.hs_stamp_value, s.tri, "pixel E", "stamp value");
        in = in && v >= 0;
      }
      if (!in) continue;
      ++o.covered;
      if (!r.any) r.first = i;
      r.any = true;
      r.last = i;
    }
  }
  return o;
}

}  // namespace trirast
