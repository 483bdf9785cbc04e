// Functional coverage of the RTL (docs/coverage.md): the cover points of rtl/ (`COVER in
// rtl/common/trirast_assert.svh) count, in every Verilated build made with TRIRAST_RTL_COVERAGE
// (cmake/trirast_rtl_builds.cmake: --coverage-user), the rising edges at which their property
// held. At the end of each run the cycle loop (cycle_loop.hpp) reads the model's coverage
// database and adds its counts here, per engine, keyed by the point's name inside the unit
// (its hierarchy below the unit top, e.g. "u_setup.g_edge[0].u_lane.LaneStepUp_C"). A run of
// `trirast raster` or the whole of `trirast fuzz` then writes the report (--coverage FILE).
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

class VerilatedContext;

namespace trirast::rtl {

// Whether the Verilated builds have their cover points (TRIRAST_RTL_COVERAGE=ON).
bool rtl_coverage_built();

// Adds the counts of the model(s) in `ctx` (one run) to `engine`'s; every point of the run's
// build is listed, a point not hit with 0. Thread-safe.
void collect_rtl_coverage(const std::string& engine, VerilatedContext& ctx);

// The counts collected so far: engine -> point -> count (merged over the runs; a point is the
// union over the builds that ran). Thread-safe.
std::map<std::string, std::map<std::string, uint64_t>> rtl_coverage_counts();
void reset_rtl_coverage();

// The counts of one coverage database as Verilator writes it (coverage.dat: one line
// "C '<key>\002<value>\001...' <count>" per point): point name -> count, for the user points
// (page v_user/...). The name is the point's hierarchical name ('h') below the unit top
// ("...u_dut."), ending in its label ('o'). Throws
// std::runtime_error on a line it cannot read, naming `what` and the line.
std::map<std::string, uint64_t> parse_coverage_dat(const std::string& text, const std::string& what);

// The report (Markdown): a first line naming `title`, "coverage: H of T cover points hit", a
// table of every point of `engines` (those with counts; in the order given) with its count,
// and the list of the points never hit. `hit`, `total` receive H and T.
std::string rtl_coverage_report(const std::vector<std::string>& engines, const std::string& title,
                                uint64_t& hit, uint64_t& total);

}  // namespace trirast::rtl
