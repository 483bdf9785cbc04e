// The half-space unit, stage 4: the span emitter. It keeps one run [first, last] per row of the
// current band (U rows), widened by every stamp row and every accepted tile the walker reports;
// a row of a triangle is convex, so the pieces of a row join into one span. At the end of a band
// the rows with a run become spans, in row order (the timed views push them one per cycle while
// the walker goes on with the next band: docs/timing.md).
#pragma once
#include <cstdint>
#include <vector>

#include "common/span.hpp"
#include "halfspace/halfspace_setup.hpp"

namespace trirast {

class HalfspaceSpanEmitter {
 public:
  explicit HalfspaceSpanEmitter(const RasterConfig& cfg);
  void begin_band(int64_t j0);
  // Box row j (in the band) covers columns first..last.
  void merge(int64_t j, int64_t first, int64_t last);
  // The band's spans in row order, appended to out; returns how many.
  size_t end_band(const HalfspaceSetupOut& s, SpanList& out);

 private:
  struct Run {
    bool any = false;
    int64_t first = 0, last = 0;
  };
  int U_;
  int64_t j0_ = 0;
  std::vector<Run> rows_;
};

}  // namespace trirast
