// Stage 5 of the unit, `span_generator`: combines the three walkers' bounds of one row into at
// most one span (docs/unit.md, section 5).
#pragma once
#include <cstdint>

#include "common/span.hpp"
#include "improved/improved_edge_normalizer.hpp"
#include "improved/improved_edge_walker.hpp"

namespace trirast {

// The generator's output for one row, box-relative.
struct SpanGenOut {
  bool valid;     // a span leaves for this row
  int64_t begin;  // first covered i
  int64_t end;    // one past the last covered i
};

class ImprovedSpanGenerator {
 public:
  // Row j of a box Xmax + 1 wide: out if any edge is out; else begin = max(0, mirrored bounds),
  // end = min(Xmax + 1, non-mirrored bounds); a span when begin < end.
  static SpanGenOut row(const NormalizedEdge edge[3], const WalkerRow bound[3], int64_t Xmax);
  // The span in screen coordinates for box origin (x0, y0), row j.
  static Span to_span(const SpanGenOut& g, uint32_t tri, int32_t x0, int32_t y0, int64_t j) {
    return Span{tri, int32_t(y0 + j), int32_t(x0 + g.begin), int32_t(x0 + g.end)};
  }
};

}  // namespace trirast
