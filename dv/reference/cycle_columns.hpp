// Every column of a per-triangle cycles row (docs/timing.md, "Outputs"), for tests that compare
// two engines' rows column by column and print a mismatch in full.
#pragma once
#include <cstdint>
#include <string>

#include "core/engine.hpp"

namespace trirast::test {

inline std::string cycles_row(const TriangleCycles& c) {
  std::string s;
  for (uint64_t v : {uint64_t(c.tri), c.accept_cycle, c.first_span_cycle, c.done_cycle, c.spans,
                     c.pixels, c.stall_cycles, c.setup_start_cycle, c.setup_done_cycle,
                     c.handoff_cycle, c.walk_start_cycle, c.walk_end_cycle, c.divider_iterations,
                     c.boundary_steps, c.box_width, c.box_height})
    s += (s.empty() ? "" : ",") + std::to_string(v);
  return s;
}

inline constexpr const char* kCyclesColumns =
    "tri,accept,first_span,done,spans,pixels,stalls,setup_start,setup_done,handoff,walk_start,"
    "walk_end,divider_iterations,boundary_steps,box_width,box_height";

// All sixteen columns equal.
inline bool same_cycles(const TriangleCycles& a, const TriangleCycles& b) {
  return cycles_row(a) == cycles_row(b);
}

}  // namespace trirast::test
