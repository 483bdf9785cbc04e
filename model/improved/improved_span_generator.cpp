#include "improved/improved_span_generator.hpp"

#include <algorithm>

namespace trirast {

SpanGenOut ImprovedSpanGenerator::row(const NormalizedEdge edge[3], const WalkerRow bound[3],
                              int64_t Xmax) {
  SpanGenOut g{false, 0, Xmax + 1};
  for (int k = 0; k < 3; ++k) {
    // Any out edge empties the row; a clear edge does not limit it.
    if (bound[k].state == EdgeRowState::Out) return SpanGenOut{false, 0, 0};
    if (bound[k].state != EdgeRowState::Bound) continue;
    // Restore the real bound: mirrored -> begin, non-mirrored -> end.
    const int64_t x = ImprovedEdgeNormalizer::restore(edge[k], bound[k].X, Xmax);
    if (edge[k].mirror)
      g.begin = std::max(g.begin, x);
    else
      g.end = std::min(g.end, x);
  }
  g.valid = g.begin < g.end;
  return g;
}

}  // namespace trirast
