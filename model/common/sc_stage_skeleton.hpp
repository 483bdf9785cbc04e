// The pipeline the improved, traditional and half-space units' SystemC models are built on
// (docs/sc-model.md):
//
//   triangle port -> setup stage -> hand-off -> walk stage -> span_fifo -> span_sink -> span port
//
// What the units share lives here once: the setup stage's acceptance (StHold, hand-off), the walk
// stage's frame (load, FIFO stalls, retire), their trace signals and counters, and the unit that
// wires the modules as a component (sc_raster_unit.hpp). A unit supplies only what its hardware
// does differently: the setup stage's datapath and cycles (SetupStageBase::set_up), the walk
// stage's rows (WalkStageBase::walk), and its own counters.
//
// Time: nothing ticks. The unit takes a triangle in the producer's transport call and computes
// its way through at once: the setup stage stamps every event with its cycle, the hand-off calls
// the walk stage (handoff.hpp), and the FIFO knows each span's pop cycle when it is pushed
// (span_fifo.hpp). SystemC time is the producer's to keep (a loosely-timed initiator's quantum).
#pragma once
#include <algorithm>
#include <cstdint>
#include <exception>
#include <map>
#include <string>
#include <systemc>
#include <vector>

#include "common/sc_handoff.hpp"
#include "common/sc_raster_unit.hpp"
#include "common/sc_span_fifo.hpp"
#include "common/sc_vcd_trace.hpp"

namespace trirast::sc {

// Setup-stage states of both units (the trace shows these numbers); a unit's own states are
// 1..3 (improved: StBox, StEdge, StLanes; trad: StSort, StLine).
enum SetupState : uint64_t { StIdle = 0, StHold = 4 };
enum WalkState : uint64_t { StWalkIdle = 0, StWalk = 1 };

// Adds `v` to the work counter `key` of a run's result.
inline void add_counter(std::map<std::string, uint64_t>& work, const std::string& key, uint64_t v) {
  work[key] += v;
}

// ---- setup stage -------------------------------------------------------------------------------

// The setup stage: accepts a triangle in cycle a, runs the unit's datapath (set_up), holds the
// triangle in StHold until the walk stage takes it, and accepts the next one the cycle after the
// hand-off (or in a + 2 when the triangle retires in a + 1 without a hand-off). `Txn` is the
// hand-off registers; it has a field `pos` (the triangle's position in the run's list).
template <class Txn>
class SetupStageBase : public sc_core::sc_module {
 public:
  explicit SetupStageBase(sc_core::sc_module_name name) : sc_core::sc_module(name), out("out") {}

  sc_core::sc_port<HandoffIf<Txn>> out;
  StageCounters counters;

  // Declares the stage's trace signals (scope "setup"): tri, state, tri_accept, then the unit's.
  void add_trace(VcdRecorder& tr) {
    sig_tri_ = tr.add("setup", "tri", 32, VcdRecorder::kX);
    sig_state_ = tr.add("setup", "state", 3, StIdle);
    // The state by name in GTKWave: the RTL's enum names (StIdle, the unit's, StHold).
    std::vector<std::pair<uint64_t, std::string>> names = {{StIdle, "StIdle"}};
    for (const auto& n : unit_state_names()) names.push_back(n);
    names.emplace_back(StHold, "StHold");
    tr.name_values(sig_state_, "setup_state", names);
    sig_accept_ = tr.add("setup", "tri_accept", 1, 0);
    add_unit_trace(tr);
  }
  // Prepares a stream (the unit's datapath for its configuration, counters cleared).
  void begin_run(RunState* run) {
    run_ = run;
    counters = {};
    configure(run->cfg);
    cur_ = 0;
  }
  // The run's work counters: the stage's, then the unit's own.
  virtual void add_counters(std::map<std::string, uint64_t>& work) const {
    add_counter(work, "busy_cycles.setup", counters.busy);
    add_counter(work, "stall_cycles.setup", counters.stall);
  }

 protected:
  // set_up()'s answer for a triangle that retires in a + 1 without a hand-off.
  static constexpr uint64_t kRetired = ~uint64_t(0);

  // The unit's datapath objects for a run's configuration; clears the unit's counters.
  virtual void configure(const RasterConfig& cfg) = 0;
  // Declares the unit's own setup signals (after tri_accept).
  virtual void add_unit_trace(VcdRecorder&) {}
  // The unit's own setup states (between StIdle and StHold) by value and name, for the trace.
  virtual std::vector<std::pair<uint64_t, std::string>> unit_state_names() const = 0;
  // The unit's datapath on triangle t, accepted in cycle a, into the hand-off registers x.
  // Reports the unit's states from a + 1 on. Returns the first StHold cycle, or kRetired.
  virtual uint64_t set_up(const TriangleSetup& t, uint64_t a, Txn& x) = 0;

  void trace_state(uint64_t cycle, uint64_t state) {
    if (VcdRecorder* tr = run_->trace) tr->value(sig_state_, cycle, state);
  }

  RunState* run_ = nullptr;
  Txn txn_[2];  // double-buffered hand-off registers: the walk stage holds the other one

 public:
  // Triangle t, at position pos of the stream, accepted in cycle a: through the stage and, at its
  // hand-off, the walk stage. Returns the first cycle the stage is idle again (the port's next
  // accept).
  uint64_t accept(const TriangleSetup& t, size_t pos, uint64_t a) {
    RunState& r = *run_;
    VcdRecorder* tr = r.trace;
    r.records.push_back(TriangleCycles{t.index, a, 0, 0, 0, 0, 0});
    TriangleCycles& rec = r.tri(pos);
    rec.setup_start_cycle = a + 1;
    if (tr) {
      tr->value(sig_accept_, a, 1);
      tr->value(sig_accept_, a + 1, 0);
      tr->value(sig_tri_, a + 1, t.index);
    }
    Txn& x = txn_[cur_];
    x.pos = pos;
    const uint64_t hold = set_up(t, a, x);
    uint64_t idle;  // the first cycle the stage is idle again
    if (hold == kRetired) {
      // The triangle retires in a + 1 (no spans, no hand-off).
      ++counters.busy;
      rec.first_span_cycle = rec.done_cycle = a + 1;
      rec.setup_done_cycle = rec.handoff_cycle = a + 1;
      rec.walk_start_cycle = rec.walk_end_cycle = a + 1;
      idle = a + 2;
    } else {
      // Busy from a + 1 until StHold; hand the triangle over in the first cycle the walk stage
      // is idle (the walk stage runs it inside this call).
      counters.busy += hold - (a + 1);
      if (tr) tr->value(sig_state_, hold, StHold);
      rec.setup_done_cycle = hold;
      const uint64_t h = out->put(&x, hold);
      counters.stall += h - hold;
      cur_ ^= 1;
      idle = h + 1;
    }
    if (tr) {
      tr->value(sig_state_, idle, StIdle);
      tr->value(sig_tri_, idle, VcdRecorder::kX);
    }
    return idle;
  }

 private:
  int sig_tri_ = -1, sig_state_ = -1, sig_accept_ = -1;
  int cur_ = 0;
};

// ---- walk stage --------------------------------------------------------------------------------

// The walk stage: the target of the hand-off. Loaded in cycle h, it runs the unit's rows at once
// (walk), each stamped with its cycle, and is idle from the cycle after its last row; it needs no
// process of its own. `row_bits` is the width of the traced row number.
template <class Txn>
class WalkStageBase : public sc_core::sc_module, public WalkLoadIf<Txn> {
 public:
  WalkStageBase(sc_core::sc_module_name name, int row_bits)
      : sc_core::sc_module(name), spans("spans"), row_bits_(row_bits) {}

  sc_core::sc_port<SpanPushIf> spans;
  StageCounters counters;

  // Declares the stage's trace signals (scope "walk"): tri, state, stall, row.
  void add_trace(VcdRecorder& tr) {
    sig_tri_ = tr.add("walk", "tri", 32, VcdRecorder::kX);
    sig_state_ = tr.add("walk", "state", 1, StWalkIdle);
    tr.name_values(sig_state_, "walk_state", {{StWalkIdle, "StWalkIdle"}, {StWalk, "StWalk"}});
    sig_stall_ = tr.add("walk", "stall", 1, 0);
    sig_row_ = tr.add("walk", "row", row_bits_, VcdRecorder::kX);
    add_unit_trace(tr);
  }
  void begin_run(RunState* run) {
    run_ = run;
    counters = {};
    idle_from_ = 0;
    configure(run->cfg);
  }
  virtual void add_counters(std::map<std::string, uint64_t>& work) const {
    add_counter(work, "busy_cycles.walk", counters.busy);
    add_counter(work, "stall_cycles.walk", counters.stall);
  }

  uint64_t idle_from() const override { return idle_from_; }
  void load(Txn* x, uint64_t h) override {
    RunState& r = *run_;
    VcdRecorder* tr = r.trace;
    TriangleCycles& rec = r.tri(x->pos);
    if (tr) {
      tr->value(sig_state_, h + 1, StWalk);
      tr->value(sig_tri_, h + 1, rec.tri);
    }
    stalls_ = 0;
    const uint64_t t_last = walk(*x, h);
    counters.stall += stalls_;
    rec.stall_cycles = stalls_;
    rec.handoff_cycle = h;
    rec.walk_start_cycle = h + 1;
    rec.walk_end_cycle = t_last;
    // A triangle without spans (the sink took none) retires in its last walk cycle.
    if (rec.spans == 0) rec.first_span_cycle = rec.done_cycle = t_last;
    if (tr) {
      tr->value(sig_state_, t_last + 1, StWalkIdle);
      tr->value(sig_tri_, t_last + 1, VcdRecorder::kX);
      tr->value(sig_row_, t_last + 1, VcdRecorder::kX);
    }
    idle_from_ = t_last + 1;
  }

 protected:
  // The unit's datapath objects for a run's configuration; clears the unit's counters.
  virtual void configure(const RasterConfig& cfg) = 0;
  // Declares the unit's own walk-side modules' signals (after the stage's).
  virtual void add_unit_trace(VcdRecorder&) {}
  // Walks triangle x, loaded in cycle h, from cycle h + 1 (each row through start_row); pushes
  // its spans into `spans` and returns the cycle of its last row.
  virtual uint64_t walk(Txn& x, uint64_t h) = 0;

  // Row `row` (n spans at most) starts in the first cycle >= t whose start finds room for n
  // spans in the FIFO; the cycles before it are stalls. Returns that cycle.
  uint64_t start_row(uint64_t t, uint64_t n, uint64_t row) {
    const uint64_t go = spans->first_room(t, n);
    VcdRecorder* tr = run_->trace;
    if (go != t) {
      stalls_ += go - t;
      if (tr) {
        tr->value(sig_stall_, t, 1);
        tr->value(sig_stall_, go, 0);
      }
    }
    if (tr) tr->value(sig_row_, go, row);
    return go;
  }

  RunState* run_ = nullptr;

 private:
  int row_bits_;
  int sig_tri_ = -1, sig_state_ = -1, sig_stall_ = -1, sig_row_ = -1;
  uint64_t idle_from_ = 0;  // the run's first cycle the stage is idle (StWalkIdle)
  uint64_t stalls_ = 0;     // the current triangle's stall cycles
};

// ---- the unit ----------------------------------------------------------------------------------

// A unit: its setup and walk stages (Setup derives from SetupStageBase, Walk from
// WalkStageBase, over one Txn), the hand-off between them, the span FIFO and the sink, as a
// component (sc_raster_unit.hpp).
template <class Setup, class Walk, class Txn>
class PipelineUnitSc : public RasterUnitSc {
 public:
  PipelineUnitSc(sc_core::sc_module_name name, const RasterConfig& cfg,
                 const sc_core::sc_time& period)
      : RasterUnitSc(name, cfg, period),
        sink("span_sink"),
        fifo("span_fifo", sink),
        handoff("handoff"),
        setup("setup"),
        walk("walk") {
    setup.out(handoff);
    handoff.walk(walk);
    walk.spans(fifo);
    start(cfg);
  }

  SpanSink sink;
  SpanFifo fifo;
  Handoff<Txn> handoff;
  Setup setup;
  Walk walk;

 protected:
  void begin_stream() override {
    RunState& r = state_;
    SpanTraceSignals span;
    if (VcdRecorder* tr = r.trace) {
      // Declaration order is the VCD's order: setup (and the unit's setup-side modules), walk (and
      // the unit's walk-side modules), span, span_fifo, span_sink: every module of the statistics.
      setup.add_trace(*tr);
      walk.add_trace(*tr);
      span.valid = tr->add("span", "valid", 1, 0);
      span.ready = tr->add("span", "ready", 1, 1);
      span.tri = tr->add("span", "tri", 32, VcdRecorder::kX);
      span.y = tr->add("span", "y", 16, VcdRecorder::kX);
      span.x_begin = tr->add("span", "x_begin", 16, VcdRecorder::kX);
      span.x_end = tr->add("span", "x_end", 16, VcdRecorder::kX);
      span.count = tr->add("span_fifo", "count", 11, 0, true);
      span.take = tr->add("span_sink", "take", 1, 0);
    }
    sink.begin_run(&r);
    fifo.begin_run(&r, span);
    walk.begin_run(&r);
    setup.begin_run(&r);
  }
  uint64_t accept(const TriangleSetup& t, size_t pos, uint64_t a) override {
    return setup.accept(t, pos, a);
  }
  uint64_t unit_idle_from() const override { return walk.idle_from(); }
  void add_counters(std::map<std::string, uint64_t>& work) const override {
    setup.add_counters(work);
    walk.add_counters(work);
    add_counter(work, "busy_cycles.span_fifo", fifo.valid_cycles());
    add_counter(work, "busy_cycles.span_sink", sink.counters().busy);
    add_counter(work, "stall_cycles.span_sink", sink.counters().stall);
  }
};

}  // namespace trirast::sc
