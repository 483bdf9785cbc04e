// The transactor between the engine interface and one Verilated build of trirast_improved2_top
// (the second-generation improved unit, engine "improved2-rtl"; docs/rtl.md, "Harness"): its
// configuration and triangle ports and its stage counters, for a build Top of the widths P; the
// per-cycle loop is cycle_loop.hpp. Its setup is a pipeline (box stage B, corner stage C, job
// stage L, several triangles at once), so the harness observes the stages by tag
// (kPipelinedSetup). Instantiated once per build by the generated rtl_builds/buildV*.cpp.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/cycle_loop.hpp"
#include "common/harness_util.hpp"
#include "improved2/improved2_unit.hpp"
#include "common/unit_widths.hpp"

namespace trirast::rtl {

// The unit's stages and modules, in the model's names (model/improved2/improved2_sc.cpp).
enum Improved2Module : int {
  kI2Box, kI2Corner, kI2Job, kI2Lane0, kI2Walk = kI2Lane0 + 3, kI2Count
};

template <class Top, class P>
struct Improved2Ports {
  static constexpr bool kPipelinedSetup = true;
  // No setup state register; the walk stage's walk_q (idle, walking).
  static inline const UnitStates kStates = {{}, kWalkStageStates};

  void configure(Top& top, const RasterConfig& cfg) {
    top.cfg_endpoints_i = uint32_t(cfg.endpoints);
    endpoints_ = unsigned(cfg.endpoints);
  }
  void offer(Top& top, const TriangleSetup& t) const { drive_edge_triangle<P>(top, t); }

  TriangleCycles& at(std::vector<TriangleCycles>& cycles, uint64_t tag, const char* what) const {
    if (tag >= cycles.size())
      throw std::logic_error("improved2-rtl: " + std::string(what) + " with an unknown tag " +
                             std::to_string(tag));
    return cycles[tag];
  }
  // The model's per-triangle columns (model/improved2/improved2_sc.cpp): setup starts as the triangle
  // enters B; setup is done in the first cycle its job in L is ready to hand off; the lanes
  // work while the job is in L.
  void observe_stages(const Top& top, uint64_t c, std::vector<TriangleCycles>& cycles) {
    if (seen_.size() != cycles.size()) seen_.assign(cycles.size(), 0);
    if (top.box_valid_o) {
      const uint64_t tag = top.box_tag_o;
      TriangleCycles& tc = at(cycles, tag, "box stage");
      if (!(seen_[tag] & kSeenBox)) {
        tc.setup_start_cycle = c;
        seen_[tag] |= kSeenBox;
      }
    }
    if (top.job_valid_o) {
      const uint64_t tag = top.job_tag_o;
      TriangleCycles& tc = at(cycles, tag, "job stage");
      const unsigned busy = top.lane_busy_o;
      tc.divider_iterations += ones3(busy & top.lane_div_o);
      tc.boundary_steps += ones3(busy & top.lane_step_o);
      if (top.job_ready_o && !(seen_[tag] & kSeenReady)) {
        tc.setup_done_cycle = c;
        seen_[tag] |= kSeenReady;
      }
      if (top.handoff_o) {
        tc.handoff_cycle = c;
        tc.box_width = uint64_t(top.box_xmax_o) + 1;
        tc.box_height = uint64_t(top.box_ymax_o) + 1;
        ++(top.probe_job_tiny_o ? tiny_ : lanes_);
      }
    }
  }
  bool idle(const Top& top) const { return !top.busy_o; }

  // A box that clips to nothing retires in the box stage.
  bool early_retire(const Top& top, size_t& tag) {
    if (!top.box_retire_o) return false;
    tag = top.box_retire_tag_o;
    ++empty_;
    return true;
  }
  // The model's definitions: a stage is busy while its register holds a triangle and stalls
  // while it holds a finished one the next stage cannot take; a lane while its busy_o is high;
  // the walk stage is busy in a cycle whose row goes and stalls in a cycle without room.
  void count(const Top& top, ModuleCycles& m) {
    m.busy[kI2Box] += top.box_valid_o;
    m.stall[kI2Box] += top.box_stall_o;
    m.busy[kI2Corner] += top.corner_valid_o;
    m.stall[kI2Corner] += top.corner_stall_o;
    m.busy[kI2Job] += top.job_valid_o;
    m.stall[kI2Job] += top.job_ready_o && !top.handoff_o;
    const unsigned lanes = top.lane_busy_o;
    for (int k = 0; k < 3; ++k) m.busy[kI2Lane0 + k] += (lanes >> k) & 1u;
    m.busy[kI2Walk] += top.walk_busy_o && !top.walk_stall_o;
    m.stall[kI2Walk] += top.walk_stall_o;
    if (top.walk_busy_o && !top.walk_stall_o) {
      // The rows the group goes through (the model's rows_visited): rows j .. j + n - 1 up to the
      // job's last row, Ymax, or for a tiny job row 1 when it has a span, else row 0.
      const unsigned tiny = top.probe_walk_tiny_o;  // {tiny job, row 1 has a span}
      const uint64_t row = top.probe_walk_row_o;
      const uint64_t last = (tiny & 2u) ? uint64_t(tiny & 1u) : uint64_t(top.probe_walk_ymax_o);
      rows_ += std::min<uint64_t>(endpoints_, last + 1 - row);
    }
  }
  void add_counters(const ModuleCycles& m, std::map<std::string, uint64_t>& work) const {
    work["busy_cycles.box_stage"] += m.busy[kI2Box];
    work["stall_cycles.box_stage"] += m.stall[kI2Box];
    work["busy_cycles.corner_stage"] += m.busy[kI2Corner];
    work["stall_cycles.corner_stage"] += m.stall[kI2Corner];
    work["busy_cycles.job_stage"] += m.busy[kI2Job];
    work["stall_cycles.job_stage"] += m.stall[kI2Job];
    for (int k = 0; k < 3; ++k)
      work["busy_cycles.lane" + std::to_string(k)] += m.busy[kI2Lane0 + k];
    work["busy_cycles.walk"] += m.busy[kI2Walk];
    work["stall_cycles.walk"] += m.stall[kI2Walk];
    work["empty_boxes"] += empty_;
    work["tiny_boxes"] += tiny_;
    work["lane_boxes"] += lanes_;
    work["rows_visited"] += rows_;
  }

 private:
  enum : uint8_t { kSeenBox = 1, kSeenReady = 2 };
  std::vector<uint8_t> seen_;
  uint64_t empty_ = 0, tiny_ = 0, lanes_ = 0, rows_ = 0;
  unsigned endpoints_ = 1;  // n: rows per group (cfg_endpoints_i)
};

// Runs a scene through a fresh instance of build Top (widths P): checks every triangle against
// the widths first (the bit-accurate model raises the WidthError naming it), then the cycle
// loop; the run's divider iterations and boundary steps are the per-triangle columns' sums.
template <class Top, class P>
void run_improved2_build(const SetupResult& setup, const RasterConfig& cfg, uint32_t x_seed,
                         EngineResult& out) {
  check_widths<Improved2Unit, P, Improved2Triangle>(setup, cfg);
  Improved2Ports<Top, P> ports;
  run_cycles<Top>(setup, cfg, x_seed, "improved2-rtl", "trirast_improved2_top", ports, out);
  uint64_t iterations = 0, steps = 0;
  for (const TriangleCycles& tc : out.cycles) {
    iterations += tc.divider_iterations;
    steps += tc.boundary_steps;
  }
  out.work["divider_iterations"] += iterations;
  out.work["boundary_steps"] += steps;
}

}  // namespace trirast::rtl
