#include "halfspace/halfspace_span_emitter.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace trirast {

HalfspaceSpanEmitter::HalfspaceSpanEmitter(const RasterConfig& cfg)
    : U_(HalfspaceParams::from(cfg).unit()), rows_(size_t(HalfspaceParams::from(cfg).unit())) {}

void HalfspaceSpanEmitter::begin_band(int64_t j0, bool backward) {
  j0_ = j0;
  backward_ = backward;
  for (Run& r : rows_) r = Run{};
}

void HalfspaceSpanEmitter::begin_unit() {
  for (Run& r : rows_) r.in_unit = r.first_unit = false;
}

void HalfspaceSpanEmitter::merge(int64_t j, int64_t first, int64_t last) {
  Run& r = rows_.at(size_t(j - j0_));
  if (!r.any) {
    r = Run{true, true, true, first, last};
    return;
  }
  // The hull of the pieces (the pieces of a right-to-left band may arrive with a gap that a
  // later piece fills) is what the order gives.
  const int64_t hull_first = std::min(r.first, first), hull_last = std::max(r.last, last);
  if (backward_ && !r.in_unit) r.first = first;
  if (!backward_ || r.first_unit) r.last = last;
  r.in_unit = true;
  if (r.first != hull_first || r.last != hull_last)
    throw std::logic_error("half-space span emitter: box row " + std::to_string(j) +
                           ": a piece out of the walk's order");
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
