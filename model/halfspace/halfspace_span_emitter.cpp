#include "halfspace/halfspace_span_emitter.hpp"

#include <algorithm>

namespace trirast {

HalfspaceSpanEmitter::HalfspaceSpanEmitter(const RasterConfig& cfg)
    : U_(HalfspaceParams::from(cfg).unit()), rows_(size_t(HalfspaceParams::from(cfg).unit())) {}

void HalfspaceSpanEmitter::begin_band(int64_t j0) {
  j0_ = j0;
  for (Run& r : rows_) r = Run{};
}

void HalfspaceSpanEmitter::merge(int64_t j, int64_t first, int64_t last) {
  Run& r = rows_.at(size_t(j - j0_));
  if (r.any) {
    // A row of a triangle is one run, so the hull of its pieces is the run (the pieces of a
    // right-to-left band may arrive with a gap that a later piece fills).
    r.first = std::min(r.first, first);
    r.last = std::max(r.last, last);
  } else {
    r = Run{true, first, last};
  }
}

size_t HalfspaceSpanEmitter::end_band(const HalfspaceSetupOut& s, SpanList& out) {
  size_t n = 0;
  for (int r = 0; r < U_; ++r) {
    const Run& run = rows_[size_t(r)];
    if (!run.any) continue;
    out.push_back(Span{s.tri, int32_t(s.y0 + j0_ + r), int32_t(s.x0 + run.first),
                       int32_t(s.x0 + run.last + 1)});
    ++n;
  }
  return n;
}

}  // namespace trirast
