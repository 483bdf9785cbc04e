// The SystemC model of the half-space tile unit (docs/timing.md, "The half-space unit"):
//
//   source -> setup stage (box, edge values at the box corner) -> hand-off -> walk stage (tile
//             walker, stamp tester, span emitter with a band buffer) -> span_fifo -> span_sink
//
// The datapath is model/halfspace_* (one call per stage); the process, the hand-off, the
// FIFO, the sink and the trace frame are the shared pipeline (stage_skeleton.hpp).
#pragma once
#include <memory>

#include "common/engine.hpp"
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>
#include <systemc>

#include "common/sc_stage_skeleton.hpp"
#include "halfspace/halfspace_unit.hpp"

namespace trirast::sc {

// The hand-off registers: the box and the three edges at its corner.
struct HalfspaceSetupTxn {
  size_t pos = 0;
  HalfspaceSetupOut setup;
};

// The half-space unit's own setup states (the improved unit's numbers: box, then edge values).
enum HalfspaceSetupState : uint64_t { StHsBox = 1, StHsEdge = 2 };

// a + 1 StBox (an empty box retires), StEdge from a + 2 (corner form dsp: one cycle; radix16, the
// digit-serial corner unit's runs: 2 + nL cycles, plus 1 + nR when the box is wider than one
// unit), then StHold.
class HalfspaceSetupStageSc : public SetupStageBase<HalfspaceSetupTxn> {
 public:
  explicit HalfspaceSetupStageSc(sc_core::sc_module_name name) : SetupStageBase<HalfspaceSetupTxn>(name) {}

 private:
  void configure(const RasterConfig& cfg) override;
  std::vector<std::pair<uint64_t, std::string>> unit_state_names() const override {
    return {{StHsBox, "StBox"}, {StHsEdge, "StEdge"}};
  }
  uint64_t set_up(const TriangleSetup& t, uint64_t a, HalfspaceSetupTxn& x) override;
  std::unique_ptr<HalfspaceUnit> unit_;
  int corner_form_ = 0;
};

// The walk stage: band k's walker cycles (one per unit test, one per stamp of a partial tile),
// then the band goes to the span emitter as soon as the emitter has pushed the previous band's
// last span; the emitter pushes one span per cycle when the FIFO has room (its entries and the
// span in the FIFO's push register leave one free), the span in the FIFO a cycle later.
class HalfspaceWalkStageSc : public WalkStageBase<HalfspaceSetupTxn> {
 public:
  explicit HalfspaceWalkStageSc(sc_core::sc_module_name name) : WalkStageBase<HalfspaceSetupTxn>(name, 17) {}
  void add_counters(std::map<std::string, uint64_t>& work) const override;
  uint64_t walker_cycles = 0, walker_wait = 0, emitter_pushes = 0;

 private:
  void configure(const RasterConfig& cfg) override;
  uint64_t walk(HalfspaceSetupTxn& x, uint64_t h) override;
  std::unique_ptr<HalfspaceUnit> unit_;
  SpanList spans_;
  HalfspaceTriangleResult res_;  // the current triangle's datapath result (its bands reused)
  // The walked triangles' datapath work, summed (add_hs_work once per read of the statistics).
  HalfspaceWork work_sum_;
  bool any_work_ = false;  // a triangle was walked
};

using HalfspaceUnitSc = PipelineUnitSc<HalfspaceSetupStageSc, HalfspaceWalkStageSc, HalfspaceSetupTxn>;

}  // namespace trirast::sc

namespace trirast {
// The half-space tile unit, timed (register as "halfspace-sc"; docs/timing.md).
std::unique_ptr<Engine> make_halfspace_sc_engine();
}  // namespace trirast
