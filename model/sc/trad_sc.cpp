#include "sc/trad_sc.hpp"

#include "unit/trad_timing.hpp"

namespace trirast::sc {

using sc_core::sc_module_name;

// ---- setup stage: a accept, a+1 StSort (quantize, sort; collinear retires), a+2 StLine,
// ---- from a+3 StHold until the walk stage is idle.

TradSetupStage::TradSetupStage(sc_module_name name) : sc_core::sc_module(name), out("out") {
  SC_THREAD(thread);
}

void TradSetupStage::begin_run(RunState* run, const TradTraceSignals& sig) {
  run_ = run;
  sig_ = sig;
  counters = {};
  quantizer_ = std::make_unique<TradVertexQuantizer>(run->cfg);
  cur_ = 0;
  pending_ = true;
  start_ev_.notify(sc_core::SC_ZERO_TIME);
}

void TradSetupStage::thread() {
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

void TradSetupStage::process_run() {
  RunState& r = *run_;
  VcdRecorder* tr = r.trace;
  const std::vector<TriangleSetup>& tris = r.setup->tris;
  uint64_t a = r.now();
  for (size_t pos = 0; pos < tris.size() && !r.error; ++pos) {
    r.wait_until(a);
    const TriangleSetup& t = tris[pos];
    TriangleCycles& rec = r.tri(pos);
    rec = TriangleCycles{t.index, a, 0, 0, 0, 0, 0};
    if (tr) {
      tr->value(sig_.setup_accept, a, 1);
      tr->value(sig_.setup_accept, a + 1, 0);
      tr->value(sig_.setup_tri, a + 1, t.index);
      tr->value(sig_.setup_state, a + 1, StSort);
    }
    TradSetupTxn& x = txn_[cur_];
    x.pos = pos;
    x.verts = quantizer_->run(t);
    if (x.verts.empty) {  // collinear integer vertices: retires in a + 1
      ++counters.busy;
      ++r.out->work["trad_collinear"];  // never reaches the walk stage's add_trad_work
      rec.first_span_cycle = rec.done_cycle = a + 1;
      if (tr) {
        tr->value(sig_.setup_state, a + 2, StTradIdle);
        tr->value(sig_.setup_tri, a + 2, VcdRecorder::kX);
      }
      a += 2;
      continue;
    }
    counters.busy += 2;
    if (tr) {
      tr->value(sig_.setup_state, a + 2, StLine);
      tr->value(sig_.setup_state, a + 3, StTradHold);
    }
    r.wait_until(a + 3);
    out->put(&x);
    const uint64_t h = r.now();
    counters.stall += h - (a + 3);
    cur_ ^= 1;
    if (tr) {
      tr->value(sig_.setup_state, h + 1, StTradIdle);
      tr->value(sig_.setup_tri, h + 1, VcdRecorder::kX);
    }
    a = h + 1;
  }
}

// ---- walk stage: rows p0.y .. p2.y, row y costs max(1, long steps, short steps) cycles and
// ---- starts only when the FIFO has room for one span at the start of its first cycle.

TradWalkStage::TradWalkStage(sc_module_name name)
    : sc_core::sc_module(name), in("in"), spans("spans") {
  SC_THREAD(thread);
}

void TradWalkStage::begin_run(RunState* run, const TradTraceSignals& sig) {
  run_ = run;
  sig_ = sig;
  counters = {};
  steps_long = steps_short = 0;
  filler_ = std::make_unique<TradSpanFiller>(run->cfg);
}

void TradWalkStage::thread() {
  for (;;) {
    TradSetupTxn* x = in->get();
    RunState& r = *run_;
    if (r.error) continue;
    uint64_t t_last;
    try {
      t_last = walk(*x, r.now());
    } catch (...) {
      if (!r.error) r.error = std::current_exception();
      continue;
    }
    r.wait_until(t_last + 1);
  }
}

uint64_t TradWalkStage::walk(TradSetupTxn& x, uint64_t h) {
  RunState& r = *run_;
  VcdRecorder* tr = r.trace;
  const TriangleSetup& t = r.setup->tris[x.pos];
  TriangleCycles& rec = r.tri(x.pos);
  // The datapath: the spans of the rows inside the viewport, in row order.
  row_spans_.clear();
  const TradTriangleResult res = filler_->run_triangle(t, row_spans_);
  add_trad_work(res, r.out->work);
  const TradWalkTiming timing(x.verts);
  if (tr) {
    tr->value(sig_.walk_state, h + 1, 1);
    tr->value(sig_.walk_tri, h + 1, t.index);
  }
  uint64_t t_now = h + 1, stalls = 0;
  size_t next_span = 0;
  for (int64_t y = timing.first_row(); y <= timing.last_row(); ++y) {
    const uint64_t go = spans->first_room(t_now, 1);
    if (go != t_now) {
      stalls += go - t_now;
      if (tr) {
        tr->value(sig_.walk_stall, t_now, 1);
        tr->value(sig_.walk_stall, go, 0);
      }
      t_now = go;
    }
    if (tr) tr->value(sig_.walk_row, t_now, uint64_t(y - timing.first_row()));
    const uint64_t l = timing.steps_on_row(0, y);
    const uint64_t s = timing.steps_on_row(1, y) + timing.steps_on_row(2, y);
    steps_long += l;
    steps_short += s;
    const uint64_t c = std::max<uint64_t>(1, std::max(l, s));
    const uint64_t end = t_now + c - 1;  // the row's span is pushed at the end of its last cycle
    if (next_span < row_spans_.size() && row_spans_[next_span].y == y)
      spans->push(row_spans_[next_span++], x.pos, end);
    counters.busy += c;
    t_now = end + 1;
  }
  const uint64_t t_last = t_now - 1;
  counters.stall += stalls;
  rec.stall_cycles = stalls;
  if (res.spans == 0) rec.first_span_cycle = rec.done_cycle = t_last;
  if (tr) {
    tr->value(sig_.walk_state, t_last + 1, 0);
    tr->value(sig_.walk_tri, t_last + 1, VcdRecorder::kX);
    tr->value(sig_.walk_row, t_last + 1, VcdRecorder::kX);
  }
  return t_last;
}

// ---- the unit ----

TradUnitSc::TradUnitSc(sc_module_name name)
    : sc_core::sc_module(name),
      sink("span_sink"),
      fifo("span_fifo", sink),
      handoff("handoff"),
      setup("setup"),
      walk("walk") {
  setup.out(handoff);
  walk.in(handoff);
  walk.spans(fifo);
}

void TradUnitSc::run(RunState& r) {
  TradTraceSignals sig;
  if (VcdRecorder* tr = r.trace) {
    sig.setup_tri = tr->add("setup", "tri", 32, VcdRecorder::kX);
    sig.setup_state = tr->add("setup", "state", 3, StTradIdle);
    sig.setup_accept = tr->add("setup", "tri_accept", 1, 0);
    sig.walk_tri = tr->add("walk", "tri", 32, VcdRecorder::kX);
    sig.walk_state = tr->add("walk", "state", 1, 0);
    sig.walk_stall = tr->add("walk", "stall", 1, 0);
    sig.walk_row = tr->add("walk", "row", 17, VcdRecorder::kX);
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
}

}  // namespace trirast::sc
