// Per-row cycle costs of the traditional-Bresenham unit's walk stage (docs/timing.md, "The
// traditional unit"): the long-edge walker (p0->p2) and the short-side walker (p0->p1, then
// p1->p2) step one pixel per cycle each, in parallel; a row takes as many cycles as the busier
// walker has steps landing on it, at least one. Built on BresenhamLine::row_run, so the step
// positions are the datapath's own.
#pragma once
#include <cstdint>

#include "trad/trad_bresenham.hpp"

namespace trirast {

class TradWalkTiming {
 public:
  // The three lines of a non-collinear triangle's sorted integer vertices, drawn downward as the
  // datapath draws them: 0 = p0->p2 (long), 1 = p0->p1, 2 = p1->p2.
  explicit TradWalkTiming(const TradVertices& v);

  int64_t first_row() const { return p0y_; }  // p0.y
  int64_t last_row() const { return p2y_; }   // p2.y

  // Bresenham steps of line e that land on row y: its pixels on the row, minus its start pixel
  // on its first row (the start is loaded, not stepped to). Summed over all rows: steps().
  uint64_t steps_on_row(int e, int64_t y) const;
  // The same from line e's run on row y as row_run gives it (on: the line touches the row), for
  // a caller that has the runs (TradSpanFiller::row); v are the triangle's sorted vertices.
  static uint64_t steps_of_run(const TradVertices& v, int e, int64_t y, bool on, const RowRun& run);
  // Cycles the walk stage spends on row y: max(1, long steps, short steps) with
  // short steps = steps of p0->p1 + steps of p1->p2 on the row.
  uint64_t row_cycles(int64_t y) const {
    const uint64_t l = steps_on_row(0, y);
    const uint64_t s = steps_on_row(1, y) + steps_on_row(2, y);
    const uint64_t m = l > s ? l : s;
    return m > 0 ? m : 1;
  }
  const BresenhamLine& line(int e) const { return line_[e]; }

 private:
  TradVertices v_;
  BresenhamLine line_[3];
  int64_t p0y_, p2y_;
};

}  // namespace trirast
