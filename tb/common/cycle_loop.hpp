// The per-cycle loop of the Verilator harnesses (rtl_engine.cpp for trirast_improved_top,
// rtl_trad_engine.cpp for trirast_trad_top): reset, triangles offered back to back, span_ready_i
// from the run's downstream (common/span_downstream.hpp: the --sink-stall pattern or queue, or a
// program's own), the handshakes and observation outputs sampled into the spans and
// per-triangle cycles of docs/timing.md, and the trace window. Both tops share these ports
// (docs/rtl.md, "Harness"); what differs is given by the harness as a Unit:
//
//   void configure(Top&, const RasterConfig&)     its cfg_*_i ports beyond the viewport and FIFO
//   void offer(Top&, const TriangleSetup&)        its triangle ports (tri_valid_i, tri_tag_i: here)
//   bool early_retire(const Top&, size_t& tag)    a triangle leaving before the walk stage in this
//                                                 cycle (no spans: a box outside the viewport,
//                                                 a collinear triangle), and its tag
//   void count(const Top&, ModuleCycles&)         its modules' busy and stall cycles of this cycle
//                                                 (the model's names, docs/sc-model.md)
//   void add_counters(const ModuleCycles&, work)  them as busy_cycles.* / stall_cycles.*
//   void observe_setup(const Top&, TriangleCycles&)   every cycle a triangle is in the setup
//                                                 stage: its lanes' divider and boundary work
//   void observe_handoff(const Top&, TriangleCycles&) in its hand-off cycle: its box size
//   static const UnitStates kStates               its stages' state names (rtl_gtkw.hpp)
//
// The stage breakdown (docs/timing.md, "Outputs") comes from the observation outputs both tops
// have: setup_state_o (its first non-idle cycle, its first StHold cycle), handoff_o, and the walk
// stage's walk_busy_o / walk_last_o with walk_tag_o. A unit whose setup is a pipeline (several
// triangles between their accept and hand-off: the second-generation unit) has no setup_state_o;
// it says so with `static constexpr bool kPipelinedSetup = true` and observes its stages itself:
//
//   void observe_stages(const Top&, uint64_t c, std::vector<TriangleCycles>&)
//                                                 every cycle: setup start, setup done, hand-off,
//                                                 box size, lane work of the triangles inside
//   bool idle(const Top&)                         no triangle inside the unit (the run's end)
//
// Cycle c (docs/timing.md, "Cycles and handshakes"): with clk_i low the inputs of cycle c are
// applied, the handshakes and the observation outputs of cycle c are sampled, and the rising edge
// c is evaluated. Cycle 0 is the first rising edge after rst_ni went high. The tops have no
// combinational path from a handshake or vertex input to an output (docs/port.md; rst_ni gates
// tri_ready_o, and the model is evaluated once after the reset's release, so it is static from
// cycle 0 on), so the outputs of cycle c are those the rising edge c - 1 left, and one evaluation per cycle serves: the clock's fall is
// written into the model's edge memory (Verilator 5's __Vtrigrprev__TOP__clk_i) instead of being
// evaluated. A traced run, or a model without that member, also evaluates with the clock low (the
// trace then shows each cycle's inputs and their combinational fan-out).
#pragma once

#include <verilated.h>
#include <verilated_fst_c.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "common/engine.hpp"
#include "common/span_downstream.hpp"
#include "common/harness_util.hpp"
#include "common/rtl_gtkw.hpp"
#include "common/rtl_coverage.hpp"

namespace trirast {
namespace rtl {

// Busy and stall cycles of the RTL's modules, counted from the observation signals every cycle
// (the unit's count()); the span FIFO's and the sink's are the loop's own.
struct ModuleCycles {
  uint64_t busy[16] = {}, stall[16] = {};
};
// Slots of ModuleCycles the loop fills itself.
enum : int { kModSpanFifo = 14, kModSpanSink = 15 };

struct CycleCounts {
  uint64_t walk_stalls = 0;        // cycles the walk stage waited for FIFO room
  uint64_t early_retirements = 0;  // triangles that left before the walk stage
};

// Runs every set-up triangle through a fresh instance of Top (named top_name in the trace) and
// fills out.spans, out.cycles, out.total_cycles and the work counters triangles, spans, pixels,
// walk_stall_cycles, total_cycles and rtl_x_seed. `engine` names the engine in errors.
template <class Unit, class = void>
struct has_watchdog : std::false_type {};
template <class Unit>
struct has_watchdog<Unit, std::void_t<decltype(Unit::kWatchdogCycles)>> : std::true_type {};

template <class Unit, class = void>
struct has_pipelined_setup : std::false_type {};
template <class Unit>
struct has_pipelined_setup<Unit, std::void_t<decltype(Unit::kPipelinedSetup)>> : std::true_type {};

// Whether Top was verilated with trace support (--trace-fst: a checked build, rtl_builds.hpp).
template <class Top, class = void>
struct has_fst_trace : std::false_type {};
template <class Top>
struct has_fst_trace<Top, std::void_t<decltype(std::declval<Top&>().trace(
                              static_cast<VerilatedFstC*>(nullptr), 0))>> : std::true_type {};

// Whether Top's edge memory of clk_i is reachable (one evaluation per cycle; see above).
template <class Top, class = void>
struct has_clock_edge_memory : std::false_type {};
template <class Top>
struct has_clock_edge_memory<Top,
                             std::void_t<decltype(std::declval<Top&>().rootp->__Vtrigrprev__TOP__clk_i)>>
    : std::true_type {};

template <class Top, class Unit>
CycleCounts run_cycles(const SetupResult& setup, const RasterConfig& cfg, uint32_t x_seed,
                       const char* engine, const char* top_name, Unit& unit, EngineResult& out) {
  // The stage downstream of the span output, driven as its contract says: asked every cycle
  // (span_ready_i), handed every span in the cycle of its handshake, in output order.
  const std::unique_ptr<SpanDownstream> ds = make_span_downstream(cfg);
  const std::vector<TriangleSetup>& tris = setup.tris;
  const size_t n = tris.size();
  const std::string who = engine;

  out.cycles.assign(n, TriangleCycles{});
  for (size_t p = 0; p < n; ++p) out.cycles[p].tri = tris[p].index;
  // Per-triangle progress, by setup position: its last group or row went through the walk stage
  // (or it retired early), and it is done (its last span left, or it had none).
  std::vector<uint8_t> walked(n, 0), done(n, 0);

  // ---- the model ----
  auto ctx = std::make_unique<VerilatedContext>();
  const bool tracing = !cfg.trace_path.empty();
  // --x-initial unique: random initial values from the seed below. A traced run without
  // TRIRAST_RTL_SEED fills them with zeros instead (Verilator is two-state: an X cannot be
  // shown, and zeros read as "not loaded yet" where random numbers look like data); it reports
  // work rtl_x_zero_fill = 1. The results do not depend on the fill (tests/rtl: seeds agree).
  const bool zero_fill = tracing && !std::getenv("TRIRAST_RTL_SEED");
  ctx->randReset(zero_fill ? 0 : 2);
  ctx->randSeed(int(x_seed));
  if (tracing) ctx->traceEverOn(true);
  auto top = std::make_unique<Top>(ctx.get(), top_name);
  std::unique_ptr<VerilatedFstC> fst;
  std::string fst_path;
  RecordingTemporaries recording;  // removed unless finish_trace() moved them to the trace
  if constexpr (!has_fst_trace<Top>::value) {
    if (tracing) throw std::logic_error(who + ": a trace of a build without trace support");
  } else if (tracing) {
    fst = std::make_unique<VerilatedFstC>();
    // The model's time base: cycle c from c ns (the rising edge that starts it) to c + 1 ns. The
    // recording counts in 100 ps: registers change at 10c (clock high), the harness drives the
    // inputs at 10c + 5 (clock low), where every signal has its cycle-c value.
    fst->set_time_unit("1ns");
    fst->set_time_resolution("100ps");
    top->trace(fst.get(), 99);
    fst_path = fst_recording_path(cfg.trace_path);
    recording.track(fst_path);
  }
  // The trace window: setup positions of triangles trace_first..trace_last (scene indices).
  size_t win_a = n, win_b = 0;
  for (size_t p = 0; p < n; ++p) {
    const int64_t idx = tris[p].index;
    if (idx >= cfg.trace_first && (cfg.trace_last < 0 || idx <= cfg.trace_last)) {
      win_a = std::min(win_a, p);
      win_b = std::max(win_b, p);
    }
  }
  bool trace_open = false, trace_over = false;
  uint64_t trace_start = 0, trace_end = 0;  // the recording's first and last dump time
  auto dump = [&](uint64_t t) {
    if (!trace_open) return;
    trace_end = t;
    fst->dump(t);
  };

  // ---- configuration and reset ----
  top->cfg_vp_xmax_i = uint32_t(cfg.width - 1);
  top->cfg_vp_ymax_i = uint32_t(cfg.height - 1);
  top->cfg_fifo_depth_i = uint32_t(cfg.fifo_depth);
  unit.configure(*top, cfg);
  top->tri_valid_i = 0;
  top->span_ready_i = 0;
  top->clk_i = 0;
  top->rst_ni = 1;
  top->eval();
  top->rst_ni = 0;
  top->eval();
  for (int i = 0; i < 2; ++i) {
    top->clk_i = 1;
    top->eval();
    top->clk_i = 0;
    top->eval();
  }
  top->rst_ni = 1;
  top->eval();

  // Puts triangle p on the port.
  auto offer = [&](size_t p) {
    if (p >= n) {
      top->tri_valid_i = 0;
      return;
    }
    top->tri_valid_i = 1;
    top->tri_tag_i = uint32_t(p);
    unit.offer(*top, tris[p]);
  };
  auto known = [&](size_t p, const char* what) {
    if (p >= n)
      throw std::logic_error(who + ": " + what + " with an unknown tag " + std::to_string(p));
    return p;
  };

  CycleCounts counts;
  ModuleCycles mods;
  size_t next = 0;  // the triangle on the port
  // The triangle in the setup stage (from its accept to its hand-off or early retirement; n:
  // none), whether its first non-idle and first StHold cycles were seen, and the triangle whose
  // walk the walk stage reported last.
  size_t in_setup = n, walk_seen = n;
  bool setup_started = false, setup_held = false;
  constexpr unsigned kStHold = 4;  // setup_state_o of StHold in both tops
  offer(next);
  uint64_t last_progress = 0;
  // Cycles without a handshake, a retirement or a triangle's last group or row. A triangle walks
  // at most 2^c rows (c = CoordIntBits), each in a bounded number of cycles, well under 2^22;
  // its stalls wait for pops, which are handshakes. A walk stage that never ends its triangle, or
  // a sink pattern that never lets spans out, trips this. A unit whose walk may go longer
  // without a span (the half-space unit tests every unit of a box, up to 2^(2 box_bits)) says so
  // with `static constexpr uint64_t kWatchdogCycles`.
  uint64_t watchdog = uint64_t(1) << 22;
  if constexpr (has_watchdog<Unit>::value) watchdog = std::max(watchdog, Unit::kWatchdogCycles);
  const bool one_eval = has_clock_edge_memory<Top>::value && !tracing;
  uint64_t c = 0;
  for (;; ++c) {
    top->span_ready_i = ds->ready(c);
    if (!one_eval) top->eval();
    // Stop once every triangle went in and the unit is empty (cycle c is not part of the run).
    if constexpr (has_pipelined_setup<Unit>::value) {
      if (next == n && unit.idle(*top)) break;
    } else {
      if (next == n && top->tri_ready_o && !top->walk_busy_o && !top->span_valid_o) break;
    }

    // Trace window: from the cycle the first triangle is on the port to the cycle after the last
    // one is done.
    if (tracing && !trace_open && !trace_over && next >= win_a && win_a < n) {
      fst->open(fst_path.c_str());
      trace_open = true;
      trace_start = 10 * c + 5;
    }

    bool progress = false;
    // The setup stage's triangle (accepted in an earlier cycle).
    if constexpr (has_pipelined_setup<Unit>::value) {
      unit.observe_stages(*top, c, out.cycles);
    } else if (in_setup < n) {
      TriangleCycles& tc = out.cycles[in_setup];
      const unsigned state = unsigned(top->setup_state_o);
      if (state != 0 && !setup_started) {
        tc.setup_start_cycle = c;
        setup_started = true;
      }
      if (state == kStHold && !setup_held) {
        tc.setup_done_cycle = c;
        setup_held = true;
      }
      unit.observe_setup(*top, tc);
      if (top->handoff_o) {
        tc.handoff_cycle = c;
        unit.observe_handoff(*top, tc);
        in_setup = n;
      }
    }
    const bool accept = top->tri_valid_i && top->tri_ready_o;
    if (accept) {
      out.cycles[next].accept_cycle = c;
      progress = true;
    }
    size_t retired = 0;
    if (unit.early_retire(*top, retired)) {
      const size_t p = known(retired, "early retirement");
      TriangleCycles& tc = out.cycles[p];
      tc.first_span_cycle = tc.done_cycle = c;
      tc.setup_done_cycle = tc.handoff_cycle = tc.walk_start_cycle = tc.walk_end_cycle = c;
      if (p == in_setup) in_setup = n;
      walked[p] = done[p] = 1;
      ++counts.early_retirements;
      progress = true;
    }
    if (accept) {
      in_setup = next;
      setup_started = setup_held = false;
    }
    if (top->walk_busy_o && top->walk_tag_o != walk_seen) {
      walk_seen = known(top->walk_tag_o, "walk");
      out.cycles[walk_seen].walk_start_cycle = c;
    }
    if (top->walk_stall_o) {
      ++out.cycles[known(top->walk_tag_o, "walk stall")].stall_cycles;
      ++counts.walk_stalls;
    }
    unit.count(*top, mods);
    if (top->span_valid_o) {
      ++mods.busy[kModSpanFifo];
      ++(top->span_ready_i ? mods.busy : mods.stall)[kModSpanSink];
    }
    if (top->walk_last_o) {
      const size_t p = known(top->walk_tag_o, "last walk step");
      out.cycles[p].walk_end_cycle = c;
      walked[p] = 1;
      if (top->walk_retire_o) {
        out.cycles[p].first_span_cycle = out.cycles[p].done_cycle = c;
        done[p] = 1;
      }
      progress = true;
    }
    if (top->span_valid_o && top->span_ready_i) {
      const size_t p = known(top->span_tag_o, "span");
      TriangleCycles& tc = out.cycles[p];
      if (tc.spans == 0) tc.first_span_cycle = c;
      tc.done_cycle = c;
      ++tc.spans;
      const Span s{tris[p].index, int32_t(top->span_y_o), int32_t(top->span_x_begin_o),
                   int32_t(top->span_x_end_o)};
      tc.pixels += uint64_t(s.pixels());
      out.spans.push_back(s);
      ds->take(s, c);
      progress = true;
    }
    if (progress) last_progress = c;
    if (c - last_progress > watchdog)
      throw std::runtime_error(who + ": no progress for " + std::to_string(watchdog) +
                               " cycles at cycle " + std::to_string(c) +
                               " (does --sink-stall ever let spans out?)");

    // Rising edge c (at (c + 1) ns in the trace).
    dump(10 * c + 5);
    top->clk_i = 1;
    top->eval();
    dump(10 * (c + 1));
    top->clk_i = 0;
    if constexpr (has_clock_edge_memory<Top>::value)
      if (one_eval) top->rootp->__Vtrigrprev__TOP__clk_i = 0;
    if (accept) offer(++next);

    // The window's last triangle is done when it went through the walk stage (or retired) and
    // its spans left the FIFO (in order: the head is a later triangle's, or the FIFO is empty).
    if (trace_open && win_b < n && walked[win_b]) {
      top->eval();
      const bool drained = !top->span_valid_o || top->span_tag_o > win_b;
      if (done[win_b] || drained) {
        dump(10 * (c + 1) + 5);
        fst->close();
        trace_open = false;
        trace_over = true;
      }
    }
  }
  if (trace_open) {
    dump(10 * c + 5);
    fst->close();
  }
  if (tracing && !trace_over && !trace_open && win_a >= n) {
    fst->open(fst_path.c_str());  // an empty window: a trace with the signals and no cycles
    fst->close();
  }
  top->final();
  if (tracing) {
    write_rtl_gtkw(fst_path, cfg.trace_path, trace_start, std::max(trace_end, trace_start + 10),
                   Unit::kStates);
    finish_trace(fst_path, cfg.trace_path, engine);
    if (zero_fill) out.work["rtl_x_zero_fill"] = 1;
  }

  uint64_t total = 0, spans = 0, pixels = 0;
  for (const TriangleCycles& tc : out.cycles) {
    total = std::max(total, tc.done_cycle + 1);
    spans += tc.spans;
    pixels += tc.pixels;
  }
  out.total_cycles = n ? total : 0;
  out.work["triangles"] += n;
  out.work["spans"] += spans;
  out.work["pixels"] += pixels;
  out.work["walk_stall_cycles"] += counts.walk_stalls;
  out.work["total_cycles"] = out.total_cycles;
  out.work["rtl_x_seed"] = x_seed;
  unit.add_counters(mods, out.work);
  out.work["busy_cycles.span_fifo"] += mods.busy[kModSpanFifo];
  out.work["busy_cycles.span_sink"] += mods.busy[kModSpanSink];
  out.work["stall_cycles.span_sink"] += mods.stall[kModSpanSink];
  // The cover points' counts of this run (common/rtl_coverage.hpp; none in a build without them).
  collect_rtl_coverage(who, *ctx);
  return counts;
}

}  // namespace rtl
}  // namespace trirast
