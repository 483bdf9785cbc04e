// The transactor between the engine interface and one Verilated build of trirast_improved_top (docs/rtl.md,
// "Harness"): the improved unit's configuration and triangle ports and its module counters, for a
// build Top of the widths P (a struct of tb/'s generated parameter headers,
// scripts/gen_params.py --struct); the per-cycle loop is cycle_loop.hpp. Instantiated once per
// build by the generated rtl_build_*.cpp (tb/CMakeLists.txt).
#pragma once

#include <algorithm>
#include <map>
#include <string>

#include "common/cycle_loop.hpp"
#include "common/harness_util.hpp"
#include "improved/improved_unit.hpp"
#include "common/unit_widths.hpp"

namespace trirast::rtl {

// The improved unit's modules, in the model's names (model/improved/improved_sc.cpp).
enum ImprovedModule : int {
  kImpSetup, kImpInterface, kImpLane0, kImpDivider0 = kImpLane0 + 3, kImpWalk = kImpDivider0 + 3,
  kImpSpanGenerator, kImpWalker0
};

// Setup-stage states of rtl/improved/trirast_improved_setup_stage.sv (and the trad one: 1..2 its own, 4 StHold).
enum : unsigned { kRtlStIdle = 0, kRtlStBox = 1, kRtlStEdge = 2, kRtlStLanes = 3, kRtlStHold = 4 };

template <class Top, class P, int kBuildEndpoints>
struct ImprovedPorts : BoxStagePorts<Top, P> {  // offer, observe_handoff, early_retire
  // rtl/improved/trirast_improved_setup_stage.sv, trirast_improved_walk_stage.sv.
  static inline const UnitStates kStates = {
      {{0, "StIdle"}, {1, "StBox"}, {2, "StEdge"}, {3, "StLanes"}, {4, "StHold"}}, kWalkStageStates};

  void configure(Top& top, const RasterConfig& cfg) {
    top.cfg_divide_i = cfg.boundary == BoundaryMode::Divide;
    top.cfg_adaptive_i = cfg.divider == DividerMode::Adaptive;
    top.cfg_endpoints_i = uint32_t(cfg.endpoints);
    endpoints = unsigned(cfg.endpoints);
  }
  unsigned endpoints = 1;  // rows per group (cfg_endpoints_i)
  // The lanes' work while the triangle is set up: a busy lane does a divider iteration or a
  // boundary column step.
  // Lanes work only while a triangle is in the setup stage, so these are also the run's totals.
  void observe_setup(const Top& top, TriangleCycles& tc) {
    const unsigned busy = top.lane_busy_o, div = top.lane_div_o;
    const unsigned iterations = ones3(busy & div), steps = ones3(busy & ~div & 7u);
    tc.divider_iterations += iterations;
    tc.boundary_steps += steps;
    work_.divider_iterations += iterations;
    work_.boundary_steps += steps;
  }
  // The model's definitions (model/improved/improved_sc.cpp, stage_skeleton.hpp): the setup stage is
  // busy in StBox..StLanes and stalls in StHold while the walk stage is busy; the interface works
  // in StBox and StEdge; a lane while its busy_o is high, its divider while it iterates (div_en);
  // the walk stage and the span generator in a cycle whose group goes, and the walk stage stalls
  // in a cycle without room; an edge walker for each Bresenham step it takes in a group that goes
  // (a row of the group in the bound state, RowBound, stepping to a row of the box: no step past
  // Ymax, as model/improved/improved_unit.cpp walks).
  void count(const Top& top, ModuleCycles& m) {
    const unsigned st = top.setup_state_o;
    m.busy[kImpSetup] += st >= kRtlStBox && st <= kRtlStLanes;
    m.stall[kImpSetup] += st == kRtlStHold && top.walk_busy_o;
    m.busy[kImpInterface] += st == kRtlStBox || st == kRtlStEdge;
    const unsigned lanes = top.lane_busy_o;
    m.busy[kImpLane0 + 0] += lanes & 1u;
    m.busy[kImpLane0 + 1] += (lanes >> 1) & 1u;
    m.busy[kImpLane0 + 2] += (lanes >> 2) & 1u;
    const unsigned dividers = top.probe_div_en_o;
    work_.divisions += ones3(dividers & top.probe_div_last_o);
    m.busy[kImpDivider0 + 0] += dividers & 1u;
    m.busy[kImpDivider0 + 1] += (dividers >> 1) & 1u;
    m.busy[kImpDivider0 + 2] += (dividers >> 2) & 1u;
    if (top.walk_busy_o) {
      const bool stall = top.walk_stall_o;
      m.busy[kImpWalk] += !stall;
      m.busy[kImpSpanGenerator] += !stall;
      m.stall[kImpWalk] += stall;
      if (!stall) {
        const uint64_t states = top.probe_walker_state_o;  // walker k, row r: bits 2(kN + r)
        const unsigned row = top.probe_walk_row_o, ymax = top.probe_walk_ymax_o;
        for (unsigned r = 0; r < endpoints && row + r < ymax; ++r)
          for (unsigned k = 0; k < 3; ++k)
            m.busy[kImpWalker0 + k] += ((states >> (2 * (k * kRows + r))) & 3u) == kRowBound;
        work_.rows_visited += std::min<uint64_t>(endpoints, uint64_t(ymax) + 1 - row);
      }
    }
  }
  static constexpr unsigned kRowBound = 1;  // trirast_pkg::RowBound
  static constexpr unsigned kRows = unsigned(kBuildEndpoints);  // rows per walker in the probe
  void add_counters(const ModuleCycles& m, std::map<std::string, uint64_t>& work) const {
    work["busy_cycles.setup"] += m.busy[kImpSetup];
    work["stall_cycles.setup"] += m.stall[kImpSetup];
    work["busy_cycles.interface"] += m.busy[kImpInterface];
    for (int k = 0; k < 3; ++k) {
      work["busy_cycles.edge_lane" + std::to_string(k)] += m.busy[kImpLane0 + k];
      work["busy_cycles.adder_divider" + std::to_string(k)] += m.busy[kImpDivider0 + k];
    }
    work["busy_cycles.walk"] += m.busy[kImpWalk];
    work["stall_cycles.walk"] += m.stall[kImpWalk];
    work["busy_cycles.span_generator"] += m.busy[kImpSpanGenerator];
    for (int k = 0; k < 3; ++k)
      work["busy_cycles.edge_walker" + std::to_string(k)] += m.busy[kImpWalker0 + k];
    // The datapath's work as model/improved/improved_unit.cpp counts it: a lane's busy cycle is a
    // divider iteration or a boundary column step; a division ends in its divider's last
    // iteration; a row visited is a box row of a group that goes; a row stepped, a walker's
    // Bresenham step.
    work["divider_iterations"] += work_.divider_iterations;
    work["boundary_steps"] += work_.boundary_steps;
    work["divisions"] += work_.divisions;
    work["rows_visited"] += work_.rows_visited;
    work["rows_stepped"] +=
        m.busy[kImpWalker0] + m.busy[kImpWalker0 + 1] + m.busy[kImpWalker0 + 2];
  }
  struct {
    uint64_t divider_iterations = 0, boundary_steps = 0, divisions = 0, rows_visited = 0;
  } work_;
};

// Runs a scene through a fresh instance of build Top (widths P, NumEndpoints kBuildEndpoints):
// checks every triangle against the widths first (the bit-accurate model raises the WidthError
// naming it), then the cycle loop.
template <class Top, class P, int kBuildEndpoints>
void run_improved_build(const SetupResult& setup, const RasterConfig& cfg, uint32_t x_seed,
                        EngineResult& out) {
  check_widths<ImprovedUnit, P>(setup, cfg);
  ImprovedPorts<Top, P, kBuildEndpoints> ports;
  run_cycles<Top>(setup, cfg, x_seed, "improved-rtl", "trirast_improved_top", ports, out);
}

}  // namespace trirast::rtl
