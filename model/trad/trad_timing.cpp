#include "trad/trad_timing.hpp"

namespace trirast {

TradWalkTiming::TradWalkTiming(const TradVertices& v) {
  const Vec2i* p = v.p;
  line_[0].start(p[0], p[2]);
  line_[1].start(p[0], p[1]);
  line_[2].start(p[1], p[2]);
  start_y_[0] = p[0].y;
  start_y_[1] = p[0].y;
  start_y_[2] = p[1].y;
  p0y_ = p[0].y;
  p2y_ = p[2].y;
}

uint64_t TradWalkTiming::steps_on_row(int e, int64_t y) const {
  RowRun run;
  if (!line_[e].row_run(y, run)) return 0;
  const uint64_t pixels = uint64_t(run.x_last - run.x_first + 1);
  return y == start_y_[e] ? pixels - 1 : pixels;
}

}  // namespace trirast
