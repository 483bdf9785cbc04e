// The scanline golden traversal: the exact per-row span bounds of docs/coverage-rule.md ("The same
// rule as per-row span bounds"), stepped from row to row by quotient and remainder like the
// improved Bresenham unit's edge walkers. It never looks at a pixel: O(rows) per triangle.
//
// For row y with centre cy and K = B*cy + C + bias (u = one pixel, h = half a pixel):
//   A > 0 (left edge):   x_begin >= ceil((-K - h*A) / (u*A))
//   A < 0 (right edge):  x_end   <= floor((K + h*A) / (-u*A)) + 1
//   A == 0 (horizontal): the row is wholly in (K >= 0) or wholly out
// From one row to the next K grows by u*B, so each numerator moves by a constant.
#include "common/fixed_point.hpp"
#include "golden/golden.hpp"

namespace trirast {

namespace {

// floor(n / d) kept as quotient q and remainder r (n = q*d + r, 0 <= r < d) while n moves by a
// constant step s each row: q and r move by floor(s / d) and its remainder, plus a carry.
struct ImprovedEdgeWalker {
  int64_t q, r, d, step_q, step_r;
  void init(int64_t n, int64_t d_, int64_t s) {
    d = d_;
    q = floor_div(n, d);
    r = n - q * d;
    step_q = floor_div(s, d);
    step_r = s - step_q * d;
  }
  void next_row() {
    q += step_q;
    r += step_r;
    if (r >= d) {
      r -= d;
      ++q;
    }
  }
  int64_t floor() const { return q; }
  int64_t ceil() const { return q + (r != 0); }
};

}  // namespace

void traverse_scanline(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out) {
  if (t.box.empty()) return;
  const int64_t u = cfg.unit(), h = cfg.half();
  const int64_t cy0 = pixel_centre(t.box.y0, cfg);
  ImprovedEdgeWalker left[3], right[3];
  int n_left = 0, n_right = 0;
  int64_t flat_k[3];  // K of the horizontal edges, stepped by u*B
  int64_t flat_step[3];
  int n_flat = 0;
  for (int i = 0; i < 3; ++i) {
    const EdgeSetup& e = t.edge[i];
    const int64_t k = e.B * cy0 + e.C + e.bias;
    if (e.A > 0) {
      left[n_left++].init(-k - h * e.A, u * e.A, -u * e.B);
    } else if (e.A < 0) {
      right[n_right++].init(k + h * e.A, -u * e.A, u * e.B);
    } else {
      flat_k[n_flat] = k;
      flat_step[n_flat++] = u * e.B;
    }
  }
  for (int32_t y = t.box.y0; y <= t.box.y1; ++y) {
    int64_t begin = t.box.x0, end = int64_t(t.box.x1) + 1;
    for (int j = 0; j < n_left; ++j) {
      begin = std::max(begin, left[j].ceil());
      left[j].next_row();
    }
    for (int j = 0; j < n_right; ++j) {
      end = std::min(end, right[j].floor() + 1);
      right[j].next_row();
    }
    for (int j = 0; j < n_flat; ++j) {
      if (flat_k[j] < 0) end = begin;  // the row lies outside a horizontal edge
      flat_k[j] += flat_step[j];
    }
    if (begin < end) out.push_back(Span{t.index, y, int32_t(begin), int32_t(end)});
  }
}

}  // namespace trirast
