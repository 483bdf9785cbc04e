// Pixel-exact comparison of two span lists (the same triangle's pixels against each other).
#pragma once
#include <cstdint>

#include "common/span.hpp"

namespace trirast {

struct SpanDiff {
  SpanList missing;  // pixels the reference covers and the other list does not
  SpanList extra;    // pixels the other list covers and the reference does not
  int64_t missing_pixels = 0;
  int64_t extra_pixels = 0;
  bool identical_spans = true;  // the sorted span lists are equal element for element
  bool exact() const { return missing_pixels == 0 && extra_pixels == 0; }
};

// Both lists must be sorted with sort_spans(). Spans of one triangle on one row may overlap or
// touch (a baseline engine may emit such); pixels are compared as sets per (triangle, row).
SpanDiff diff_spans(const SpanList& reference, const SpanList& other);

}  // namespace trirast
