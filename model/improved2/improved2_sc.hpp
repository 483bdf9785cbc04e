// The SystemC model of the second-generation improved unit (docs/improved2.md; its timing:
// docs/timing.md), cycle for cycle the unit's RTL rtl/improved2/trirast_improved2.f (N = 1, 2, 4
// rows per walk cycle):
//
//   source -> [B] box stage -> [C] corner stage (DSP or digit-serial) -> [L] job register + three
//             lanes (or the direct 2x2 test's row spans) -> [W] walk stage, registered push ->
//             span_fifo -> span_sink
//
// Each stage holds one triangle (a register with a full flag) and passes it on in the first cycle
// the next one is free or frees itself in that cycle, so the stages' cycles follow from one
// another in acceptance order; one process (the unit's) computes them triangle by triangle with
// the datapath of model/improved2/improved2_unit.hpp, stamps the spans with their push cycles into the
// shared span FIFO (span_fifo.hpp, which knows each pop cycle). The unit is a component
// (sc_raster_unit.hpp): it takes each triangle in the producer's transport call.
//
// The trace (--trace, docs/improved2.md, "Trace"): the same process reports each
// stage's signal changes, stamped with their cycles, to the run's VcdRecorder (vcd_trace.hpp): per
// stage a busy bit and the tag it holds, the corner unit's runs, each lane's busy cycles, the walk
// stage's state and rows; the span port, FIFO and sink through the shared SpanFifo.
#pragma once
#include <memory>

#include "common/engine.hpp"
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <systemc>

#include "common/sc_span_fifo.hpp"
#include "common/sc_stage_skeleton.hpp"
#include "improved2/improved2_unit.hpp"

namespace trirast::sc {

// [B] The box stage: the triangle register, box, clip and empty test in one cycle. A triangle
// accepted in a is in B from a + 1: an empty box retires in a + 1, any other moves to C in the
// first cycle k >= a + 1 in which C is free (C empty, or C's triangle moving on in k). The port
// accepts the next triangle in the cycle B's leaves (ready = B empty, retiring or moving).
class Improved2BoxStageSc : public sc_core::sc_module {
 public:
  explicit Improved2BoxStageSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {}
  // The cycle triangle accepted in a moves to C, C being free from c_free on.
  static uint64_t take(uint64_t a, uint64_t c_free) { return std::max(a + 1, c_free); }
  StageCounters counters;  // busy: cycles holding a triangle; stall: of them waiting for C
};

// [C] The corner stage: E_L (and E_R) of the triangle that entered in k. Ready (its values valid
// for L) in:
//   DSP products (CornerForm 0):   k + 1
//   digit-serial, radix 16 (CornerForm 1): started in k (the operands from B's box), dl digits:
//     a box for the direct test  k + 1 + dl
//     a box for the lanes        k + 3 + dl + dr (a second run at x0 + Xmax for E_R: the start
//                                cycle after the first run's last, then dr digits)
// It moves to L in the first cycle >= ready in which L is free.
class Improved2CornerStageSc : public sc_core::sc_module {
 public:
  explicit Improved2CornerStageSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {}
  void configure(int form) {
    form_ = form;
    counters = {};
  }
  uint64_t ready(uint64_t k, const Improved2Triangle& x) const {
    if (form_ == 0) return k + 1;
    if (x.tiny) return k + 1 + uint64_t(x.corner_digits_l);
    return k + 3 + uint64_t(x.corner_digits_l) + uint64_t(x.corner_digits_r);
  }
  int form() const { return form_; }
  StageCounters counters;  // busy: cycles holding a triangle; stall: of them waiting for L

 private:
  int form_ = 1;
};

// [L] The job register and the three redesigned lanes: a triangle moved from C in m is in L
// from m + 1; a direct-test job can be handed to the walk stage from m + 1, a lane job from
// m + 1 + max_k L_k (Improved2EdgeLane's cycles); it is handed off in the first such cycle the walk stage
// is idle, and L is free again in that cycle.
class Improved2JobStageSc : public sc_core::sc_module {
 public:
  explicit Improved2JobStageSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {}
  static uint64_t ready(uint64_t m, const Improved2Triangle& x) {
    return x.tiny ? m + 1 : m + 1 + x.lane_cycles;
  }
  StageCounters counters;  // busy: lane cycles; stall: cycles a ready job waited for W
  uint64_t lane_busy[3] = {0, 0, 0};
};

// [W] The retimed walk stage (trirast_improved2_walk_stage.sv): loaded in h, it processes one group of N
// rows (--endpoints; rows g*N .. g*N + N - 1) per cycle from h + 1, a group in the first cycle t in
// which count + push + N <= DEPTH (count: the FIFO's occupancy at the start of t; push: the spans
// registered in t - 1, pushed in t); a group's spans are registered and pushed into the FIFO
// together in t + 1. A tiny job's rows 0 and 1 are one group when N >= 2. Idle from the cycle after
// its last group.
class Improved2WalkStageSc : public sc_core::sc_module {
 public:
  explicit Improved2WalkStageSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {}
  StageCounters counters;
};

// The unit as a component (sc_raster_unit.hpp).
class Improved2UnitSc : public RasterUnitSc {
 public:
  Improved2UnitSc(sc_core::sc_module_name name, const RasterConfig& cfg,
                  const sc_core::sc_time& period);

  // The walk stage's trace states (walk_stage.state): idle, a lane job's rows, a tiny job's rows.
  enum WalkTraceState : uint64_t { kWalkIdle = 0, kWalkLanes = 1, kWalkTiny = 2 };
  // The corner unit's trace states (corner_unit.run).
  // A lane's trace phases (laneK.phase): the slope division with the traversal beside it (its
  // set-up cycle included), the entry division, a horizontal edge's traversal.
  enum LanePhase : uint64_t { kLaneIdle = 0, kLaneSlope = 1, kLaneEntry = 2, kLaneTraverse = 3 };
  enum CornerRun : uint64_t { kCornerIdle = 0, kRunL = 1, kRunR = 2, kProducts = 3 };

  SpanSink sink;
  SpanFifo fifo;
  Improved2BoxStageSc box_stage;
  Improved2CornerStageSc corner_stage;
  Improved2JobStageSc job_stage;
  Improved2WalkStageSc walk_stage;

 protected:
  void begin_stream() override;
  uint64_t accept(const TriangleSetup& t, size_t pos, uint64_t a) override;
  uint64_t unit_idle_from() const override { return w_free_; }
  void add_counters(std::map<std::string, uint64_t>& work) const override;

 private:
  // Walks job x of triangle tri (setup position pos) loaded in h; returns its last row's cycle.
  // A lane job's rows come from the unit's walkers (Improved2Unit::walk_row) as they go.
  // Reports the walk stage's signals to tr when not null.
  uint64_t walk(const TriangleSetup& tri, Improved2Triangle& x, size_t pos, uint64_t h,
                TriangleCycles& rec, VcdRecorder* tr);
  // Declares the unit's trace signals (scopes box_stage .. walk_stage, then span, span_fifo,
  // span_sink); returns the span port's handles for the FIFO.
  SpanTraceSignals add_trace(VcdRecorder& tr);
  // Reports the stages' signal changes of a non-empty triangle (accepted in a, B -> C in k, C's
  // values ready in cr, C -> L in m, job ready in ready, handed off in h).
  void trace_job(VcdRecorder& tr, uint32_t tag, uint64_t a, uint64_t k, uint64_t cr, uint64_t m,
                 uint64_t ready, uint64_t h);

  struct TraceSignals {
    int accept = -1, b_busy = -1, b_tri = -1, b_stall = -1, b_retire = -1;
    int c_busy = -1, c_tri = -1, c_stall = -1, c_run = -1, c_digits = -1;
    int l_busy = -1, l_tri = -1, l_tiny = -1, l_stall = -1;
    int lane_busy[3] = {-1, -1, -1}, lane_phase[3] = {-1, -1, -1}, lane_steps[3] = {-1, -1, -1},
        lane_iter[3] = {-1, -1, -1};
    int w_state = -1, w_tri = -1, w_row = -1, w_stall = -1, w_push = -1;
  };
  TraceSignals sig_;

  std::unique_ptr<Improved2Unit> unit_;
  Improved2Triangle x_;
  uint64_t c_free_ = 0;  // C is free from this cycle (its last triangle's move to L)
  uint64_t l_free_ = 0;  // L is free from this cycle (its last job's hand-off)
  uint64_t w_free_ = 0;  // the walk stage is idle from this cycle
  uint64_t tiny_ = 0, lanes_ = 0, empty_ = 0, iterations_ = 0, steps_ = 0, rows_ = 0;
};

}  // namespace trirast::sc

namespace trirast {
// The second-generation improved unit, timed (register as "improved2-sc").
std::unique_ptr<Engine> make_improved2_sc_engine();
}  // namespace trirast
