// The SystemC model of the improved-Bresenham unit (docs/timing.md, docs/sc-model.md).
//
//   source -> setup stage (interface, edge_lane x3: edge_normalizer + adder_divider + boundary
//             traversal) -> hand-off -> walk stage (edge_walker x3, span_generator) -> span_fifo
//             -> span_sink
//
// Every module calls the bit-accurate datapath of model/ (the arithmetic exists once) and
// stamps its work with the cycles its hardware counterpart takes; the process, the hand-off, the
// FIFO stalls and the trace frame are the pipeline both units share (stage_skeleton.hpp).
#pragma once
#include <memory>

#include "common/engine.hpp"
#include <map>
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "common/sc_stage_skeleton.hpp"
#include "improved/improved_adder_divider.hpp"
#include "improved/improved_edge_normalizer.hpp"
#include "improved/improved_edge_walker.hpp"
#include "improved/improved_unit.hpp"
#include "common/box_stage.hpp"
#include "improved/improved_span_generator.hpp"

namespace trirast::sc {

// "An edge set-up": one triangle as the setup stage hands it to the walk stage: the interface
// output, the three normalized edges and the three walkers' registers at row 0.
struct EdgeSetupTxn {
  size_t pos = 0;  // position in SetupResult::tris
  BoxStageOut iface{};
  NormalizedEdge norm[3]{};
  std::vector<ImprovedEdgeWalker> walker;  // three, the registers the lanes loaded
};

// Stage 1, `interface`: bounding box and box-relative edge terms.
class BoxStageSc : public sc_core::sc_module {
 public:
  explicit BoxStageSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {}
  void configure(const RasterConfig& cfg) {
    dp_ = std::make_unique<BoxStage>(cfg);
    counters = {};
  }
  BoxStageOut run(const TriangleSetup& t) { return dp_->run(t); }
  StageCounters counters;

 private:
  std::unique_ptr<BoxStage> dp_;
};

// One edge lane: edge_normalizer, its own adder_divider, and the FSM that runs the slope
// division, the boundary traversal and the entry-x division (L_k cycles).
class ImprovedEdgeLaneSc : public sc_core::sc_module {
 public:
  explicit ImprovedEdgeLaneSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {}
  void configure(const RasterConfig& cfg) {
    normalizer_ = std::make_unique<ImprovedEdgeNormalizer>(cfg);
    divider_ = std::make_unique<ImprovedAdderDivider>(cfg);
    counters = {};
    divider_busy = 0;
  }
  const ImprovedAdderDivider& divider() const { return *divider_; }
  // Normalizes edge k of the triangle and loads walker w; returns L_k, the lane's cycles.
  uint64_t run(const BoxStageOut& in, int k, uint32_t tri, NormalizedEdge& n, ImprovedEdgeWalker& w) {
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
  std::unique_ptr<ImprovedEdgeNormalizer> normalizer_;
  std::unique_ptr<ImprovedAdderDivider> divider_;
};

// The improved unit's own setup states, between StIdle and StHold (stage_skeleton.hpp).
enum ImprovedSetupState : uint64_t { StBox = 1, StEdge = 2, StLanes = 3 };

// The setup stage: a + 1 StBox (interface; an empty box retires), a + 2 StEdge (corner values,
// normalizers), from a + 3 StLanes (L = max L_k cycles), from a + 3 + L StHold.
class ImprovedSetupStageSc : public SetupStageBase<EdgeSetupTxn> {
 public:
  explicit ImprovedSetupStageSc(sc_core::sc_module_name name);
  void add_counters(std::map<std::string, uint64_t>& work) const override;
  BoxStageSc interface;
  std::unique_ptr<ImprovedEdgeLaneSc> lane[3];

 private:
  void configure(const RasterConfig& cfg) override;
  void add_unit_trace(VcdRecorder& tr) override;
  std::vector<std::pair<uint64_t, std::string>> unit_state_names() const override {
    return {{StBox, "StBox"}, {StEdge, "StEdge"}, {StLanes, "StLanes"}};
  }
  uint64_t set_up(const TriangleSetup& t, uint64_t a, EdgeSetupTxn& x) override;
  int sig_lane_busy_[3] = {-1, -1, -1};
  // Scopes interface, edge_lane0..2, adder_divider0..2 (the statistics table's modules).
  int sig_iface_busy_ = -1, sig_edge_lane_busy_[3] = {-1, -1, -1}, sig_div_iter_[3] = {-1, -1, -1};
};

// The span_generator: counts the rows it combined.
class ImprovedSpanGeneratorSc : public sc_core::sc_module {
 public:
  explicit ImprovedSpanGeneratorSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {}
  StageCounters counters;
};

// The walk stage: the three edge walkers present a group of up to N rows per cycle and the span
// generator makes their spans; a group goes when the FIFO has room for N spans.
class ImprovedWalkStageSc : public WalkStageBase<EdgeSetupTxn> {
 public:
  explicit ImprovedWalkStageSc(sc_core::sc_module_name name);
  // Adds the run's datapath work (summed over its triangles) into the run's work map.
  void add_counters(std::map<std::string, uint64_t>& work) const override;
  ImprovedSpanGeneratorSc span_generator;
  uint64_t rows_stepped[3] = {0, 0, 0};

 private:
  void configure(const RasterConfig& cfg) override;
  void add_unit_trace(VcdRecorder& tr) override;
  uint64_t walk(EdgeSetupTxn& x, uint64_t h) override;
  // Scopes edge_walker0..2 and span_generator.
  int sig_walker_busy_[3] = {-1, -1, -1}, sig_gen_busy_ = -1;

  TriangleWork work_sum_;  // the walked triangles' work, summed field by field
  bool any_work_ = false;  // a triangle was walked (add_work was due at least once)
};

// The whole unit (elaborated once per process).
using ImprovedUnitSc = PipelineUnitSc<ImprovedSetupStageSc, ImprovedWalkStageSc, EdgeSetupTxn>;

}  // namespace trirast::sc

namespace trirast {
// The improved-Bresenham unit, timed (register as "improved-sc").
std::unique_ptr<Engine> make_improved_sc_engine();
}  // namespace trirast
