#include "trad/trad_sc.hpp"

#include <algorithm>

#include "common/sc_engine.hpp"
#include "trad/trad_timing.hpp"

namespace trirast::sc {

// ---- setup stage -------------------------------------------------------------------------------

void TradSetupStage::configure(const RasterConfig& cfg) {
  quantizer_ = std::make_unique<TradVertexQuantizer>(cfg);
  collinear_ = 0;
}

void TradSetupStage::add_counters(std::map<std::string, uint64_t>& work) const {
  SetupStageBase<TradSetupTxn>::add_counters(work);
  if (collinear_ > 0) add_counter(work, "trad_collinear", collinear_);
}

uint64_t TradSetupStage::set_up(const TriangleSetup& t, uint64_t a, TradSetupTxn& x) {
  // a + 1, StSort: quantize and sort the vertices; collinear integer vertices retire here.
  trace_state(a + 1, StSort);
  x.tri = &t;
  x.verts = quantizer_->run(t);
  if (x.verts.empty) {
    ++collinear_;  // never reaches the walk stage's work
    return kRetired;
  }
  // The box the walk stage covers: the integer vertices' bounding box (rows p0.y .. p2.y).
  TriangleCycles& rec = run_->tri(x.pos);
  const Vec2i* p = x.verts.p;
  rec.box_width = uint64_t(std::max({p[0].x, p[1].x, p[2].x}) - std::min({p[0].x, p[1].x, p[2].x})) + 1;
  rec.box_height = uint64_t(p[2].y - p[0].y) + 1;
  // a + 2, StLine: the three lines' set-up; StHold from a + 3.
  trace_state(a + 2, StLine);
  return a + 3;
}

// ---- walk stage --------------------------------------------------------------------------------

void TradWalkStage::configure(const RasterConfig& cfg) {
  steps_long = steps_short = 0;
  filler_ = std::make_unique<TradSpanFiller>(cfg);
  work_sum_ = TradTriangleResult{};
  any_work_ = false;
}

void TradWalkStage::add_counters(std::map<std::string, uint64_t>& work) const {
  WalkStageBase<TradSetupTxn>::add_counters(work);
  add_counter(work, "busy_cycles.long_walker", steps_long);
  add_counter(work, "busy_cycles.short_walker", steps_short);
  if (any_work_) add_trad_work(work_sum_, work);
}

uint64_t TradWalkStage::walk(TradSetupTxn& x, uint64_t h) {
  // The datapath (stages 2 and 3 on the setup stage's vertices) row by row: the three lines' runs
  // on every row p0.y .. p2.y, which give the row's steps, and the spans of the rows inside the
  // viewport.
  TradTriangleResult res;
  filler_->begin(x.verts, res);
  const int64_t first = x.verts.p[0].y, last = x.verts.p[2].y;
  RowRun run[3];
  bool on[3];
  uint64_t t = h + 1;
  for (int64_t y = first; y <= last; ++y) {
    t = start_row(t, 1, uint64_t(y - first));
    row_spans_.clear();
    filler_->row(*x.tri, y, run, on, res, row_spans_);
    uint64_t steps[3];
    for (int e = 0; e < 3; ++e) steps[e] = TradWalkTiming::steps_of_run(x.verts, e, y, on[e], run[e]);
    // The row takes as many cycles as the busier walker steps (at least one).
    const uint64_t l = steps[0];
    const uint64_t s = steps[1] + steps[2];
    steps_long += l;
    steps_short += s;
    const uint64_t c = std::max<uint64_t>(1, std::max(l, s));
    const uint64_t end = t + c - 1;  // the row's span is pushed at the end of its last cycle
    if (!row_spans_.empty()) spans->push(row_spans_.front(), x.pos, end);
    counters.busy += c;
    t = end + 1;
  }
  work_sum_ += res;
  any_work_ = true;
  return t - 1;
}

}  // namespace trirast::sc

namespace trirast {
namespace {
const int kUnit = sc::register_sc_unit(
    {"trad",
     [](const char* name, const RasterConfig& cfg, const sc_core::sc_time& period) {
       return std::unique_ptr<sc::RasterUnitSc>(new sc::TradUnitSc(name, cfg, period));
     },
     nullptr});
}  // namespace

std::unique_ptr<Engine> make_trad_sc_engine() { return sc::make_sc_engine(kUnit); }

}  // namespace trirast
