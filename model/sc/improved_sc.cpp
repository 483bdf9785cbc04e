#include "sc/improved_sc.hpp"

#include <algorithm>

#include "unit/improved_unit.hpp"

namespace trirast::sc {

using sc_core::sc_module_name;

namespace {
// The setup stage synchronizes with SystemC time at least once per this many cycles.
constexpr uint64_t kQuantumCycles = uint64_t(1) << 16;
}  // namespace

// ---- setup stage -------------------------------------------------------------------------------

SetupStage::SetupStage(sc_module_name name)
    : sc_core::sc_module(name), out("out"), interface("interface") {
  for (int k = 0; k < 3; ++k)
    lane[k] = std::make_unique<EdgeLane>(("edge_lane" + std::to_string(k)).c_str());
  SC_THREAD(thread);
}

void SetupStage::begin_run(RunState* run, const ImprovedTraceSignals& sig) {
  run_ = run;
  sig_ = sig;
  counters = {};
  interface.configure(run->cfg);
  for (auto& l : lane) l->configure(run->cfg);
  for (auto& t : txn_) {
    t = std::make_unique<EdgeSetupTxn>();
    t->walker.reserve(3);
    for (int k = 0; k < 3; ++k) t->walker.emplace_back(run->cfg, lane[k]->divider());
  }
  cur_ = 0;
  pending_ = true;
  start_ev_.notify(sc_core::SC_ZERO_TIME);
}

void SetupStage::thread() {
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

void SetupStage::process_run() {
  RunState& r = *run_;
  VcdRecorder* tr = r.trace;
  const std::vector<TriangleSetup>& tris = r.setup->tris;
  uint64_t a = r.now();  // the cycle the next triangle is accepted in
  for (size_t pos = 0; pos < tris.size() && !r.error; ++pos) {
    // The stage keeps its own cycle a (the accept) ahead of SystemC time; the walk stage is
    // called in this process at the hand-off (HandoffTransport).
    const TriangleSetup& t = tris[pos];
    TriangleCycles& rec = r.tri(pos);
    rec = TriangleCycles{t.index, a, 0, 0, 0, 0, 0};
    if (tr) {
      tr->value(sig_.setup_accept, a, 1);
      tr->value(sig_.setup_accept, a + 1, 0);
      tr->value(sig_.setup_tri, a + 1, t.index);
      tr->value(sig_.setup_state, a + 1, StBox);
    }
    // a + 1, StBox: the interface's bounding box; an empty box retires here.
    EdgeSetupTxn& x = *txn_[cur_];
    x.pos = pos;
    x.iface = interface.run(t);
    if (x.iface.empty) {
      ++interface.counters.busy;
      ++counters.busy;
      rec.first_span_cycle = rec.done_cycle = a + 1;
      if (tr) {
        tr->value(sig_.setup_state, a + 2, StIdle);
        tr->value(sig_.setup_tri, a + 2, VcdRecorder::kX);
      }
      a += 2;
      continue;
    }
    // a + 2, StEdge: corner values and normalizers; a + 3 on, StLanes: L_k cycles per lane.
    uint64_t L = 0, Lk[3];
    for (int k = 0; k < 3; ++k) {
      Lk[k] = lane[k]->run(x.iface, k, t.index, x.norm[k], x.walker[k]);
      L = std::max(L, Lk[k]);
    }
    interface.counters.busy += 2;
    counters.busy += 2 + L;
    if (tr) {
      tr->value(sig_.setup_state, a + 2, StEdge);
      tr->value(sig_.setup_state, a + 3, StLanes);
      for (int k = 0; k < 3; ++k)
        if (Lk[k] > 0) {
          tr->value(sig_.lane_busy[k], a + 3, 1);
          tr->value(sig_.lane_busy[k], a + 3 + Lk[k], 0);
        }
      tr->value(sig_.setup_state, a + 3 + L, StHold);
    }
    // From a + 3 + L, StHold: hand the triangle over in the first cycle the walk stage is idle.
    const uint64_t h = out->put(&x, a + 3 + L);
    counters.stall += h - (a + 3 + L);
    cur_ ^= 1;
    if (tr) {
      tr->value(sig_.setup_state, h + 1, StIdle);
      tr->value(sig_.setup_tri, h + 1, VcdRecorder::kX);
    }
    // Temporal decoupling: the stage runs ahead of SystemC time (every cycle is stamped on the
    // data) and synchronizes once per quantum.
    if (h + 1 >= r.now() + kQuantumCycles) r.wait_until(h + 1);
    a = h + 1;
  }
  // The run ends in SystemC time when the unit's last stage is idle.
  r.wait_until(std::max(a, out->walk_idle_from()));
}

// ---- walk stage --------------------------------------------------------------------------------

WalkStage::WalkStage(sc_module_name name)
    : sc_core::sc_module(name), spans("spans"), span_generator("span_generator") {}

void WalkStage::begin_run(RunState* run, const ImprovedTraceSignals& sig) {
  run_ = run;
  sig_ = sig;
  counters = {};
  span_generator.counters = {};
  for (auto& r : rows_stepped) r = 0;
  work_sum_ = TriangleWork{};
  any_work_ = false;
  idle_from_ = 0;
}

void WalkStage::end_run() {
  if (any_work_) add_work(work_sum_, run_->out->work);
}

uint64_t WalkStage::walk(EdgeSetupTxn& x, uint64_t h) {
  RunState& r = *run_;
  VcdRecorder* tr = r.trace;
  const uint64_t N = uint64_t(r.cfg.endpoints);
  const InterfaceOut& in_ = x.iface;
  const uint32_t tri = in_.tri;
  TriangleCycles& rec = r.tri(x.pos);
  TriangleWork work;
  if (tr) {
    tr->value(sig_.walk_state, h + 1, StWalk);
    tr->value(sig_.walk_tri, h + 1, tri);
  }
  uint64_t t = h + 1, t_last = h, stalls = 0;
  int64_t j = 0;
  while (j <= in_.Ymax) {
    // A group goes when the FIFO held at most DEPTH - N spans at the start of the cycle.
    const uint64_t go = spans->first_room(t, N);
    if (go != t) {
      stalls += go - t;
      if (tr) {
        tr->value(sig_.walk_stall, t, 1);
        tr->value(sig_.walk_stall, go, 0);
      }
      t = go;
    }
    if (tr) tr->value(sig_.walk_row, t, uint64_t(j));
    // The walkers present up to N rows; the span generator makes their spans, pushed in row order.
    for (uint64_t n = 0; n < N && j <= in_.Ymax; ++n, ++j) {
      const WalkerRow bound[3] = {x.walker[0].row(), x.walker[1].row(), x.walker[2].row()};
      const SpanGenOut g = SpanGenerator::row(x.norm, bound, in_.Xmax);
      ++work.rows_visited;
      if (g.valid) {
        spans->push(SpanGenerator::to_span(g, tri, in_.x0, in_.y0, j), x.pos, t);
        ++work.spans;
        work.pixels += uint64_t(g.end - g.begin);
      }
      if (j < in_.Ymax)
        for (EdgeWalker& w : x.walker) w.advance();
    }
    ++counters.busy;
    ++span_generator.counters.busy;
    t_last = t++;
  }
  counters.stall += stalls;
  rec.stall_cycles = stalls;
  if (work.spans == 0) rec.first_span_cycle = rec.done_cycle = t_last;  // retires in t_last
  if (tr) {
    tr->value(sig_.walk_state, t_last + 1, StWalkIdle);
    tr->value(sig_.walk_tri, t_last + 1, VcdRecorder::kX);
    tr->value(sig_.walk_row, t_last + 1, VcdRecorder::kX);
  }
  for (int k = 0; k < 3; ++k) {
    work.edge[k] = x.walker[k].work();
    rows_stepped[k] += work.edge[k].rows_stepped;
  }
  // add_work() goes through a string-keyed map: once per run (end_run), not per triangle.
  for (int k = 0; k < 3; ++k) {
    work_sum_.edge[k].divisions += work.edge[k].divisions;
    work_sum_.edge[k].divider_iterations += work.edge[k].divider_iterations;
    work_sum_.edge[k].boundary_steps += work.edge[k].boundary_steps;
    work_sum_.edge[k].rows_stepped += work.edge[k].rows_stepped;
  }
  work_sum_.rows_visited += work.rows_visited;
  work_sum_.spans += work.spans;
  work_sum_.pixels += work.pixels;
  any_work_ = true;
  return t_last;
}

// ---- the unit ----------------------------------------------------------------------------------

ImprovedUnitSc::ImprovedUnitSc(sc_module_name name)
    : sc_core::sc_module(name),
      sink("span_sink"),
      fifo("span_fifo", sink),
      handoff("handoff"),
      setup("setup"),
      walk("walk") {
  setup.out(handoff);
  handoff.walk(walk);
  walk.spans(fifo);
}

void ImprovedUnitSc::run(RunState& r) {
  ImprovedTraceSignals sig;
  if (VcdRecorder* tr = r.trace) {
    sig.setup_tri = tr->add("setup", "tri", 32, VcdRecorder::kX);
    sig.setup_state = tr->add("setup", "state", 3, StIdle);
    sig.setup_accept = tr->add("setup", "tri_accept", 1, 0);
    for (int k = 0; k < 3; ++k)
      sig.lane_busy[k] = tr->add("setup", "lane" + std::to_string(k) + "_busy", 1, 0);
    sig.walk_tri = tr->add("walk", "tri", 32, VcdRecorder::kX);
    sig.walk_state = tr->add("walk", "state", 1, StWalkIdle);
    sig.walk_stall = tr->add("walk", "stall", 1, 0);
    sig.walk_row = tr->add("walk", "row", 16, VcdRecorder::kX);
    sig.span.valid = tr->add("span", "valid", 1, 0);
    sig.span.ready = tr->add("span", "ready", 1, 1);
    sig.span.tri = tr->add("span", "tri", 32, VcdRecorder::kX);
    sig.span.y = tr->add("span", "y", 16, VcdRecorder::kX);
    sig.span.x_begin = tr->add("span", "x_begin", 16, VcdRecorder::kX);
    sig.span.x_end = tr->add("span", "x_end", 16, VcdRecorder::kX);
    sig.span.count = tr->add("span_fifo", "count", 11, 0, true);
  }
  sink.begin_run(&r);
  fifo.begin_run(&r, sig.span);
  walk.begin_run(&r, sig);
  setup.begin_run(&r, sig);
  sc_core::sc_start();
  walk.end_run();
}

}  // namespace trirast::sc
