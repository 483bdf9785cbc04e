// The transactor between the engine interface and one Verilated build of trirast_halfspace_top (the
// half-space tile unit, rtl/halfspace/trirast_halfspace.f): the improved unit's triangle port (the same
// set-up triangle), the setup stage's counters, for a build Top of the widths P (see
// improved_harness.hpp); the per-cycle loop is cycle_loop.hpp. Instantiated once per build by the
// generated build*.cpp (cmake/trirast_rtl_builds.cmake).
#pragma once

#include <map>
#include <string>

#include "common/cycle_loop.hpp"
#include "common/harness_util.hpp"
#include "halfspace/halfspace_unit.hpp"
#include "common/unit_widths.hpp"

namespace trirast::rtl {

template <class Top, class P>
struct HalfspacePorts : BoxStagePorts<Top, P> {  // offer, observe_handoff, early_retire
  // rtl/halfspace/trirast_halfspace_setup_stage.sv; the tile walker (rtl/halfspace/trirast_halfspace_tile_walker.sv) is the walk
  // stage's state machine.
  static inline const UnitStates kStates = {
      {{0, "StIdle"}, {1, "StBox"}, {2, "StEdge"}, {4, "StHold"}},
      {{0, "WIdle"}, {1, "WUnit"}, {2, "WStamp"}, {3, "WWait"}, {4, "WDrain"}}};

  void configure(Top&, const RasterConfig&) const {}  // viewport and FIFO only
  void observe_setup(const Top&, TriangleCycles&) const {}
  // The modules as the model counts them (model/halfspace/halfspace_sc.cpp, stage_skeleton.hpp): the
  // setup stage is busy in StBox and StEdge and stalled in StHold while the walk stage is busy;
  // the tile walker (and the walk stage) works on a band in WUnit and WStamp and waits in WWait
  // for the span emitter to take the band; the span emitter is busy for each push, and the walk
  // stage stalls while a span waits for FIFO room (walk_stall_o).
  void count(const Top& top, ModuleCycles& m) {
    const unsigned st = top.setup_state_o;
    m.busy[kHsSetup] += st == kHsStBox || st == kHsStEdge;
    const unsigned w = top.probe_walk_state_o;
    // The walker's own state: walk_busy_o also covers a span in the span FIFO's push register.
    m.stall[kHsSetup] += st == kHsStHold && w != kHsWIdle;
    const bool band = w == kHsWUnit || w == kHsWStamp;
    m.busy[kHsTileWalker] += band;
    m.stall[kHsTileWalker] += w == kHsWWait;
    m.busy[kHsWalk] += band;
    m.stall[kHsWalk] += top.walk_stall_o;
    m.busy[kHsSpanEmitter] += top.probe_push_o;
    // The datapath's work (model/halfspace/halfspace_unit.cpp, HalfspaceWork): a unit tested per WUnit cycle
    // (rejected, a tile accepted whole, or partial), a stamp per WStamp cycle, a band per hand-off
    // to the span emitter.
    if (w == kHsWUnit) {
      const unsigned cls = top.probe_unit_class_o;  // bit 1: accept, bit 0: reject
      ++work_.units_tested;
      if (cls & 1u) ++work_.rejected;
      else if (cls & 2u) ++work_.accepted;
      else ++work_.partial;
    }
    work_.stamps += w == kHsWStamp;
    work_.bands += top.probe_band_load_o;
  }
  HalfspaceWork work_;  // spans and pixels stay 0: the loop counts those
  void add_counters(const ModuleCycles& m, std::map<std::string, uint64_t>& work) const {
    work["busy_cycles.setup"] += m.busy[kHsSetup];
    work["stall_cycles.setup"] += m.stall[kHsSetup];
    work["busy_cycles.tile_walker"] += m.busy[kHsTileWalker];
    work["stall_cycles.tile_walker"] += m.stall[kHsTileWalker];
    work["busy_cycles.walk"] += m.busy[kHsWalk];
    work["stall_cycles.walk"] += m.stall[kHsWalk];
    work["busy_cycles.span_emitter"] += m.busy[kHsSpanEmitter];
    add_hs_work(work_, work);
  }
  enum : int { kHsSetup, kHsTileWalker, kHsWalk, kHsSpanEmitter };
  static constexpr unsigned kHsStBox = 1, kHsStEdge = 2, kHsStHold = 4;
  // Tile-walker states of rtl/halfspace/trirast_halfspace_tile_walker.sv.
  static constexpr unsigned kHsWIdle = 0, kHsWUnit = 1, kHsWStamp = 2, kHsWWait = 3;
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
  run_cycles<Top>(setup, cfg, x_seed, "halfspace-rtl", "trirast_halfspace_top", ports, out);
}

}  // namespace trirast::rtl
