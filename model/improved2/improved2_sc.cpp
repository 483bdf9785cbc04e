#include "improved2/improved2_sc.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "common/sc_engine.hpp"
#include "improved2/improved2_unit.hpp"

namespace trirast::sc {

using sc_core::sc_module_name;

Improved2UnitSc::Improved2UnitSc(sc_module_name name, const RasterConfig& cfg,
                                 const sc_core::sc_time& period)
    : RasterUnitSc(name, cfg, period),
      sink("span_sink"),
      fifo("span_fifo", sink),
      box_stage("box_stage"),
      corner_stage("corner_stage"),
      job_stage("job_stage"),
      walk_stage("walk_stage") {
  start(cfg);
}

void Improved2UnitSc::begin_stream() {
  RunState& r = state_;
  sink.begin_run(&r);
  fifo.begin_run(&r, r.trace ? add_trace(*r.trace) : SpanTraceSignals{});
  // The per-triangle cross-check of the gen2 parts against gen1's (Improved2Unit) runs in the
  // untimed improved2-datapath engine and here only on request: TRIRAST_IMPROVED2_CHECK=1.
  const char* check = std::getenv("TRIRAST_IMPROVED2_CHECK");
  unit_ = std::make_unique<Improved2Unit>(r.cfg, check && std::string(check) == "1");
  corner_stage.configure(r.cfg.improved2.corner_form);
  box_stage.counters = {};
  job_stage.counters = {};
  for (auto& b : job_stage.lane_busy) b = 0;
  walk_stage.counters = {};
  tiny_ = lanes_ = empty_ = iterations_ = steps_ = rows_ = 0;
  c_free_ = l_free_ = w_free_ = 0;
}

SpanTraceSignals Improved2UnitSc::add_trace(VcdRecorder& tr) {
  // Declaration order is the VCD's and the .gtkw's: the stages in pipeline order, then the span
  // port, the FIFO and the sink (the shared SpanFifo drives those).
  sig_.accept = tr.add("box_stage", "tri_accept", 1, 0);  // the triangle port's valid && ready
  sig_.b_busy = tr.add("box_stage", "busy", 1, 0);
  sig_.b_tri = tr.add("box_stage", "tri", 32, VcdRecorder::kX);
  sig_.b_stall = tr.add("box_stage", "stall", 1, 0);    // waiting for C
  sig_.b_retire = tr.add("box_stage", "retire", 1, 0);  // an empty box retires (box_retire_o)
  sig_.c_busy = tr.add("corner_stage", "busy", 1, 0);
  sig_.c_tri = tr.add("corner_stage", "tri", 32, VcdRecorder::kX);
  sig_.c_stall = tr.add("corner_stage", "stall", 1, 0);  // values ready, waiting for L
  sig_.c_run = tr.add("corner_unit", "run", 2, kCornerIdle);
  tr.name_values(
      sig_.c_run, "corner_run",
      {{kCornerIdle, "Idle"}, {kRunL, "RunL"}, {kRunR, "RunR"}, {kProducts, "Products"}});
  sig_.c_digits = tr.add("corner_unit", "digits", 8, VcdRecorder::kX);  // the run's digit count
  sig_.l_busy = tr.add("job_stage", "busy", 1, 0);
  sig_.l_tri = tr.add("job_stage", "tri", 32, VcdRecorder::kX);
  sig_.l_tiny = tr.add("job_stage", "tiny", 1, 0);    // the direct 2x2 test's job
  sig_.l_stall = tr.add("job_stage", "stall", 1, 0);  // ready, waiting for the walk stage
  for (int e = 0; e < 3; ++e) {
    const std::string lane = "lane" + std::to_string(e);
    sig_.lane_busy[e] = tr.add(lane, "busy", 1, 0);
    sig_.lane_phase[e] = tr.add(lane, "phase", 2, kLaneIdle);
    tr.name_values(sig_.lane_phase[e], "lane_phase",
                   {{kLaneIdle, "Idle"},
                    {kLaneSlope, "Slope"},
                    {kLaneEntry, "Entry"},
                    {kLaneTraverse, "Traverse"}});
    sig_.lane_steps[e] = tr.add(lane, "steps", 16, VcdRecorder::kX);     // T, while busy
    sig_.lane_iter[e] = tr.add(lane, "iterations", 8, VcdRecorder::kX);  // divider, while busy
  }
  sig_.w_state = tr.add("walk_stage", "state", 2, kWalkIdle);
  tr.name_values(
      sig_.w_state, "walk_state",
      {{kWalkIdle, "StWalkIdle"}, {kWalkLanes, "StWalkLanes"}, {kWalkTiny, "StWalkTiny"}});
  sig_.w_tri = tr.add("walk_stage", "tri", 32, VcdRecorder::kX);
  sig_.w_row = tr.add("walk_stage", "row", 16, VcdRecorder::kX);
  sig_.w_stall = tr.add("walk_stage", "stall", 1, 0);  // no FIFO room for the row
  sig_.w_push = tr.add("walk_stage", "push", 1, 0);    // the registered span enters the FIFO
  SpanTraceSignals span;
  span.valid = tr.add("span", "valid", 1, 0);
  span.ready = tr.add("span", "ready", 1, 1);
  span.tri = tr.add("span", "tri", 32, VcdRecorder::kX);
  span.y = tr.add("span", "y", 16, VcdRecorder::kX);
  span.x_begin = tr.add("span", "x_begin", 16, VcdRecorder::kX);
  span.x_end = tr.add("span", "x_end", 16, VcdRecorder::kX);
  span.count = tr.add("span_fifo", "count", 11, 0, true);
  span.take = tr.add("span_sink", "take", 1, 0);
  return span;
}

// Each stage's signals hold from the cycle the triangle is in it to the cycle it leaves; the
// value a stage falls back to in the cycle after is reported first, so the next triangle's
// entering in that cycle (reported later) wins.
void Improved2UnitSc::trace_job(VcdRecorder& tr, uint32_t tag, uint64_t a, uint64_t k, uint64_t cr,
                                uint64_t m, uint64_t ready, uint64_t h) {
  // B: a + 1 .. k (stalled a + 1 .. k - 1 while C was full).
  tr.value(sig_.b_busy, a + 1, 1);
  tr.value(sig_.b_tri, a + 1, tag);
  tr.value(sig_.b_busy, k + 1, 0);
  tr.value(sig_.b_tri, k + 1, VcdRecorder::kX);
  if (k > a + 1) {
    tr.value(sig_.b_stall, a + 1, 1);
    tr.value(sig_.b_stall, k, 0);
  }
  // C: k + 1 .. m (stalled cr .. m - 1 while L was full). The digit-serial unit runs from k
  // (started on B's box as the triangle enters C): E_L for d_L + 1 cycles, then (a lane box) E_R
  // for d_R + 2, until cr - 1; the DSP products are combinational on C's register.
  tr.value(sig_.c_busy, k + 1, 1);
  tr.value(sig_.c_tri, k + 1, tag);
  tr.value(sig_.c_busy, m + 1, 0);
  tr.value(sig_.c_tri, m + 1, VcdRecorder::kX);
  if (m > cr) {
    tr.value(sig_.c_stall, cr, 1);
    tr.value(sig_.c_stall, m, 0);
  }
  if (corner_stage.form() == 0) {
    tr.value(sig_.c_run, k + 1, kProducts);
    tr.value(sig_.c_run, m + 1, kCornerIdle);
  } else {
    const uint64_t dl = uint64_t(x_.corner_digits_l);
    tr.value(sig_.c_run, k, kRunL);
    tr.value(sig_.c_digits, k, dl);
    if (!x_.tiny) {
      tr.value(sig_.c_run, k + 1 + dl, kRunR);
      tr.value(sig_.c_digits, k + 1 + dl, uint64_t(x_.corner_digits_r));
    }
    tr.value(sig_.c_run, cr, kCornerIdle);
    tr.value(sig_.c_digits, cr, VcdRecorder::kX);
  }
  // L: m + 1 .. h (stalled ready .. h - 1 while the walk stage was busy); lane e busy
  // m + 1 .. m + L_e.
  tr.value(sig_.l_busy, m + 1, 1);
  tr.value(sig_.l_tri, m + 1, tag);
  tr.value(sig_.l_tiny, m + 1, x_.tiny ? 1 : 0);
  tr.value(sig_.l_busy, h + 1, 0);
  tr.value(sig_.l_tri, h + 1, VcdRecorder::kX);
  tr.value(sig_.l_tiny, h + 1, 0);
  if (h > ready) {
    tr.value(sig_.l_stall, ready, 1);
    tr.value(sig_.l_stall, h, 0);
  }
  if (!x_.tiny)
    for (int e = 0; e < 3; ++e) {
      const Improved2LaneWork& w = x_.lane[e];
      if (w.cycles == 0) continue;
      tr.value(sig_.lane_busy[e], m + 1, 1);
      // Improved2EdgeLane's cycles: a horizontal edge (no division) T + 1; otherwise max(m_s, T) + 1 for
      // the slope division with the traversal, then m_e for the entry division.
      if (w.iterations == 0) {
        tr.value(sig_.lane_phase[e], m + 1, kLaneTraverse);
      } else {
        const uint64_t me = !w.enters ? 0 : w.entry_saturated ? 2 : uint64_t(w.m);
        tr.value(sig_.lane_phase[e], m + 1, kLaneSlope);
        if (me) tr.value(sig_.lane_phase[e], m + 1 + w.cycles - me, kLaneEntry);
      }
      tr.value(sig_.lane_phase[e], m + 1 + w.cycles, kLaneIdle);
      tr.value(sig_.lane_steps[e], m + 1, uint64_t(w.steps));
      tr.value(sig_.lane_iter[e], m + 1, w.iterations);
      tr.value(sig_.lane_busy[e], m + 1 + w.cycles, 0);
      tr.value(sig_.lane_steps[e], m + 1 + w.cycles, VcdRecorder::kX);
      tr.value(sig_.lane_iter[e], m + 1 + w.cycles, VcdRecorder::kX);
    }
}

uint64_t Improved2UnitSc::walk(const TriangleSetup& tri, Improved2Triangle& x, size_t pos,
                               uint64_t h, TriangleCycles& rec, VcdRecorder* tr) {
  if (tr) {
    tr->value(sig_.w_state, h + 1, x.tiny ? kWalkTiny : kWalkLanes);
    tr->value(sig_.w_tri, h + 1, rec.tri);
  }
  // Groups of N rows (--endpoints): rows g*N .. g*N + N - 1 (of a tiny job's x.rows, or of a lane
  // job's rows 0 .. Ymax, which the unit's walkers produce one by one) go in one cycle and their
  // spans are pushed together.
  const uint64_t N = uint64_t(state_.cfg.endpoints);
  const uint64_t n_rows = x.tiny ? uint64_t(x.rows.size()) : uint64_t(x.box.Ymax) + 1;
  uint64_t t = h + 1, last = h, groups = 0;
  for (uint64_t i = 0; i < n_rows;) {
    // The admission test: the FIFO's entries plus the spans in flight (pushed in cycle t, which
    // the FIFO model already holds) leave room for N more.
    const uint64_t go = fifo.first_room(t, N);
    rec.stall_cycles += go - t;
    bool pushed = false;
    if (tr) {
      if (go != t) {
        tr->value(sig_.w_stall, t, 1);
        tr->value(sig_.w_stall, go, 0);
      }
      tr->value(sig_.w_row, go, i);  // the group's first row, g*N
    }
    for (const uint64_t end = std::min(i + N, n_rows); i < end; ++i) {
      const Improved2Row row = x.tiny ? x.rows[i] : unit_->walk_row(tri, x, int64_t(i));
      if (row.valid) {
        fifo.push(row.span, pos, go + 1);  // registered, pushed in go + 1
        pushed = true;
      }
    }
    if (tr && pushed) {
      tr->value(sig_.w_push, go + 1, 1);
      tr->value(sig_.w_push, go + 2, 0);  // overridden by the next group's push in go + 2
    }
    ++groups;
    last = go;
    t = go + 1;
  }
  if (tr) {
    tr->value(sig_.w_state, last + 1, kWalkIdle);
    tr->value(sig_.w_tri, last + 1, VcdRecorder::kX);
    tr->value(sig_.w_row, last + 1, VcdRecorder::kX);
  }
  walk_stage.counters.busy += groups;
  walk_stage.counters.stall += rec.stall_cycles;
  rows_ += n_rows;
  return last;
}

// Triangle t accepted in a through the stages; the port takes the next one in the cycle B's
// triangle leaves (a + 1 for an empty box, else the cycle it moves to C).
uint64_t Improved2UnitSc::accept(const TriangleSetup& t, size_t pos, uint64_t a) {
  RunState& r = state_;
  r.records.push_back(TriangleCycles{t.index, a, 0, 0, 0, 0, 0});
  TriangleCycles& rec = r.tri(pos);
  rec.setup_start_cycle = a + 1;
  unit_->set_up(t, x_);  // the walk stage runs the lane job's rows (walk)
  // The trace: past the window's last cycle every report would be dropped (the recorder keeps
  // the window), so the process stops reporting there.
  VcdRecorder* tr = r.trace && a <= r.trace->window_last() ? r.trace : nullptr;
  if (tr) {
    tr->value(sig_.accept, a, 1);
    tr->value(sig_.accept, a + 1, 0);  // overridden by the next accept in a + 1
  }
  if (x_.box.empty) {
    if (tr) {
      tr->value(sig_.b_busy, a + 1, 1);
      tr->value(sig_.b_tri, a + 1, t.index);
      tr->value(sig_.b_retire, a + 1, 1);
      tr->value(sig_.b_busy, a + 2, 0);
      tr->value(sig_.b_tri, a + 2, VcdRecorder::kX);
      tr->value(sig_.b_retire, a + 2, 0);
    }
    // B: retires in a + 1; the port takes the next triangle in the same cycle.
    ++empty_;
    ++box_stage.counters.busy;
    rec.first_span_cycle = rec.done_cycle = a + 1;
    rec.setup_done_cycle = rec.handoff_cycle = a + 1;
    rec.walk_start_cycle = rec.walk_end_cycle = a + 1;
    return a + 1;
  } else {
    const uint64_t k = Improved2BoxStageSc::take(a, c_free_);  // B -> C
    const uint64_t cr = corner_stage.ready(k, x_);
    const uint64_t m = std::max(cr, l_free_);  // C -> L
    const uint64_t ready = Improved2JobStageSc::ready(m, x_);
    const uint64_t h = std::max(ready, w_free_);  // L -> W (hand-off)
    if (tr) trace_job(*tr, t.index, a, k, cr, m, ready, h);
    box_stage.counters.busy += k - a;
    box_stage.counters.stall += k - (a + 1);
    corner_stage.counters.busy += m - k;
    corner_stage.counters.stall += m - cr;
    job_stage.counters.busy += h - m;
    job_stage.counters.stall += h - ready;
    ++(x_.tiny ? tiny_ : lanes_);
    for (int e = 0; e < 3; ++e) {
      job_stage.lane_busy[e] += x_.lane[e].cycles;
      rec.divider_iterations += x_.lane[e].iterations;
      rec.boundary_steps += uint64_t(x_.lane[e].steps);
    }
    iterations_ += rec.divider_iterations;
    steps_ += rec.boundary_steps;
    rec.box_width = uint64_t(x_.box.Xmax) + 1;
    rec.box_height = uint64_t(x_.box.Ymax) + 1;
    rec.setup_done_cycle = ready;
    rec.handoff_cycle = h;
    rec.walk_start_cycle = h + 1;
    const uint64_t last = walk(t, x_, pos, h, rec, tr);
    rec.walk_end_cycle = last;
    // A job without spans retires in its last walk cycle.
    if (rec.spans == 0) rec.first_span_cycle = rec.done_cycle = last;
    c_free_ = m;
    l_free_ = h;
    w_free_ = last + 1;
    return k;
  }
}

void Improved2UnitSc::add_counters(std::map<std::string, uint64_t>& work) const {
  add_counter(work, "busy_cycles.box_stage", box_stage.counters.busy);
  add_counter(work, "stall_cycles.box_stage", box_stage.counters.stall);
  add_counter(work, "busy_cycles.corner_stage", corner_stage.counters.busy);
  add_counter(work, "stall_cycles.corner_stage", corner_stage.counters.stall);
  add_counter(work, "busy_cycles.job_stage", job_stage.counters.busy);
  add_counter(work, "stall_cycles.job_stage", job_stage.counters.stall);
  for (int k = 0; k < 3; ++k)
    add_counter(work, "busy_cycles.lane" + std::to_string(k), job_stage.lane_busy[k]);
  add_counter(work, "busy_cycles.walk", walk_stage.counters.busy);
  add_counter(work, "stall_cycles.walk", walk_stage.counters.stall);
  add_counter(work, "busy_cycles.span_fifo", fifo.valid_cycles());
  add_counter(work, "busy_cycles.span_sink", sink.counters().busy);
  add_counter(work, "stall_cycles.span_sink", sink.counters().stall);
  add_counter(work, "empty_boxes", empty_);
  add_counter(work, "tiny_boxes", tiny_);
  add_counter(work, "lane_boxes", lanes_);
  add_counter(work, "divider_iterations", iterations_);
  add_counter(work, "boundary_steps", steps_);
  add_counter(work, "rows_visited", rows_);
}

}  // namespace trirast::sc

namespace trirast {
namespace {
const int kUnit = sc::register_sc_unit(
    {"improved2",
     [](const char* name, const RasterConfig& cfg, const sc_core::sc_time& period) {
       return std::unique_ptr<sc::RasterUnitSc>(new sc::Improved2UnitSc(name, cfg, period));
     },
     [](const RasterConfig& cfg) { Improved2Unit check(cfg); }});
}  // namespace

std::unique_ptr<Engine> make_improved2_sc_engine() { return sc::make_sc_engine(kUnit); }

}  // namespace trirast
