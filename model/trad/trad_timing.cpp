#include "trad/trad_timing.hpp"

namespace trirast {

TradWalkTiming::TradWalkTiming(const TradVertices& v) : v_(v) {
  const Vec2i* p = v.p;
  line_[0].start(p[0], p[2]);
  line_[1].start(p[0], p[1]);
  line_[2].start(p[1], p[2]);
  p0y_ = p[0].y;
  p2y_ = p[2].y;
}

uint64_t TradWalkTiming::steps_on_row(int e, int64_t y) const {
  RowRun run;
  const bool on = line_[e].row_run(y, run);
  return steps_of_run(v_, e, y, on, run);
}

uint64_t TradWalkTiming::steps_of_run(const TradVertices& v, int e, int64_t y, bool on,
                                      const RowRun& run) {
  if (!on) return 0;
  const uint64_t pixels = uint64_t(run.x_last - run.x_first + 1);
  const int64_t start_y = e == 2 ? v.p[1].y : v.p[0].y;  // line e's first row
  return y == start_y ? pixels - 1 : pixels;
}

}  // namespace trirast
