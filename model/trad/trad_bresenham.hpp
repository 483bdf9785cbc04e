// The traditional Bresenham triangle rasterizer: the baseline the improved unit is compared with
// (003_ef0fb899afde143a.txt), as the older GR3 software renderer did it (001_efbf726a8c96efcc.txt,
// sections 2.1 and 2.1.1). It deliberately does NOT follow docs/coverage-rule.md; its difference
// from the golden rasterizer is reported as error.
//
// Hardware stages, in order (one C++ class per stage, integer arithmetic only, int64 throughout):
//
//  1. TradVertexQuantizer  Each snapped vertex (frac_bits() units) becomes its integer pixel,
//                          floor(v / 2^F): the fraction is dropped, as GR3 stored "Eckpunkte als
//                          Ganzzahl". If the three integer pixels are collinear (integer area 0)
//                          the triangle is dropped: the lines make no usable step and nothing is
//                          drawn (figure 2.4: a one-pixel triangle is lost although its pixel
//                          centre is inside). Otherwise a three-comparator sorting network orders
//                          the vertices by (y, x): p0 top, p1 middle, p2 bottom.
//  2. BresenhamLine x 3    The edges p0->p2 (long), p0->p1 and p1->p2, each drawn downward as a
//                          classic Bresenham line: unit steps along the major axis (|dx| >= |dy|:
//                          x), the decision variable D = 2*dminor - dmajor; a step moves the minor
//                          axis when D > 0 (ties stay on the side of the start point). One hardware
//                          cycle per step: max(|dx|, |dy|) steps per edge, end points included.
//  3. TradSpanFiller       For every row from p0.y to p2.y, the leftmost and rightmost pixel any
//  edge
//                          puts on that row; the span is [leftmost, rightmost + 1), so edge pixels
//                          are drawn and the interior between them filled ("zwischen den dadurch
//                          entstehenden Begrenzungen alle Pixel eingefärbt"). Spans are clipped to
//                          the viewport [0, W) x [0, H) and leave in row order.
//
// Cost of the model. The hardware walks every pixel of every edge (that is what the step counter
// reports, also for off-screen parts). The model gets the same pixels without walking them: the
// line's state at any major index j has a closed form (BresenhamLine::seek), and so has the run of
// pixels an edge puts on one row (BresenhamLine::row_run). The filler therefore visits only the
// rows inside the viewport and does O(1) work per edge per row, whatever the coordinates (vertices
// up to
// +-2^15 pixels: a few thousand rows at most, never the 65536-pixel lines). tests/test_trad.cpp
// checks seek and row_run against the cycle-by-cycle step().
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "common/config.hpp"
#include "common/engine.hpp"
#include "common/setup.hpp"
#include "common/span.hpp"

namespace trirast {

// ---- stage 1: integer vertices, collinearity, y sort ----

struct TradVertices {
  Vec2i p[3];          // integer pixels sorted by (y, x): p[0] top, p[2] bottom
  bool empty = false;  // integer pixels collinear: the triangle draws nothing
};

class TradVertexQuantizer {
 public:
  explicit TradVertexQuantizer(const RasterConfig& cfg) : frac_bits_(cfg.frac_bits()) {}
  TradVertices run(const TriangleSetup& t) const;

 private:
  int frac_bits_;  // one pixel is 2^frac_bits_ units: the integer pixel is v >> frac_bits_
};

// ---- stage 2: one Bresenham line ----

// The extent of a line on one row: pixels x_first .. x_last (inclusive, x_first <= x_last).
struct RowRun {
  int64_t x_first;
  int64_t x_last;
};

class BresenhamLine {
 public:
  // Loads the line from pixel a to pixel b (the state for major index 0, i.e. pixel a).
  void start(Vec2i a, Vec2i b);

  // One hardware cycle: moves to the next pixel. Returns false (and does nothing) at the end.
  bool step();
  // Sets the state to major index j (0 <= j <= steps()) exactly as j calls of step() would.
  void seek(int64_t j);

  // The current pixel and decision variable.
  int64_t x() const { return x_; }
  int64_t y() const { return y_; }
  int64_t decision() const { return d_; }
  int64_t index() const { return j_; }

  // Major-axis steps of the whole line: max(|dx|, |dy|), the hardware's cycles for this edge.
  int64_t steps() const { return dmaj_; }
  bool x_major() const { return x_major_; }

  // The pixels the line puts on row y, in closed form (what stepping through the row gives).
  // Returns false when the line does not touch the row.
  bool row_run(int64_t y, RowRun& run) const;

 private:
  // Minor-axis offset (>= 0, in steps of the minor sign) at major index j: round(j*dmin/dmaj)
  // with ties toward the start point.
  int64_t minor_at(int64_t j) const;
  // Smallest major index whose minor offset is >= k (k >= 1, dmin > 0).
  int64_t first_index_of_minor(int64_t k) const;

  Vec2i a_{0, 0};
  int64_t sx_ = 1, sy_ = 1;      // step directions (+1 or -1)
  int64_t dmaj_ = 0, dmin_ = 0;  // |major delta|, |minor delta|
  bool x_major_ = true;          // |dx| >= |dy|
  int64_t x_ = 0, y_ = 0;        // current pixel
  int64_t j_ = 0;                // current major index, 0 .. dmaj_
  int64_t d_ = 0;                // decision variable for the step from j_ to j_ + 1
};

// ---- the triangle ----

// Work of one triangle: what a timing model counts cycles from.
struct TradTriangleResult {
  TradVertices verts;                  // stage 1 output
  uint64_t edge_steps[3] = {0, 0, 0};  // Bresenham steps of p0->p2, p0->p1, p1->p2 (0 if empty)
  uint64_t rows_visited = 0;           // rows from p0.y to p2.y inside the viewport
  uint64_t spans = 0;                  // spans that left (non-empty after clipping)
  uint64_t pixels = 0;                 // pixels in them

  uint64_t steps() const { return edge_steps[0] + edge_steps[1] + edge_steps[2]; }
  // The counters of o added to these (verts stays: a sum of triangles has no vertices).
  TradTriangleResult& operator+=(const TradTriangleResult& o) {
    for (int e = 0; e < 3; ++e) edge_steps[e] += o.edge_steps[e];
    rows_visited += o.rows_visited;
    spans += o.spans;
    pixels += o.pixels;
    return *this;
  }
};

// Stage 3 with stages 1 and 2 in front: one set-up triangle in, its spans out in row order.
class TradSpanFiller {
 public:
  explicit TradSpanFiller(const RasterConfig& cfg) : cfg_(cfg), quantizer_(cfg) {}
  TradTriangleResult run_triangle(const TriangleSetup& t, SpanList& out);
  // Stages 2 and 3 on the vertices stage 1 gave for t.
  TradTriangleResult fill(const TriangleSetup& t, const TradVertices& v, SpanList& out);

  // fill() a row at a time, for a caller that visits every row p0.y .. p2.y (the timed walk
  // stage): begin() starts the three lines of non-empty vertices v (r.verts, r.edge_steps);
  // row() gives the lines' runs on row y (on[e] false: line e does not touch it) and, for a row
  // inside the viewport, counts it in r and appends its span, if any, to out.
  void begin(const TradVertices& v, TradTriangleResult& r);
  void row(const TriangleSetup& t, int64_t y, RowRun run[3], bool on[3], TradTriangleResult& r,
           SpanList& out) const;

 private:
  RasterConfig cfg_;
  TradVertexQuantizer quantizer_;
  BresenhamLine line_[3];
};

// Adds one triangle's work into an engine's work map: "trad_bresenham_steps", "rows_visited",
// "spans", "pixels", "trad_collinear" (triangles dropped by stage 1).
void add_trad_work(const TradTriangleResult& r, std::map<std::string, uint64_t>& work);

// The traditional rasterizer as an untimed engine (not exact); app/engines.cpp registers its timed
// form, make_trad_sc_engine(), as "trad-sc".
std::unique_ptr<Engine> make_trad_datapath_engine();

}  // namespace trirast
