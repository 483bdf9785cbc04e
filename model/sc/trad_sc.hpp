// The SystemC model of the traditional-Bresenham unit (docs/timing.md, "The traditional unit"):
//
//   source -> setup stage (vertex quantizer + sorter, line set-up) -> hand-off -> walk stage
//             (long-edge and short-side Bresenham walkers, span filler) -> span_fifo -> span_sink
//
// The datapath is model/unit/trad_bresenham (spans) and model/unit/trad_timing (steps per row);
// the FIFO, the sink and the hand-off are the improved unit's.
#pragma once
#include <memory>
#include <systemc>

#include "sc/handoff.hpp"
#include "sc/span_fifo.hpp"
#include "unit/trad_bresenham.hpp"

namespace trirast::sc {

// A set-up triangle of the traditional unit: its sorted integer vertices.
struct TradSetupTxn {
  size_t pos = 0;
  TradVertices verts{};
};

struct TradTraceSignals {
  int setup_tri = -1, setup_state = -1, setup_accept = -1;
  int walk_tri = -1, walk_state = -1, walk_stall = -1, walk_row = -1;
  SpanTraceSignals span;
};

enum TradSetupState : uint64_t { StTradIdle = 0, StSort = 1, StLine = 2, StTradHold = 4 };

class TradSetupStage : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(TradSetupStage);
  explicit TradSetupStage(sc_core::sc_module_name name);
  sc_core::sc_port<HandoffPutIf<TradSetupTxn>> out;
  void begin_run(RunState* run, const TradTraceSignals& sig);
  StageCounters counters;

 private:
  void thread();
  void process_run();
  RunState* run_ = nullptr;
  TradTraceSignals sig_;
  bool pending_ = false;
  sc_core::sc_event start_ev_;
  std::unique_ptr<TradVertexQuantizer> quantizer_;
  TradSetupTxn txn_[2];
  int cur_ = 0;
};

class TradWalkStage : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(TradWalkStage);
  explicit TradWalkStage(sc_core::sc_module_name name);
  sc_core::sc_port<HandoffGetIf<TradSetupTxn>> in;
  sc_core::sc_port<SpanPushIf> spans;
  void begin_run(RunState* run, const TradTraceSignals& sig);
  StageCounters counters;
  uint64_t steps_long = 0, steps_short = 0;  // Bresenham steps of the two walkers

 private:
  void thread();
  uint64_t walk(TradSetupTxn& x, uint64_t h);
  RunState* run_ = nullptr;
  TradTraceSignals sig_;
  std::unique_ptr<TradSpanFiller> filler_;
  SpanList row_spans_;
};

class TradUnitSc : public sc_core::sc_module {
 public:
  explicit TradUnitSc(sc_core::sc_module_name name);
  void run(RunState& run);

  SpanSink sink;
  SpanFifo fifo;
  Handoff<TradSetupTxn> handoff;
  TradSetupStage setup;
  TradWalkStage walk;
};

}  // namespace trirast::sc
