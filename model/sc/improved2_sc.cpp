#include "sc/improved2_sc.hpp"

#include <algorithm>

namespace trirast::sc {

using sc_core::sc_module_name;

Improved2UnitSc::Improved2UnitSc(sc_module_name name)
    : sc_core::sc_module(name),
      sink("span_sink"),
      fifo("span_fifo", sink),
      box_stage("box_stage"),
      corner_stage("corner_stage"),
      job_stage("job_stage"),
      walk_stage("walk_stage") {
  tlm_utils::tlm_quantumkeeper::set_global_quantum(cycles_time(kQuantumCycles));
  SC_THREAD(thread);
}

void Improved2UnitSc::run(RunState& r) {
  run_ = &r;
  sink.begin_run(&r);
  fifo.begin_run(&r, SpanTraceSignals{});
  unit_ = std::make_unique<Improved2Unit>(r.cfg);
  corner_stage.configure(r.cfg.g2_corner_form);
  box_stage.counters = {};
  job_stage.counters = {};
  for (auto& b : job_stage.lane_busy) b = 0;
  walk_stage.counters = {};
  tiny_ = lanes_ = empty_ = iterations_ = steps_ = rows_ = 0;
  pending_ = true;
  start_ev_.notify(sc_core::SC_ZERO_TIME);
  sc_core::sc_start();
}

void Improved2UnitSc::thread() {
  for (;;) {
    while (!pending_) wait(start_ev_);
    pending_ = false;
    try {
      process_run();
    } catch (...) {
      if (!run_->error) run_->error = std::current_exception();
    }
    run_->finished = true;
  }
}

uint64_t Improved2UnitSc::walk(const Improved2Triangle& x, size_t pos, uint64_t h,
                               TriangleCycles& rec) {
  uint64_t t = h + 1, last = h;
  for (const Improved2Row& row : x.rows) {
    // The admission test: the FIFO's entries plus the push in flight (pushed in cycle t, whose
    // span the FIFO model already holds) leave room for one more.
    const uint64_t go = fifo.first_room(t, 1);
    rec.stall_cycles += go - t;
    if (row.valid) fifo.push(row.span, pos, go + 1);  // registered, pushed in go + 1
    last = go;
    t = go + 1;
  }
  walk_stage.counters.busy += x.rows.size();
  walk_stage.counters.stall += rec.stall_cycles;
  rows_ += x.rows.size();
  return last;
}

void Improved2UnitSc::process_run() {
  RunState& r = *run_;
  const std::vector<TriangleSetup>& tris = r.setup->tris;
  quantum_.reset();
  uint64_t a = r.now();  // the cycle the next triangle is accepted in
  uint64_t c_free = 0;   // C is free from this cycle (its last triangle's move to L)
  uint64_t l_free = 0;   // L is free from this cycle (its last job's hand-off)
  uint64_t w_free = 0;   // the walk stage is idle from this cycle
  for (size_t pos = 0; pos < tris.size(); ++pos) {
    const TriangleSetup& t = tris[pos];
    TriangleCycles& rec = r.tri(pos);
    rec = TriangleCycles{t.index, a, 0, 0, 0, 0, 0};
    rec.setup_start_cycle = a + 1;
    unit_->run_triangle(t, x_);
    if (x_.box.empty) {
      // B: retires in a + 1; the port takes the next triangle in the same cycle.
      ++empty_;
      ++box_stage.counters.busy;
      rec.first_span_cycle = rec.done_cycle = a + 1;
      rec.setup_done_cycle = rec.handoff_cycle = a + 1;
      rec.walk_start_cycle = rec.walk_end_cycle = a + 1;
      a = a + 1;
    } else {
      const uint64_t k = G2BoxStage::take(a, c_free);  // B -> C
      const uint64_t cr = corner_stage.ready(k, x_);
      const uint64_t m = std::max(cr, l_free);  // C -> L
      const uint64_t ready = G2JobStage::ready(m, x_);
      const uint64_t h = std::max(ready, w_free);  // L -> W (hand-off)
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
      const uint64_t last = walk(x_, pos, h, rec);
      rec.walk_end_cycle = last;
      // A job without spans retires in its last walk cycle.
      if (rec.spans == 0) rec.first_span_cycle = rec.done_cycle = last;
      c_free = m;
      l_free = h;
      w_free = last + 1;
      a = k;
    }
    quantum_.set_and_sync(cycles_time(a - std::min(a, r.now())));
  }
  quantum_.set(cycles_time(std::max(a, w_free) - std::min(std::max(a, w_free), r.now())));
  quantum_.sync();
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
