// The traditional Bresenham triangle rasterizer, stage by stage (design: trad_bresenham.hpp).
#include "trad/trad_bresenham.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "common/fixed_point.hpp"

namespace trirast {

// ---- stage 1 ----

namespace {

// (y, x) order of two integer pixels: the comparator of the sorting network.
bool above(const Vec2i& a, const Vec2i& b) { return a.y < b.y || (a.y == b.y && a.x < b.x); }

void compare_swap(Vec2i& a, Vec2i& b) {
  if (above(b, a)) std::swap(a, b);
}

}  // namespace

TradVertices TradVertexQuantizer::run(const TriangleSetup& t) const {
  TradVertices out;
  // Drop the fraction: the integer pixel that contains the vertex (an arithmetic shift is the
  // floor).
  for (int i = 0; i < 3; ++i) out.p[i] = Vec2i{t.v[i].x >> frac_bits_, t.v[i].y >> frac_bits_};
  // Integer area 0: the three pixels lie on one line (or coincide), nothing is drawn (fig. 2.4).
  const int64_t area = (out.p[1].x - out.p[0].x) * (out.p[2].y - out.p[0].y) -
                       (out.p[1].y - out.p[0].y) * (out.p[2].x - out.p[0].x);
  out.empty = area == 0;
  // Three-comparator sorting network: top vertex first.
  compare_swap(out.p[0], out.p[1]);
  compare_swap(out.p[1], out.p[2]);
  compare_swap(out.p[0], out.p[1]);
  return out;
}

// ---- stage 2 ----

void BresenhamLine::start(Vec2i a, Vec2i b) {
  a_ = a;
  const int64_t dx = b.x - a.x;
  const int64_t dy = b.y - a.y;
  sx_ = dx < 0 ? -1 : 1;
  sy_ = dy < 0 ? -1 : 1;
  const int64_t adx = dx < 0 ? -dx : dx;
  const int64_t ady = dy < 0 ? -dy : dy;
  x_major_ = adx >= ady;
  dmaj_ = x_major_ ? adx : ady;
  dmin_ = x_major_ ? ady : adx;
  x_ = a.x;
  y_ = a.y;
  j_ = 0;
  d_ = 2 * dmin_ - dmaj_;  // classic initial decision variable
}

bool BresenhamLine::step() {
  if (j_ >= dmaj_) return false;
  // The minor axis moves when the exact line has passed the midpoint between the two candidates.
  if (d_ > 0) {
    if (x_major_)
      y_ += sy_;
    else
      x_ += sx_;
    d_ -= 2 * dmaj_;
  }
  d_ += 2 * dmin_;
  if (x_major_)
    x_ += sx_;
  else
    y_ += sy_;
  ++j_;
  return true;
}

int64_t BresenhamLine::minor_at(int64_t j) const {
  if (dmaj_ == 0) return 0;
  // k_j = ceil((2*j*dmin - dmaj) / (2*dmaj)): the step rule above, summed (D > 0 means
  // 2*dmin*j - dmaj > 2*dmaj*k).
  return floor_div(2 * j * dmin_ + dmaj_ - 1, 2 * dmaj_);
}

int64_t BresenhamLine::first_index_of_minor(int64_t k) const {
  // minor_at(j) >= k  <=>  2*j*dmin >= (2k - 1)*dmaj + 1.
  return ceil_div((2 * k - 1) * dmaj_ + 1, 2 * dmin_);
}

void BresenhamLine::seek(int64_t j) {
  j = std::clamp<int64_t>(j, 0, dmaj_);
  const int64_t k = minor_at(j);
  j_ = j;
  x_ = a_.x + sx_ * (x_major_ ? j : k);
  y_ = a_.y + sy_ * (x_major_ ? k : j);
  // D before the step from j: 2*dmin*(j+1) - dmaj - 2*dmaj*k (the initial value plus j updates).
  d_ = 2 * dmin_ * (j + 1) - dmaj_ - 2 * dmaj_ * k;
}

bool BresenhamLine::row_run(int64_t y, RowRun& run) const {
  const int64_t off = (y - a_.y) * sy_;  // rows from the start point, in the line's y direction
  if (!x_major_) {
    // y-major: one pixel per row, at major index off.
    if (off < 0 || off > dmaj_) return false;
    run.x_first = run.x_last = a_.x + sx_ * minor_at(off);
    return true;
  }
  // x-major: the row is minor offset off; its pixels are the major indices whose minor is off.
  if (off < 0 || off > dmin_) return false;
  const int64_t j_lo = off == 0 ? 0 : first_index_of_minor(off);
  const int64_t j_hi = off == dmin_ ? dmaj_ : first_index_of_minor(off + 1) - 1;
  const int64_t x_lo = a_.x + sx_ * j_lo;
  const int64_t x_hi = a_.x + sx_ * j_hi;
  run.x_first = std::min(x_lo, x_hi);
  run.x_last = std::max(x_lo, x_hi);
  return true;
}

// ---- stage 3 ----

TradTriangleResult TradSpanFiller::run_triangle(const TriangleSetup& t, SpanList& out) {
  return fill(t, quantizer_.run(t), out);
}

TradTriangleResult TradSpanFiller::fill(const TriangleSetup& t, const TradVertices& v, SpanList& out) {
  TradTriangleResult r;
  if (v.empty) {
    r.verts = v;
    return r;
  }
  begin(v, r);  // sets r.verts
  // Rows of the triangle inside the viewport only: the rows above and below cost nothing here.
  const int64_t y_first = std::max<int64_t>(v.p[0].y, 0);
  const int64_t y_last = std::min<int64_t>(v.p[2].y, int64_t(cfg_.height) - 1);
  RowRun run[3];
  bool on[3];
  for (int64_t y = y_first; y <= y_last; ++y) row(t, y, run, on, r, out);
  return r;
}

void TradSpanFiller::begin(const TradVertices& v, TradTriangleResult& r) {
  r.verts = v;
  const Vec2i* p = v.p;
  // The long edge and the two short ones, each drawn downward.
  line_[0].start(p[0], p[2]);
  line_[1].start(p[0], p[1]);
  line_[2].start(p[1], p[2]);
  for (int e = 0; e < 3; ++e) r.edge_steps[e] = uint64_t(line_[e].steps());
}

void TradSpanFiller::row(const TriangleSetup& t, int64_t y, RowRun run[3], bool on[3],
                         TradTriangleResult& r, SpanList& out) const {
  int64_t left = std::numeric_limits<int64_t>::max();
  int64_t right = std::numeric_limits<int64_t>::min();
  for (int e = 0; e < 3; ++e) {
    on[e] = line_[e].row_run(y, run[e]);
    if (!on[e]) continue;
    left = std::min(left, run[e].x_first);
    right = std::max(right, run[e].x_last);
  }
  if (y < 0 || y >= int64_t(cfg_.height)) return;  // outside the viewport: no span, not counted
  ++r.rows_visited;
  if (left > right) return;  // no edge on the row (cannot happen: the long edge spans all)
  // Edge pixels included, the interior between them filled, clipped to the viewport.
  const int64_t begin = std::max<int64_t>(left, 0);
  const int64_t end = std::min<int64_t>(right + 1, cfg_.width);
  if (begin >= end) return;
  out.push_back(Span{t.index, int32_t(y), int32_t(begin), int32_t(end)});
  ++r.spans;
  r.pixels += uint64_t(end - begin);
}

void add_trad_work(const TradTriangleResult& r, std::map<std::string, uint64_t>& work) {
  work["trad_bresenham_steps"] += r.steps();
  work["rows_visited"] += r.rows_visited;
  work["spans"] += r.spans;
  work["pixels"] += r.pixels;
  work["trad_collinear"] += r.verts.empty ? 1 : 0;
}

std::unique_ptr<Engine> make_trad_datapath_engine() {
  return make_datapath_engine<TradSpanFiller>(add_trad_work);
}

}  // namespace trirast
