// The one output type of every engine: a horizontal run of covered pixels of one triangle.
#pragma once
#include <cstdint>
#include <tuple>
#include <vector>

namespace trirast {

struct Span {
  uint32_t tri;     // triangle index in the scene (its order in the input, from 0)
  int32_t y;        // pixel row
  int32_t x_begin;  // first covered pixel
  int32_t x_end;    // one past the last covered pixel (exclusive)

  int64_t pixels() const { return int64_t(x_end) - x_begin; }
  friend bool operator==(const Span& a, const Span& b) {
    return a.tri == b.tri && a.y == b.y && a.x_begin == b.x_begin && a.x_end == b.x_end;
  }
  friend bool operator!=(const Span& a, const Span& b) { return !(a == b); }
  friend bool operator<(const Span& a, const Span& b) {
    return std::tie(a.tri, a.y, a.x_begin, a.x_end) < std::tie(b.tri, b.y, b.x_begin, b.x_end);
  }
};

using SpanList = std::vector<Span>;

// Sort into the interchange order: by triangle, then row, then x_begin.
void sort_spans(SpanList& spans);

// Total covered pixels of a span list.
int64_t count_pixels(const SpanList& spans);

}  // namespace trirast
