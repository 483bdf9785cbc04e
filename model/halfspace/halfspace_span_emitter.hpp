// The half-space unit, stage 4: the span emitter. It keeps one run [first, last] per row of the
// current band (U rows), widened by every stamp row and every accepted tile the walker reports;
// a row of a triangle is convex, so the pieces of a row join into one span. At the end of a band
// the rows with a run become spans, in row order (the timed views push them one per cycle while
// the walker goes on with the next band: docs/timing.md).
// As the RTL does, it widens a run without a compare: the walk's order says which piece is
// further out (units left to right or right to left, a unit's pieces of a row left to right).
// Left to right, the first piece sets first and every piece last; right to left, a piece of a new
// unit sets first, and last is the newest piece of the row's first unit. Two flags per row say
// which (a piece of the current unit; all pieces from it). A piece that falls outside that order
// would make the run differ from the hull of the pieces: merge() throws std::logic_error.
#pragma once
#include <cstdint>
#include <vector>

#include "common/span.hpp"
#include "halfspace/halfspace_setup.hpp"

namespace trirast {

class HalfspaceSpanEmitter {
 public:
  explicit HalfspaceSpanEmitter(const RasterConfig& cfg);
  // A band at box row j0, its units left to right or (backward) right to left.
  void begin_band(int64_t j0, bool backward);
  // The walker's next unit: its pieces follow.
  void begin_unit();
  // Box row j (in the band) covers columns first..last.
  void merge(int64_t j, int64_t first, int64_t last);
  // The band's spans in row order, appended to out; returns how many.
  size_t end_band(const HalfspaceSetupOut& s, SpanList& out);

 private:
  struct Run {
    bool any = false;
    bool in_unit = false;     // a piece of the current unit
    bool first_unit = false;  // every piece from the current unit
    int64_t first = 0, last = 0;
  };
  int U_;
  int64_t j0_ = 0;
  bool backward_ = false;
  std::vector<Run> rows_;
};

}  // namespace trirast
