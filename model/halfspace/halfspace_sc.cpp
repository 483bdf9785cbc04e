#include "halfspace/halfspace_sc.hpp"

#include <algorithm>

#include "common/sc_engine.hpp"
#include "halfspace/halfspace_unit.hpp"

namespace trirast::sc {

void HalfspaceSetupStageSc::configure(const RasterConfig& cfg) {
  unit_ = std::make_unique<HalfspaceUnit>(cfg);
  corner_form_ = cfg.halfspace.corner_form;
}

uint64_t HalfspaceSetupStageSc::set_up(const TriangleSetup& t, uint64_t a, HalfspaceSetupTxn& x) {
  trace_state(a + 1, StHsBox);
  x.setup = unit_->set_up(t);
  if (x.setup.empty) return kRetired;
  TriangleCycles& rec = run_->tri(x.pos);
  rec.box_width = uint64_t(x.setup.Xmax) + 1;
  rec.box_height = uint64_t(x.setup.Ymax) + 1;
  // StEdge (rtl/halfspace/trirast_halfspace_setup_stage.sv): products, one cycle; radix16, run
  // 1's start, its digits and the cycle E0 is taken, then run 2's digits and the cycle E_end is
  // ready, when there is a run 2.
  trace_state(a + 2, StHsEdge);
  if (corner_form_ == 0) return a + 3;
  const uint64_t d0 = uint64_t(x.setup.corner_digits_e0);
  const uint64_t dend = uint64_t(x.setup.corner_digits_eend);
  return a + 4 + d0 + (dend > 0 ? 1 + dend : 0);
}

void HalfspaceWalkStageSc::configure(const RasterConfig& cfg) {
  unit_ = std::make_unique<HalfspaceUnit>(cfg);
  walker_cycles = walker_wait = emitter_pushes = 0;
  work_sum_ = HalfspaceWork{};
  any_work_ = false;
}

void HalfspaceWalkStageSc::add_counters(std::map<std::string, uint64_t>& work) const {
  WalkStageBase<HalfspaceSetupTxn>::add_counters(work);
  add_counter(work, "busy_cycles.tile_walker", walker_cycles);
  add_counter(work, "stall_cycles.tile_walker", walker_wait);
  add_counter(work, "busy_cycles.span_emitter", emitter_pushes);
  if (any_work_) add_hs_work(work_sum_, work);
}

uint64_t HalfspaceWalkStageSc::walk(HalfspaceSetupTxn& x, uint64_t h) {
  HalfspaceTriangleResult& res = res_;
  res.setup = x.setup;
  res.bands.clear();
  res.work = HalfspaceWork{};
  spans_.clear();
  unit_->walk(res, spans_);
  work_sum_ += res.work;
  any_work_ = true;
  uint64_t t = h + 1;        // the walker's first cycle of the next band
  uint64_t last_push = 0;    // the emitter's last push so far (0: none; every push is > h)
  uint64_t w = h;            // the cycle the last band went to the emitter
  size_t next = 0;
  for (const HalfspaceBand& b : res.bands) {
    const uint64_t e = t + b.cycles - 1;     // the band's last walker cycle
    w = std::max(e, last_push);              // hand-off to the emitter at the end of w
    walker_cycles += b.cycles;
    walker_wait += w - e;
    counters.busy += b.cycles;
    uint64_t p = w;
    for (uint64_t i = 0; i < b.spans; ++i, ++next) {
      const Span& s = spans_[next];
      // The emitter's push in p goes through the push register in front of the span FIFO (in
      // block RAM): into the FIFO at the end of p + 1. The room test counts it (first_room:
      // count + pending).
      p = start_row(p + 1, 1, uint64_t(s.y - x.setup.y0));
      spans->push(s, x.pos, p + 1);
      ++emitter_pushes;
      last_push = p;
    }
    t = w + 1;
  }
  return std::max(w, last_push);
}

}  // namespace trirast::sc

namespace trirast {
namespace {
const int kUnit = sc::register_sc_unit(
    {"halfspace",
     [](const char* name, const RasterConfig& cfg, const sc_core::sc_time& period) {
       return std::unique_ptr<sc::RasterUnitSc>(new sc::HalfspaceUnitSc(name, cfg, period));
     },
     [](const RasterConfig& cfg) { HalfspaceUnit check(cfg); }});
}  // namespace

std::unique_ptr<Engine> make_halfspace_sc_engine() { return sc::make_sc_engine(kUnit); }

}  // namespace trirast
