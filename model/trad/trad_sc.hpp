// The SystemC model of the traditional-Bresenham unit (docs/timing.md, "The traditional unit"):
//
//   source -> setup stage (vertex quantizer + sorter, line set-up) -> hand-off -> walk stage
//             (long-edge and short-side Bresenham walkers, span filler) -> span_fifo -> span_sink
//
// The datapath is model/trad_bresenham (spans) and model/trad_timing (steps per row);
// the process, the hand-off, the FIFO, the sink and the trace frame are the pipeline both units
// share (stage_skeleton.hpp).
#pragma once
#include <memory>

#include "common/engine.hpp"
#include <map>
#include <memory>
#include <string>
#include <systemc>

#include "common/sc_stage_skeleton.hpp"
#include "trad/trad_bresenham.hpp"

namespace trirast::sc {

// A set-up triangle of the traditional unit: its sorted integer vertices.
struct TradSetupTxn {
  size_t pos = 0;  // position in the stream
  const TriangleSetup* tri = nullptr;  // the triangle (its walk runs inside its transport call)
  TradVertices verts{};
};

// The traditional unit's own setup states, between StIdle and StHold (stage_skeleton.hpp).
enum TradSetupState : uint64_t { StSort = 1, StLine = 2 };

// The setup stage: a + 1 StSort (quantize and sort; collinear vertices retire), a + 2 StLine
// (the three lines' set-up), from a + 3 StHold.
class TradSetupStage : public SetupStageBase<TradSetupTxn> {
 public:
  explicit TradSetupStage(sc_core::sc_module_name name) : SetupStageBase<TradSetupTxn>(name) {}
  void add_counters(std::map<std::string, uint64_t>& work) const override;

 private:
  void configure(const RasterConfig& cfg) override;
  std::vector<std::pair<uint64_t, std::string>> unit_state_names() const override {
    return {{StSort, "StSort"}, {StLine, "StLine"}};
  }
  uint64_t set_up(const TriangleSetup& t, uint64_t a, TradSetupTxn& x) override;
  std::unique_ptr<TradVertexQuantizer> quantizer_;
  uint64_t collinear_ = 0;  // triangles retired in StSort ("trad_collinear")
};

// The walk stage: rows p0.y .. p2.y; row y costs max(1, long-edge steps, short-side steps) cycles
// and starts only when the FIFO has room for one span at the start of its first cycle.
class TradWalkStage : public WalkStageBase<TradSetupTxn> {
 public:
  explicit TradWalkStage(sc_core::sc_module_name name) : WalkStageBase<TradSetupTxn>(name, 17) {}
  void add_counters(std::map<std::string, uint64_t>& work) const override;
  uint64_t steps_long = 0, steps_short = 0;  // Bresenham steps of the two walkers

 private:
  void configure(const RasterConfig& cfg) override;
  uint64_t walk(TradSetupTxn& x, uint64_t h) override;
  std::unique_ptr<TradSpanFiller> filler_;
  SpanList row_spans_;
  // The walked triangles' datapath work, summed (add_trad_work once per read of the statistics).
  TradTriangleResult work_sum_;
  bool any_work_ = false;  // a triangle was walked
};

// The whole unit (elaborated once per process).
using TradUnitSc = PipelineUnitSc<TradSetupStage, TradWalkStage, TradSetupTxn>;

}  // namespace trirast::sc

namespace trirast {
// The traditional-Bresenham unit, timed: the spans of make_trad_datapath_engine() plus cycles
// (register as "trad-sc").
std::unique_ptr<Engine> make_trad_sc_engine();
}  // namespace trirast
