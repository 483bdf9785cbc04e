// Every column of a per-triangle cycles row (docs/timing.md, "Outputs"), for tests that compare
// two engines' rows column by column and print a mismatch in full; and the run's statistics a
// unit's RTL reports as its SystemC model does.
#pragma once
#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "common/engine.hpp"

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

// Two runs' per-triangle rows compared position by position: the number of triangles whose rows
// differ, and the first three of them in full (`what`: the case, `a` and `b`: the engines'
// names) in `report`.
inline size_t cycle_rows_mismatch(const std::vector<TriangleCycles>& a, const char* a_name,
                                  const std::vector<TriangleCycles>& b, const char* b_name,
                                  const std::string& what, std::string& report) {
  size_t mismatches = 0;
  for (size_t p = 0; p < std::min(a.size(), b.size()); ++p)
    if (!same_cycles(a[p], b[p]) && mismatches++ < 3)
      report += what + ": triangle " + std::to_string(a[p].tri) + " (position " +
                std::to_string(p) + ", " + kCyclesColumns + "): " + a_name + " (" +
                cycles_row(a[p]) + ") " + b_name + " (" + cycles_row(b[p]) + ")\n";
  return mismatches;
}

// The first difference of two sorted span lists ("" when they are equal), naming both sides.
inline std::string first_span_difference(const SpanList& a, const char* a_name, const SpanList& b,
                                         const char* b_name) {
  auto show = [](const Span& s) {
    return "(tri " + std::to_string(s.tri) + " y " + std::to_string(s.y) + " [" +
           std::to_string(s.x_begin) + ", " + std::to_string(s.x_end) + "))";
  };
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    if (!(a[i] == b[i]))
      return "span " + std::to_string(i) + ": " + a_name + " " + show(a[i]) + ", " + b_name + " " +
             show(b[i]);
  if (a.size() != b.size())
    return std::string(a_name) + " " + std::to_string(a.size()) + " spans, " + b_name + " " +
           std::to_string(b.size());
  return "";
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
