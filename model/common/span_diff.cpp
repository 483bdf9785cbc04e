#include "common/span_diff.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace trirast {

namespace {

using Interval = std::pair<int32_t, int32_t>;  // [begin, end)

// Merges the spans of one (tri, y) group, starting at index i, into disjoint sorted intervals.
size_t take_row(const SpanList& spans, size_t i, std::vector<Interval>& row) {
  row.clear();
  const uint32_t tri = spans[i].tri;
  const int32_t y = spans[i].y;
  for (; i < spans.size() && spans[i].tri == tri && spans[i].y == y; ++i) {
    if (spans[i].x_begin >= spans[i].x_end) continue;
    if (!row.empty() && spans[i].x_begin <= row.back().second)
      row.back().second = std::max(row.back().second, spans[i].x_end);
    else
      row.push_back({spans[i].x_begin, spans[i].x_end});
  }
  return i;
}

// Appends a \ b (both disjoint and sorted) as spans of (tri, y).
int64_t subtract(const std::vector<Interval>& a, const std::vector<Interval>& b, uint32_t tri,
                 int32_t y, SpanList& out) {
  int64_t pixels = 0;
  size_t k = 0;
  for (const Interval& iv : a) {
    int32_t cursor = iv.first;
    while (k < b.size() && b[k].second <= cursor) ++k;
    for (size_t m = k; m < b.size() && b[m].first < iv.second && cursor < iv.second; ++m) {
      if (b[m].first > cursor) {
        out.push_back(Span{tri, y, cursor, b[m].first});
        pixels += b[m].first - cursor;
      }
      cursor = std::max(cursor, b[m].second);
    }
    if (cursor < iv.second) {
      out.push_back(Span{tri, y, cursor, iv.second});
      pixels += iv.second - cursor;
    }
  }
  return pixels;
}

}  // namespace

SpanDiff diff_spans(const SpanList& reference, const SpanList& other) {
  SpanDiff d;
  d.identical_spans = reference == other;
  if (d.identical_spans) return d;
  std::vector<Interval> ra, rb;
  const std::vector<Interval> none;
  size_t i = 0, j = 0;
  while (i < reference.size() || j < other.size()) {
    // Pick the smaller (tri, y) key; rows present in only one list compare against nothing.
    bool take_ref = j >= other.size() ||
                    (i < reference.size() &&
                     std::make_pair(reference[i].tri, reference[i].y) <=
                         std::make_pair(other[j].tri, other[j].y));
    bool take_other = i >= reference.size() ||
                      (j < other.size() &&
                       std::make_pair(other[j].tri, other[j].y) <=
                           std::make_pair(reference[i].tri, reference[i].y));
    const Span& key = take_ref ? reference[i] : other[j];
    const uint32_t tri = key.tri;
    const int32_t y = key.y;
    if (take_ref) i = take_row(reference, i, ra); else ra.clear();
    if (take_other) j = take_row(other, j, rb); else rb.clear();
    d.missing_pixels += subtract(ra, rb, tri, y, d.missing);
    d.extra_pixels += subtract(rb, ra, tri, y, d.extra);
  }
  return d;
}

}  // namespace trirast
