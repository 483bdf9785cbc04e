// The transactor between the engine interface and one Verilated build of trirast_trad_top
// (docs/rtl.md, "The traditional unit's RTL"): its triangle ports and module counters, for a build
// Top of the widths P (see improved_harness.hpp); the per-cycle loop is cycle_loop.hpp.
#pragma once

#include <algorithm>
#include <map>
#include <string>

#include "common/cycle_loop.hpp"
#include "common/harness_util.hpp"
#include "improved/improved_harness.hpp"
#include "common/unit_widths.hpp"

namespace trirast::rtl {

// The traditional unit's modules, in the model's names (model/trad/trad_sc.cpp).
enum TradModule : int { kTradSetup, kTradWalk, kTradLongWalker, kTradShortWalker };

template <class Top, class P>
struct TradPorts {
  // rtl/trad/trirast_trad_setup_stage.sv, trirast_trad_walk_stage.sv.
  static inline const UnitStates kStates = {
      {{0, "StIdle"}, {1, "StSort"}, {2, "StLine"}, {4, "StHold"}}, kWalkStageStates};
  using PortBits = Bits<4>;  // up to 128-bit ports
  static_assert(words(3 * P::kVertexBits) <= 4, "Bits<4> holds up to 128 bits");

  void configure(Top&, const RasterConfig&) const {}  // viewport and FIFO only
  void offer(Top& top, const TriangleSetup& t) const {
    PortBits vx, vy;
    for (int k = 0; k < 3; ++k) {
      vx.put(k * P::kVertexBits, P::kVertexBits, t.v[k].x);
      vy.put(k * P::kVertexBits, P::kVertexBits, t.v[k].y);
    }
    drive(top.tri_vx_i, vx, words(3 * P::kVertexBits));
    drive(top.tri_vy_i, vy, words(3 * P::kVertexBits));
  }
  void observe_setup(const Top&, TriangleCycles&) const {}  // no divider, no lanes
  // The box the walk stage covers: the bounding box of the sorted integer pixels.
  void observe_handoff(const Top& top, TriangleCycles& tc) const {
    int64_t x[3], y[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = field(top.hand_px_o, k);
      y[k] = field(top.hand_py_o, k);
    }
    tc.box_width = uint64_t(std::max({x[0], x[1], x[2]}) - std::min({x[0], x[1], x[2]})) + 1;
    tc.box_height = uint64_t(y[2] - y[0]) + 1;
  }
  // Field k (signed, P::kCoordIntBits wide) of a packed vertex port.
  static int64_t field(uint64_t port, int k) {
    const uint64_t u = (port >> (k * P::kCoordIntBits)) & ((uint64_t(1) << P::kCoordIntBits) - 1);
    const uint64_t sign = uint64_t(1) << (P::kCoordIntBits - 1);
    return int64_t(u ^ sign) - int64_t(sign);
  }
  // A collinear triangle retires in the setup stage.
  bool early_retire(const Top& top, size_t& tag) const {
    if (!top.setup_retire_o) return false;
    tag = top.setup_retire_tag_o;
    return true;
  }
  // The model's definitions (model/trad/trad_sc.cpp): the setup stage is busy in StSort and StLine
  // and stalls in StHold while the walk stage is busy; the walk stage is busy in a cycle of a row
  // (not a stall); the long walker counts its steps, the short walker its two edges' steps.
  void count(const Top& top, ModuleCycles& m) const {
    const unsigned st = top.setup_state_o;
    m.busy[kTradSetup] += st >= 1 && st <= 3;
    m.stall[kTradSetup] += st == kRtlStHold && top.walk_busy_o;
    if (top.walk_busy_o) {
      m.busy[kTradWalk] += !top.walk_stall_o;
      m.stall[kTradWalk] += top.walk_stall_o;
    }
    m.busy[kTradLongWalker] += top.probe_long_step_o;
    m.busy[kTradShortWalker] += top.probe_short_step_o;
  }
  void add_counters(const ModuleCycles& m, std::map<std::string, uint64_t>& work) const {
    work["busy_cycles.setup"] += m.busy[kTradSetup];
    work["stall_cycles.setup"] += m.stall[kTradSetup];
    work["busy_cycles.walk"] += m.busy[kTradWalk];
    work["stall_cycles.walk"] += m.stall[kTradWalk];
    work["busy_cycles.long_walker"] += m.busy[kTradLongWalker];
    work["busy_cycles.short_walker"] += m.busy[kTradShortWalker];
    // The datapath's work as the model counts it: a Bresenham step per walker step (the model's
    // rows_visited has no RTL counterpart here).
    work["trad_bresenham_steps"] += m.busy[kTradLongWalker] + m.busy[kTradShortWalker];
  }
};

template <class Top, class P>
void run_trad_build(const SetupResult& setup, const RasterConfig& cfg, uint32_t x_seed,
                    EngineResult& out) {
  // The RTL assumes its inputs fit its widths: the vertices are the only input.
  for (const TriangleSetup& t : setup.tris)
    for (int k = 0; k < 3; ++k) {
      check_signed(t.v[k].x, P::kVertexBits, t.index, "x", "vertex coordinate");
      check_signed(t.v[k].y, P::kVertexBits, t.index, "y", "vertex coordinate");
    }
  TradPorts<Top, P> ports;
  const CycleCounts counts =
      run_cycles<Top>(setup, cfg, x_seed, "trad-rtl", "trirast_trad_top", ports, out);
  out.work["trad_collinear"] += counts.early_retirements;
}

}  // namespace trirast::rtl
