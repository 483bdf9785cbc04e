// Every column of a per-triangle cycles row (docs/timing.md, "Outputs"), for tests that compare
// two engines' rows column by column and print a mismatch in full; and the run's statistics a
// unit's RTL reports as its SystemC model does.
#pragma once
#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

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

// The model's statistics the RTL must equal: every counter of the model's work (module busy and
// stall cycles, the datapath's work) but its simulation speed (sim_*) and the names in `except`
// (counters without an RTL counterpart). Returns the mismatches ("" when none) and sets
// `compared` to the number of counters compared.
inline std::string statistics_mismatch(const std::map<std::string, uint64_t>& model,
                                       const std::map<std::string, uint64_t>& rtl,
                                       const std::vector<std::string>& except, int& compared) {
  std::string bad;
  compared = 0;
  for (const auto& [key, v] : model) {
    if (key.rfind("sim_", 0) == 0 || std::find(except.begin(), except.end(), key) != except.end())
      continue;
    ++compared;
    const auto it = rtl.find(key);
    if (it == rtl.end())
      bad += " " + key + " (not reported)";
    else if (it->second != v)
      bad += " " + key + " (rtl " + std::to_string(it->second) + ", model " + std::to_string(v) + ")";
  }
  return bad;
}

}  // namespace trirast::test
