// Finding why a triangle is slow: the timed engines' per-triangle cycles joined side
// by side, the slowest triangles named with their stage breakdown and what each waited for, a
// window of triangles exported as a .tri file, and the options of raster and compare that ask
// for them (docs/timing.md, "Outputs", defines every column used here).
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "cli/args.hpp"
#include "common/engine.hpp"
#include "common/setup.hpp"
#include "units.hpp"

namespace trirast {

// One timed engine's per-triangle cycles (scene order, as every engine reports them).
struct TimedCycles {
  std::string engine;
  const std::vector<TriangleCycles>* cycles;
};

// The unit whose cycle contract an engine follows: its unit's name for the engines of a unit's
// timed pair (improved-sc and improved-rtl: "improved"), the engine's own name otherwise.
// Engines of one unit must report identical rows.
std::string timing_unit(const std::string& engine);

// Cycles from accept to done.
inline uint64_t latency(const TriangleCycles& c) { return c.done_cycle - c.accept_cycle; }

// Positions of the n triangles with the most cycles from accept to done (ties: earlier first).
std::vector<size_t> slowest_triangles(const std::vector<TriangleCycles>& cycles, size_t n);

// One line on the triangle at position pos: its cycles, what it waited for (largest wait first)
// and the stage breakdown, in the words of the engine's unit (units.hpp, CycleWords), e.g.
// "waited 53 cycles in StHold: walk stage busy with triangle 1285 until cycle 23218".
// sink_stall is the run's --sink-stall (a pattern, or queue:RATE:CAPACITY).
std::string explain_triangle(const std::vector<TriangleCycles>& cycles, size_t pos,
                             const std::string& sink_stall, const CycleWords& words);

// The timed engines' rows side by side: tri, then every column but tri of each engine prefixed
// "ENGINE.", then `mismatch`: the engines whose row differs from the first engine of their unit
// ("rtl!=model"), empty when they agree. Rows are joined by position; every engine must report
// the same triangles.
std::string joined_cycles_csv(const std::vector<TimedCycles>& runs);

// Triangles on which an engine's row differs from the first engine of its unit; `first` gets a
// line naming the first such triangle and column.
size_t count_cycle_mismatches(const std::vector<TimedCycles>& runs, std::string& first);

// compare's part: writes --cycles (the joined CSV) when cycles_path is set, says whether engines
// of one unit agree on every column, and explains the --slowest and --explain triangles of each
// timed engine. Throws UsageError when one of these is asked for and no engine is timed.
struct DiagOptions;
void print_timed_cycles(const std::vector<std::pair<std::string, std::vector<TriangleCycles>>>& timed,
                        const DiagOptions& diag, const std::string& cycles_path,
                        const std::string& sink_stall);

// ---- options shared by raster and compare ----

struct DiagOptions {
  bool export_tris = false;
  int64_t export_first = 0, export_last = 0;  // scene indices, inclusive
  std::string export_path;
  std::string heatmap_metric;  // "", "cycles", "stalls" or "setup"
  std::string heatmap_path;
  size_t slowest = 0;          // compare only
  bool explain = false;        // compare only
  int64_t explain_first = 0, explain_last = 0;
};

// Appends --export-tris and --heatmap (and for compare --cycles, --slowest, --explain).
void add_diag_options(std::vector<OptionSpec>& specs, bool compare);
// Reads them; UsageError naming the option for a malformed value or an unwritable file.
DiagOptions diag_options_from(const Args& a, bool compare);

// Writes the set-up triangles whose scene index is in [first, last] as a .tri file of their
// snapped vertices in pixels (in the input's winding), so that loading it with the same
// --subpixel-bits sets up the same triangles exactly. Returns how many it wrote.
size_t export_tri_window(const SetupResult& setup, const RasterConfig& cfg, int64_t first,
                         int64_t last, const std::string& path, const std::string& option,
                         const std::string& scene_name);

}  // namespace trirast
