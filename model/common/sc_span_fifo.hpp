// The span FIFO and the span sink (docs/timing.md, "Span FIFO and sink"), shared by every unit's
// SystemC model.
//
// Both are exact without an event per cycle: the downstream's ready is a function of the cycle and
// of the spans it took before (span_downstream.hpp), so the cycle a span leaves is known when it is
// pushed: span i is on the output from avail_i = max(push_i + 1, pop_(i-1) + 1) and popped in the
// first cycle >= avail_i in which the downstream is ready, where it hands the span over. The FIFO
// keeps the pop cycles of the spans still inside it; the walk stage asks it for the occupancy at
// the start of a cycle and for the first cycle with room for N more spans.
#pragma once
#include <algorithm>
#include <cstdint>
#include <exception>
#include <map>
#include <string>
#include <systemc>
#include <vector>

#include "common/config.hpp"
#include "common/engine.hpp"
#include "common/setup.hpp"
#include "common/span_downstream.hpp"
#include "common/sc_vcd_trace.hpp"

namespace trirast::sc {

// The trace handles of the span output (scope "span"), the FIFO (scope "span_fifo") and the
// sink (scope "span_sink").
struct SpanTraceSignals {
  int valid = -1, ready = -1, tri = -1, y = -1, x_begin = -1, x_end = -1, count = -1;
  int take = -1;  // scope "span_sink": the sink takes a span in this cycle
};

// What one stream shares between a unit's modules: configuration, the downstream, the
// per-triangle records and work counters, the trace, the first error.
struct RunState {
  RasterConfig cfg;
  SpanDownstream* downstream = nullptr;  // the unit's span port's downstream
  std::vector<TriangleCycles> records;   // one per accepted triangle, in acceptance order
  std::map<std::string, uint64_t> work;  // the datapath's counters (the modules' are their own)
  VcdRecorder* trace = nullptr;          // null: no trace
  std::exception_ptr error;              // the first triangle the unit could not take

  TriangleCycles& tri(size_t pos) { return records[pos]; }
};

// Per-module statistics of one run, added into EngineResult::work at the end.
struct StageCounters {
  uint64_t busy = 0;   // cycles the module did work
  uint64_t stall = 0;  // cycles it held work but could not advance
};

// The span sink: the unit's end of the span port. Records each span's triangle's first and last
// pop and hands the span to the downstream in its pop cycle.
class SpanSink : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(SpanSink);
  explicit SpanSink(sc_core::sc_module_name name) : sc_core::sc_module(name) {}

  void begin_run(RunState* run) {
    run_ = run;
    counters_ = StageCounters{};
  }
  // Span of the triangle at setup position `pos`, popped in cycle `pop` after waiting `waited`
  // cycles on the output with ready low.
  void take(const Span& s, size_t pos, uint64_t pop, uint64_t waited) {
    TriangleCycles& t = run_->tri(pos);
    if (t.spans == 0) t.first_span_cycle = pop;
    t.done_cycle = pop;
    ++t.spans;
    t.pixels += uint64_t(s.pixels());
    run_->downstream->take(s, pop);
    ++counters_.busy;
    counters_.stall += waited;
  }
  const StageCounters& counters() const { return counters_; }

 private:
  RunState* run_ = nullptr;
  StageCounters counters_;
};

// The walk stage's port onto the span FIFO.
class SpanPushIf : public virtual sc_core::sc_interface {
 public:
  // First cycle >= t whose start-of-cycle occupancy is <= DEPTH - n (room for n pushes).
  virtual uint64_t first_room(uint64_t t, uint64_t n) = 0;
  // Pushes a span of the triangle at setup position pos at the end of cycle t.
  virtual void push(const Span& s, size_t pos, uint64_t t) = 0;
};

// The span FIFO: DEPTH entries between the walk stage and the sink.
class SpanFifo : public sc_core::sc_module, public SpanPushIf {
 public:
  SC_HAS_PROCESS(SpanFifo);
  SpanFifo(sc_core::sc_module_name name, SpanSink& sink) : sc_core::sc_module(name), sink_(sink) {}

  void begin_run(RunState* run, const SpanTraceSignals& sig) {
    run_ = run;
    sig_ = sig;
    depth_ = uint64_t(run->cfg.fifo_depth);
    head_ = size_ = 0;
    last_pop_ = 0;
    any_pop_ = false;
    valid_cycles_ = 0;
    pushes_ = 0;
  }

  // Occupancy at the start of cycle t (t never decreases between calls of one run).
  uint64_t count_at(uint64_t t) {
    while (size_ > 0 && pops_[head_] < t) {
      head_ = (head_ + 1) & mask_;
      --size_;
    }
    return size_;
  }
  // First cycle >= t whose start-of-cycle occupancy is <= DEPTH - n (room for n pushes).
  uint64_t first_room(uint64_t t, uint64_t n) override {
    const uint64_t c = count_at(t);
    if (c + n <= depth_) return t;
    const uint64_t k = c + n - depth_;  // pops needed
    return pops_[(head_ + k - 1) & mask_] + 1;
  }
  // Pushes a span at the end of cycle t (t >= every earlier push's cycle).
  void push(const Span& s, size_t pos, uint64_t t) override {
    const uint64_t avail = any_pop_ ? std::max(t + 1, last_pop_ + 1) : t + 1;
    const uint64_t pop = run_->downstream->next_ready(avail);
    last_pop_ = pop;
    any_pop_ = true;
    if (size_ == pops_.size()) grow();
    pops_[(head_ + size_) & mask_] = pop;
    ++size_;
    ++pushes_;
    valid_cycles_ += pop - avail + 1;
    if (VcdRecorder* tr = run_->trace) {
      tr->delta(sig_.count, t + 1, +1);
      tr->delta(sig_.count, pop + 1, -1);
      tr->value(sig_.valid, avail, 1);
      tr->value(sig_.tri, avail, s.tri);
      tr->value(sig_.y, avail, uint64_t(uint32_t(s.y)));
      tr->value(sig_.x_begin, avail, uint64_t(uint32_t(s.x_begin)));
      tr->value(sig_.x_end, avail, uint64_t(uint32_t(s.x_end)));
      tr->value(sig_.valid, pop + 1, 0);  // overridden when the next span is there in pop + 1
      tr->value(sig_.tri, pop + 1, VcdRecorder::kX);
      tr->value(sig_.take, pop, 1);
      tr->value(sig_.take, pop + 1, 0);  // overridden by the next span's pop in pop + 1
    }
    sink_.take(s, pos, pop, pop - avail);
  }

  uint64_t valid_cycles() const { return valid_cycles_; }  // cycles with span_valid_o high
  uint64_t pushes() const { return pushes_; }

 private:
  SpanSink& sink_;
  RunState* run_ = nullptr;
  SpanTraceSignals sig_;
  uint64_t depth_ = 8;
  // Doubles the ring, its entries from index 0 on.
  void grow() {
    std::vector<uint64_t> bigger(pops_.size() * 2);
    for (size_t i = 0; i < size_; ++i) bigger[i] = pops_[(head_ + i) & mask_];
    pops_.swap(bigger);
    head_ = 0;
    mask_ = pops_.size() - 1;
  }

  // Pop cycles of the spans pushed so far and not yet known gone, oldest first: a ring of
  // pops_.size() (a power of two) entries from head_.
  std::vector<uint64_t> pops_ = std::vector<uint64_t>(64);
  size_t head_ = 0, size_ = 0, mask_ = 63;
  uint64_t last_pop_ = 0;
  bool any_pop_ = false;
  uint64_t valid_cycles_ = 0, pushes_ = 0;
};

}  // namespace trirast::sc
