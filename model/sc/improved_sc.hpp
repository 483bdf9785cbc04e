// The SystemC model of the improved-Bresenham unit (docs/timing.md, docs/sc-model.md).
//
//   source -> setup stage (interface, edge_lane x3: edge_normalizer + adder_divider + boundary
//             traversal) -> hand-off -> walk stage (edge_walker x3, span_generator) -> span_fifo
//             -> span_sink
//
// Every module calls the bit-accurate datapath of model/unit/ (the arithmetic exists once) and
// advances time by the cycles its hardware counterpart takes: the setup stage waits once per
// triangle, the walk stage computes a triangle's rows at once and stamps each group of N rows with
// its cycle (the FIFO knows, for any cycle, how full it is), then waits until it is idle again.
#pragma once
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "sc/handoff.hpp"
#include "sc/span_fifo.hpp"
#include "unit/adder_divider.hpp"
#include "unit/edge_normalizer.hpp"
#include "unit/edge_walker.hpp"
#include "unit/improved_unit.hpp"
#include "unit/interface.hpp"
#include "unit/span_generator.hpp"

namespace trirast::sc {

// "An edge set-up": one triangle as the setup stage hands it to the walk stage: the interface
// output, the three normalized edges and the three walkers' registers at row 0.
struct EdgeSetupTxn {
  size_t pos = 0;  // position in SetupResult::tris
  InterfaceOut iface{};
  NormalizedEdge norm[3]{};
  std::vector<EdgeWalker> walker;  // three, the registers the lanes loaded
};

// Stage 1, `interface`: bounding box and box-relative edge terms.
class InterfaceModule : public sc_core::sc_module {
 public:
  explicit InterfaceModule(sc_core::sc_module_name name) : sc_core::sc_module(name) {}
  void configure(const RasterConfig& cfg) {
    dp_ = std::make_unique<Interface>(cfg);
    counters = {};
  }
  InterfaceOut run(const TriangleSetup& t) { return dp_->run(t); }
  StageCounters counters;

 private:
  std::unique_ptr<Interface> dp_;
};

// One edge lane: edge_normalizer, its own adder_divider, and the FSM that runs the slope
// division, the boundary traversal and the entry-x division (L_k cycles).
class EdgeLane : public sc_core::sc_module {
 public:
  explicit EdgeLane(sc_core::sc_module_name name) : sc_core::sc_module(name) {}
  void configure(const RasterConfig& cfg) {
    normalizer_ = std::make_unique<EdgeNormalizer>(cfg);
    divider_ = std::make_unique<AdderDivider>(cfg);
    counters = {};
    divider_busy = 0;
  }
  const AdderDivider& divider() const { return *divider_; }
  // Normalizes edge k of the triangle and loads walker w; returns L_k, the lane's cycles.
  uint64_t run(const InterfaceOut& in, int k, uint32_t tri, NormalizedEdge& n, EdgeWalker& w) {
    n = normalizer_->run(in.edge[k], in.Xmax, tri);
    w.start(n, in.Xmax, in.Ymax, tri);
    const EdgeWork& work = w.work();
    const uint64_t L = work.boundary_steps + work.divider_iterations;
    counters.busy += L;
    divider_busy += work.divider_iterations;
    return L;
  }
  StageCounters counters;
  uint64_t divider_busy = 0;

 private:
  std::unique_ptr<EdgeNormalizer> normalizer_;
  std::unique_ptr<AdderDivider> divider_;
};

// Trace handles of the improved unit.
struct ImprovedTraceSignals {
  int setup_tri = -1, setup_state = -1, setup_accept = -1, lane_busy[3] = {-1, -1, -1};
  int walk_tri = -1, walk_state = -1, walk_stall = -1, walk_row = -1;
  SpanTraceSignals span;
};

// Setup-stage states (the trace shows these numbers).
enum SetupState : uint64_t { StIdle = 0, StBox = 1, StEdge = 2, StLanes = 3, StHold = 4 };
enum WalkState : uint64_t { StWalkIdle = 0, StWalk = 1 };

class SetupStage : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(SetupStage);
  explicit SetupStage(sc_core::sc_module_name name);

  sc_core::sc_port<HandoffTransportIf<EdgeSetupTxn>> out;

  // Prepares a run (datapath objects for cfg, counters cleared) and releases the process.
  void begin_run(RunState* run, const ImprovedTraceSignals& sig);
  StageCounters counters;
  InterfaceModule interface;
  std::unique_ptr<EdgeLane> lane[3];

 private:
  void thread();
  void process_run();

  RunState* run_ = nullptr;
  ImprovedTraceSignals sig_;
  bool pending_ = false;
  sc_core::sc_event start_ev_;
  std::unique_ptr<EdgeSetupTxn> txn_[2];  // double-buffered: the walk stage holds the other
  int cur_ = 0;
};

// The span_generator: counts the rows it combined.
class SpanGeneratorModule : public sc_core::sc_module {
 public:
  explicit SpanGeneratorModule(sc_core::sc_module_name name) : sc_core::sc_module(name) {}
  StageCounters counters;
};

// The walk stage: a target of the hand-off (WalkLoadIf). Loaded in cycle h, it computes the
// triangle's rows at once, stamps each group of N rows with its cycle, and is idle from
// t_last + 1; it needs no process of its own.
class WalkStage : public sc_core::sc_module, public WalkLoadIf<EdgeSetupTxn> {
 public:
  explicit WalkStage(sc_core::sc_module_name name);

  sc_core::sc_port<SpanPushIf> spans;

  void begin_run(RunState* run, const ImprovedTraceSignals& sig);
  // Adds the run's datapath work (summed over its triangles) into the run's work map.
  void end_run();
  uint64_t idle_from() const override { return idle_from_; }
  void load(EdgeSetupTxn* x, uint64_t h) override { idle_from_ = walk(*x, h) + 1; }
  StageCounters counters;
  SpanGeneratorModule span_generator;
  uint64_t rows_stepped[3] = {0, 0, 0};

 private:
  // Walks the triangle loaded in cycle h; returns the cycle of its last group.
  uint64_t walk(EdgeSetupTxn& x, uint64_t h);

  RunState* run_ = nullptr;
  ImprovedTraceSignals sig_;
  uint64_t idle_from_ = 0;  // the run's first cycle the stage is idle (StWalkIdle)
  TriangleWork work_sum_;   // the walked triangles' work, summed field by field
  bool any_work_ = false;   // a triangle was walked (add_work was due at least once)
};

// The whole unit. Elaborated once per process; every run goes through the same modules.
class ImprovedUnitSc : public sc_core::sc_module {
 public:
  explicit ImprovedUnitSc(sc_core::sc_module_name name);
  // Runs one scene from the current SystemC time; fills run.out (spans, cycles, work).
  void run(RunState& run);

  SpanSink sink;
  SpanFifo fifo;
  HandoffTransport<EdgeSetupTxn> handoff;
  SetupStage setup;
  WalkStage walk;
};

}  // namespace trirast::sc
