#include "common/span.hpp"

#include <algorithm>

namespace trirast {

void sort_spans(SpanList& spans) { std::sort(spans.begin(), spans.end()); }

int64_t count_pixels(const SpanList& spans) {
  int64_t total = 0;
  for (const Span& s : spans) total += s.pixels();
  return total;
}

}  // namespace trirast
