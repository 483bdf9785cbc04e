// The transactor between the engine interface and one Verilated build of trirast_hs_top (the
// half-space tile unit, rtl/trirast_halfspace.f): the improved unit's triangle port (the same
// set-up triangle), the setup stage's counters, for a build Top of the widths P (see
// improved_harness.hpp); the per-cycle loop is cycle_loop.hpp. Instantiated once per build by the
// generated build*.cpp (cmake/trirast_rtl_builds.cmake).
#pragma once

#include <map>
#include <string>

#include "cycle_loop.hpp"
#include "harness_util.hpp"
#include "unit/halfspace_unit.hpp"
#include "unit/unit_widths.hpp"

namespace trirast::rtl {

template <class Top, class P>
struct HalfspacePorts {

  void configure(Top&, const RasterConfig&) const {}  // viewport and FIFO only
  void offer(Top& top, const TriangleSetup& t) const {
    drive_edge_triangle<P>(top, t);
  }
  void observe_setup(const Top&, TriangleCycles&) const {}
  void observe_handoff(const Top& top, TriangleCycles& tc) const {
    tc.box_width = uint64_t(top.box_xmax_o) + 1;
    tc.box_height = uint64_t(top.box_ymax_o) + 1;
  }
  bool early_retire(const Top& top, size_t& tag) const {
    if (!top.box_retire_o) return false;
    tag = top.box_retire_tag_o;
    return true;
  }
  // The setup stage as the model counts it (model/sc/halfspace_sc.cpp, stage_skeleton.hpp): busy
  // in StBox and StEdge, stalled in StHold while the walk stage is busy. The walk stage's own
  // counters (tile walker, span emitter) are the model's only.
  void count(const Top& top, ModuleCycles& m) const {
    const unsigned st = top.setup_state_o;
    m.busy[0] += st == kHsStBox || st == kHsStEdge;
    m.stall[0] += st == kHsStHold && top.walk_busy_o;
  }
  void add_counters(const ModuleCycles& m, std::map<std::string, uint64_t>& work) const {
    work["busy_cycles.setup"] += m.busy[0];
    work["stall_cycles.setup"] += m.stall[0];
  }
  static constexpr unsigned kHsStBox = 1, kHsStEdge = 2, kHsStHold = 4;
  // A box of up to 2^box_bits x 2^box_bits pixels walked a pixel per cycle without a span (every
  // unit of an empty band is tested), plus margin: cycle_loop.hpp's watchdog.
  static constexpr uint64_t kWatchdogCycles = uint64_t(4) << (2 * P::kBoxBits);
};

// Runs a scene through a fresh instance of build Top (widths P): checks every triangle against the
// widths first (the bit-accurate model raises the WidthError naming it), then the cycle loop.
template <class Top, class P>
void run_halfspace_build(const SetupResult& setup, const RasterConfig& cfg, uint32_t x_seed,
                         EngineResult& out) {
  check_widths<HalfspaceUnit, P>(setup, cfg);
  HalfspacePorts<Top, P> ports;
  run_cycles<Top>(setup, cfg, x_seed, "halfspace-rtl", "trirast_hs_top", ports, out);
}

}  // namespace trirast::rtl
