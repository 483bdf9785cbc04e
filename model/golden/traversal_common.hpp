// Pieces shared by the golden traversals (model/golden/traversal_*.cpp): the edge values of a
// triangle at any pixel centre of its box, the per-pixel inside test, and the row table the block
// traversals collect their pixels in before emitting spans in row order.
#pragma once
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "common/config.hpp"
#include "common/setup.hpp"
#include "common/span.hpp"

namespace trirast::golden_detail {

// The three edge functions with the bias folded in, as values at the box origin (the centre of
// pixel (box.x0, box.y0)) plus per-pixel steps: E_i(x, y) + bias_i = origin[i] + dx[i]*(x - x0)
// + dy[i]*(y - y0). A pixel is covered iff all three are >= 0.
struct EdgeValues {
  int64_t origin[3];
  int64_t dx[3];  // A * u: one pixel to the right
  int64_t dy[3];  // B * u: one pixel down
  int32_t x0, y0;

  EdgeValues(const TriangleSetup& t, const RasterConfig& cfg) : x0(t.box.x0), y0(t.box.y0) {
    const int64_t u = cfg.unit(), cx = pixel_centre(t.box.x0, cfg), cy = pixel_centre(t.box.y0, cfg);
    for (int i = 0; i < 3; ++i) {
      origin[i] = t.edge[i].eval(cx, cy) + t.edge[i].bias;
      dx[i] = t.edge[i].A * u;
      dy[i] = t.edge[i].B * u;
    }
  }
  int64_t at(int i, int32_t x, int32_t y) const {
    return origin[i] + dx[i] * (int64_t(x) - x0) + dy[i] * (int64_t(y) - y0);
  }
};

inline bool inside(const int64_t e[3]) { return (e[0] | e[1] | e[2]) >= 0; }

// Covered x extent of each row of a box, filled in any order, emitted in row order. A triangle's
// covered pixels on one row are one run, so the extent of what was found is the span.
class RowTable {
 public:
  void reset(int32_t y0, int32_t rows) {
    y0_ = y0;
    begin_.assign(size_t(rows), std::numeric_limits<int32_t>::max());
    end_.assign(size_t(rows), std::numeric_limits<int32_t>::min());
  }
  // Pixels [xb, xe) of row y are covered.
  void add(int32_t y, int32_t xb, int32_t xe) {
    const size_t r = size_t(y - y0_);
    begin_[r] = std::min(begin_[r], xb);
    end_[r] = std::max(end_[r], xe);
  }
  void emit(uint32_t tri, SpanList& out) const {
    for (size_t r = 0; r < begin_.size(); ++r)
      if (begin_[r] < end_[r]) out.push_back(Span{tri, int32_t(y0_ + r), begin_[r], end_[r]});
  }

 private:
  int32_t y0_ = 0;
  std::vector<int32_t> begin_, end_;
};

// One row table per thread, reused from triangle to triangle.
inline RowTable& scratch_rows() {
  thread_local RowTable rows;
  return rows;
}

}  // namespace trirast::golden_detail
