// Block-level golden traversals on 8x8 pixel blocks of the bounding box: block (000 5.2), adaptive
// (000 5.3), bisector (000 5.5) and sat-block (004). A block is the rectangle spanned by the
// centres of its pixels (clipped to the box); since each edge function is linear, its extreme
// values over a block are at the corners, which gives exact tests:
//   reject: some edge is < 0 at all four corners (no pixel of the block is covered);
//   accept: every edge is >= 0 at all four corners (every pixel of the block is covered).
// Along a block row the blocks that an edge does not reject form a half-line (its largest corner
// value grows with x when A > 0, shrinks when A < 0, is constant when A == 0), so the blocks no
// edge rejects form one run: a row can be left at its first rejected block after a kept one.
#include "common/fixed_point.hpp"
#include "golden/golden.hpp"
#include "golden/traversal_common.hpp"

namespace trirast {

using golden_detail::EdgeValues;
using golden_detail::inside;
using golden_detail::RowTable;

namespace {

constexpr int32_t kQ = kGoldenBlock;

enum class BlockClass { Rejected, Accepted, Partial };

// One block row of a triangle's box: rows [y, ye], blocks [bx, bx + 7] clipped to the box.
class BlockRow {
 public:
  BlockRow(const EdgeValues& ev, const PixelBox& box, int32_t y)
      : ev_(ev), box_(box), y_(y), ye_(std::min(y + kQ - 1, box.y1)) {}

  int32_t columns() const { return int32_t((int64_t(box_.x1) - box_.x0) / kQ + 1); }
  int32_t block_x(int32_t col) const { return box_.x0 + col * kQ; }

  // Classifies block `col` by its corners. For a rejected block, `dir` says where the unrejected
  // blocks of this row lie: +1 right, -1 left, 0 nowhere (rejecting edges disagree or are flat).
  BlockClass classify(int32_t col, int* dir = nullptr) const {
    const int32_t bx = block_x(col), bxe = std::min(bx + kQ - 1, box_.x1);
    bool all_in = true;
    int d = 0;
    bool rejected = false;
    for (int i = 0; i < 3; ++i) {
      const int64_t c00 = ev_.at(i, bx, y_);
      const int64_t c10 = c00 + ev_.dx[i] * (bxe - bx);
      const int64_t c01 = c00 + ev_.dy[i] * (ye_ - y_);
      const int64_t c11 = c10 + ev_.dy[i] * (ye_ - y_);
      if ((c00 & c10 & c01 & c11) < 0) {  // all four negative
        const int want = ev_.dx[i] > 0 ? 1 : ev_.dx[i] < 0 ? -1 : 2;
        d = (rejected && d != want) || want == 2 ? 2 : want;
        rejected = true;
      }
      if ((c00 | c10 | c01 | c11) < 0) all_in = false;
    }
    if (rejected) {
      if (dir) *dir = d == 2 ? 0 : d;
      return BlockClass::Rejected;
    }
    return all_in ? BlockClass::Accepted : BlockClass::Partial;
  }

  // Records the covered pixels of a kept block in the row table.
  void fill(int32_t col, BlockClass cls, RowTable& rows) const {
    const int32_t bx = block_x(col), bxe = std::min(bx + kQ - 1, box_.x1);
    if (cls == BlockClass::Accepted) {
      for (int32_t y = y_; y <= ye_; ++y) rows.add(y, bx, bxe + 1);
      return;
    }
    scan_block(bx, bxe, rows);
  }

  // Per-pixel scan of one block by incremental edge functions, leaving a row at its run's end.
  void scan_block(int32_t bx, int32_t bxe, RowTable& rows) const {
    int64_t row[3];
    for (int i = 0; i < 3; ++i) row[i] = ev_.at(i, bx, y_);
    for (int32_t y = y_; y <= ye_; ++y) {
      int64_t e[3] = {row[0], row[1], row[2]};
      int32_t first = -1, x = bx;
      for (; x <= bxe; ++x) {
        const bool in = inside(e);
        if (in && first < 0) first = x;
        if (!in && first >= 0) break;
        for (int i = 0; i < 3; ++i) e[i] += ev_.dx[i];
      }
      if (first >= 0) rows.add(y, first, x);
      for (int i = 0; i < 3; ++i) row[i] += ev_.dy[i];
    }
  }

  int32_t y() const { return y_; }

 private:
  const EdgeValues& ev_;
  const PixelBox& box_;
  int32_t y_, ye_;
};

// Walks a block row from block `start` outwards: finds a kept block (moving the way the rejecting
// edges point), then fills kept blocks to the right and to the left until each side is rejected.
// Returns false when the row has no kept block; otherwise [left, right] are the kept columns.
bool walk_block_row(const BlockRow& br, int32_t start, RowTable& rows, int32_t& left,
                    int32_t& right) {
  const int32_t n = br.columns();
  int32_t col = std::clamp(start, 0, n - 1);
  int dir = 0;
  BlockClass cls = br.classify(col, &dir);
  while (cls == BlockClass::Rejected) {
    const int want = dir;
    if (want == 0) return false;
    col += want;
    if (col < 0 || col >= n) return false;
    cls = br.classify(col, &dir);
    if (cls == BlockClass::Rejected && dir != want) return false;
  }
  br.fill(col, cls, rows);
  right = col;
  for (int32_t c = col + 1; c < n; ++c) {
    const BlockClass k = br.classify(c);
    if (k == BlockClass::Rejected) break;
    br.fill(c, k, rows);
    right = c;
  }
  left = col;
  for (int32_t c = col - 1; c >= 0; --c) {
    const BlockClass k = br.classify(c);
    if (k == BlockClass::Rejected) break;
    br.fill(c, k, rows);
    left = c;
  }
  return true;
}

}  // namespace

// 000 5.2: block rows top to bottom, blocks left to right; skip rejected blocks, fill accepted
// ones whole, scan partial ones pixel by pixel; leave the row at the first rejected block after a
// kept one.
void traverse_block(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out) {
  if (t.box.empty()) return;
  const EdgeValues ev(t, cfg);
  RowTable& rows = golden_detail::scratch_rows();
  rows.reset(t.box.y0, int32_t(t.box.height()));
  for (int32_t y = t.box.y0; y <= t.box.y1; y += kQ) {
    const BlockRow br(ev, t.box, y);
    bool kept = false;
    for (int32_t c = 0; c < br.columns(); ++c) {
      const BlockClass k = br.classify(c);
      if (k == BlockClass::Rejected) {
        if (kept) break;
        continue;
      }
      kept = true;
      br.fill(c, k, rows);
    }
  }
  rows.emit(t.index, out);
}

// 000 5.3: orient = box width / box height. Triangles of orient 0.4..1.6 that reach one block
// along x or y go to the block traversal, all others to the incremental one.
void traverse_adaptive(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out) {
  if (t.box.empty()) return;
  const int64_t w = t.box.width(), h = t.box.height();
  const bool squarish = 5 * w >= 2 * h && 5 * w <= 8 * h;  // 0.4 <= w/h <= 1.6
  if (squarish && (w >= kQ || h >= kQ)) traverse_block(t, cfg, out);
  else traverse_incremental(t, cfg, out);
}

// 000 5.5: the upper half of the block rows top-down, starting at the topmost vertex's block, the
// lower half bottom-up, starting at the bottommost vertex's block; every following block row
// starts at the middle of the previous row's kept blocks and walks outwards both ways.
void traverse_bisector(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out) {
  if (t.box.empty()) return;
  const EdgeValues ev(t, cfg);
  RowTable& rows = golden_detail::scratch_rows();
  rows.reset(t.box.y0, int32_t(t.box.height()));
  const int32_t block_rows = int32_t((t.box.height() - 1) / kQ + 1);
  const int32_t half = (block_rows - 1) / 2;
  int top = 0, bottom = 0;
  for (int i = 1; i < 3; ++i) {
    if (t.v[i].y < t.v[top].y) top = i;
    if (t.v[i].y > t.v[bottom].y) bottom = i;
  }
  auto vertex_column = [&](int i) {
    return int32_t((floor_div(t.v[i].x, cfg.unit()) - t.box.x0) / kQ);
  };
  auto walk = [&](int32_t from, int32_t to, int32_t step, int32_t start) {
    for (int32_t k = from; k != to; k += step) {
      const BlockRow br(ev, t.box, t.box.y0 + k * kQ);
      int32_t left, right;
      if (walk_block_row(br, start, rows, left, right)) start = left + ((right - left) >> 1);
    }
  };
  walk(0, half + 1, 1, vertex_column(top));
  walk(block_rows - 1, half, -1, vertex_column(bottom));
  rows.emit(t.index, out);
}

// 004: first a mask of the blocks that overlap the triangle by the separating-axis test (the
// block's own axes never separate it from the triangle, since the box holds only centres within
// the vertex extent; on each edge's normal one corner, the one furthest along the normal, decides),
// then a pixel traversal inside every overlapping block.
void traverse_sat_block(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out) {
  if (t.box.empty()) return;
  const EdgeValues ev(t, cfg);
  RowTable& rows = golden_detail::scratch_rows();
  rows.reset(t.box.y0, int32_t(t.box.height()));
  const int32_t cols = int32_t((t.box.width() - 1) / kQ + 1);
  const int32_t brows = int32_t((t.box.height() - 1) / kQ + 1);
  thread_local std::vector<uint8_t> mask;
  mask.assign(size_t(cols) * size_t(brows), 0);
  // Pass 1: the block mask.
  for (int32_t r = 0; r < brows; ++r) {
    const int32_t y = t.box.y0 + r * kQ, ye = std::min(y + kQ - 1, t.box.y1);
    for (int32_t c = 0; c < cols; ++c) {
      const int32_t x = t.box.x0 + c * kQ, xe = std::min(x + kQ - 1, t.box.x1);
      bool overlap = true;
      for (int i = 0; i < 3 && overlap; ++i) {
        const int32_t px = ev.dx[i] > 0 ? xe : x;  // corner furthest along the edge's normal
        const int32_t py = ev.dy[i] > 0 ? ye : y;
        overlap = ev.at(i, px, py) >= 0;
      }
      mask[size_t(r) * size_t(cols) + size_t(c)] = overlap;
    }
  }
  // Pass 2: traversal inside the overlapping blocks.
  for (int32_t r = 0; r < brows; ++r) {
    const BlockRow br(ev, t.box, t.box.y0 + r * kQ);
    for (int32_t c = 0; c < cols; ++c)
      if (mask[size_t(r) * size_t(cols) + size_t(c)]) {
        const int32_t x = br.block_x(c);
        br.scan_block(x, std::min(x + kQ - 1, t.box.x1), rows);
      }
  }
  rows.emit(t.index, out);
}

}  // namespace trirast
