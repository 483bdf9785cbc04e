// Per-triangle cycles of a timed engine as CSV (docs/timing.md, "Outputs"):
// tri,accept_cycle,first_span_cycle,done_cycle,spans,pixels,stall_cycles, then the stage
// breakdown setup_start_cycle,setup_done_cycle,handoff_cycle,walk_start_cycle,walk_end_cycle,
// divider_iterations,boundary_steps,box_width,box_height
#pragma once
#include <string>
#include <vector>

#include "common/engine.hpp"

namespace trirast {

void write_cycles_file(const std::vector<TriangleCycles>& cycles, const std::string& path,
                       const std::string& option);

// Reads a cycles CSV back; throws std::runtime_error("PATH:LINE: ...") when malformed.
std::vector<TriangleCycles> read_cycles_file(const std::string& path);

}  // namespace trirast
