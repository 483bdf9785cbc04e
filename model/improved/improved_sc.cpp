#include "improved/improved_sc.hpp"

#include <algorithm>

#include "common/sc_engine.hpp"
#include "improved/improved_unit.hpp"

namespace trirast::sc {

using sc_core::sc_module_name;

// ---- setup stage -------------------------------------------------------------------------------

ImprovedSetupStageSc::ImprovedSetupStageSc(sc_module_name name)
    : SetupStageBase<EdgeSetupTxn>(name), interface("interface") {
  for (int k = 0; k < 3; ++k)
    lane[k] = std::make_unique<ImprovedEdgeLaneSc>(("edge_lane" + std::to_string(k)).c_str());
}

void ImprovedSetupStageSc::configure(const RasterConfig& cfg) {
  interface.configure(cfg);
  for (auto& l : lane) l->configure(cfg);
  // The hand-off registers hold the three walkers, each bound to its lane's divider.
  for (EdgeSetupTxn& x : txn_) {
    x.walker.clear();
    x.walker.reserve(3);
    for (int k = 0; k < 3; ++k) x.walker.emplace_back(cfg, lane[k]->divider());
  }
}

void ImprovedSetupStageSc::add_unit_trace(VcdRecorder& tr) {
  for (int k = 0; k < 3; ++k)
    sig_lane_busy_[k] = tr.add("setup", "lane" + std::to_string(k) + "_busy", 1, 0);
  sig_iface_busy_ = tr.add("interface", "busy", 1, 0);
  for (int k = 0; k < 3; ++k)
    sig_edge_lane_busy_[k] = tr.add("edge_lane" + std::to_string(k), "busy", 1, 0);
  // The divider's iterations of the lane's triangle, shown while the lane works: the model knows
  // their number, not their cycles (they interleave with the boundary steps inside L_k).
  for (int k = 0; k < 3; ++k)
    sig_div_iter_[k] = tr.add("adder_divider" + std::to_string(k), "iterations", 16, VcdRecorder::kX);
}

uint64_t ImprovedSetupStageSc::set_up(const TriangleSetup& t, uint64_t a, EdgeSetupTxn& x) {
  VcdRecorder* tr = run_->trace;
  // a + 1, StBox: the interface's bounding box; an empty box retires here.
  trace_state(a + 1, StBox);
  x.iface = interface.run(t);
  if (x.iface.empty) {
    ++interface.counters.busy;
    if (tr) {
      tr->value(sig_iface_busy_, a + 1, 1);
      tr->value(sig_iface_busy_, a + 2, 0);
    }
    return kRetired;
  }
  // a + 2, StEdge: corner values and normalizers; a + 3 on, StLanes: L_k cycles per lane.
  uint64_t L = 0, Lk[3];
  TriangleCycles& rec = run_->tri(x.pos);
  for (int k = 0; k < 3; ++k) {
    Lk[k] = lane[k]->run(x.iface, k, t.index, x.norm[k], x.walker[k]);
    L = std::max(L, Lk[k]);
    rec.divider_iterations += x.walker[k].work().divider_iterations;
    rec.boundary_steps += x.walker[k].work().boundary_steps;
  }
  rec.box_width = uint64_t(x.iface.Xmax) + 1;
  rec.box_height = uint64_t(x.iface.Ymax) + 1;
  interface.counters.busy += 2;
  trace_state(a + 2, StEdge);
  trace_state(a + 3, StLanes);
  if (tr) {
    tr->value(sig_iface_busy_, a + 1, 1);
    tr->value(sig_iface_busy_, a + 3, 0);
    for (int k = 0; k < 3; ++k)
      if (Lk[k] > 0) {
        tr->value(sig_lane_busy_[k], a + 3, 1);
        tr->value(sig_lane_busy_[k], a + 3 + Lk[k], 0);
        tr->value(sig_edge_lane_busy_[k], a + 3, 1);
        tr->value(sig_edge_lane_busy_[k], a + 3 + Lk[k], 0);
        tr->value(sig_div_iter_[k], a + 3, x.walker[k].work().divider_iterations);
        tr->value(sig_div_iter_[k], a + 3 + Lk[k], VcdRecorder::kX);
      }
  }
  // The slowest lane's last cycle ends the set-up: StHold from a + 3 + L.
  return a + 3 + L;
}

void ImprovedSetupStageSc::add_counters(std::map<std::string, uint64_t>& work) const {
  SetupStageBase<EdgeSetupTxn>::add_counters(work);
  add_counter(work, "busy_cycles.interface", interface.counters.busy);
  for (int k = 0; k < 3; ++k) {
    add_counter(work, "busy_cycles.edge_lane" + std::to_string(k), lane[k]->counters.busy);
    add_counter(work, "busy_cycles.adder_divider" + std::to_string(k), lane[k]->divider_busy);
  }
}

// ---- walk stage --------------------------------------------------------------------------------

ImprovedWalkStageSc::ImprovedWalkStageSc(sc_module_name name)
    : WalkStageBase<EdgeSetupTxn>(name, 16), span_generator("span_generator") {}

void ImprovedWalkStageSc::configure(const RasterConfig&) {
  span_generator.counters = {};
  for (auto& r : rows_stepped) r = 0;
  work_sum_ = TriangleWork{};
  any_work_ = false;
}

void ImprovedWalkStageSc::add_unit_trace(VcdRecorder& tr) {
  for (int k = 0; k < 3; ++k)
    sig_walker_busy_[k] = tr.add("edge_walker" + std::to_string(k), "busy", 1, 0);
  sig_gen_busy_ = tr.add("span_generator", "busy", 1, 0);
}

void ImprovedWalkStageSc::add_counters(std::map<std::string, uint64_t>& work) const {
  WalkStageBase<EdgeSetupTxn>::add_counters(work);
  for (int k = 0; k < 3; ++k)
    add_counter(work, "busy_cycles.edge_walker" + std::to_string(k), rows_stepped[k]);
  add_counter(work, "busy_cycles.span_generator", span_generator.counters.busy);
  if (any_work_) add_work(work_sum_, work);
}

uint64_t ImprovedWalkStageSc::walk(EdgeSetupTxn& x, uint64_t h) {
  const uint64_t N = uint64_t(run_->cfg.endpoints);
  const BoxStageOut& in_ = x.iface;
  VcdRecorder* tr = run_->trace;
  TriangleWork work;
  uint64_t t = h + 1, t_last = h;
  int64_t j = 0;
  while (j <= in_.Ymax) {
    // A group of N rows goes when the FIFO held at most DEPTH - N spans at the start of the cycle.
    t = start_row(t, N, uint64_t(j));
    uint64_t stepped[3] = {0, 0, 0};  // the walkers' rows stepped before this group (trace)
    if (tr)
      for (int k = 0; k < 3; ++k) stepped[k] = x.walker[k].work().rows_stepped;
    // The walkers present up to N rows; the span generator makes their spans, pushed in row order.
    for (uint64_t n = 0; n < N && j <= in_.Ymax; ++n, ++j) {
      const WalkerRow bound[3] = {x.walker[0].row(), x.walker[1].row(), x.walker[2].row()};
      const SpanGenOut g = ImprovedSpanGenerator::row(x.norm, bound, in_.Xmax);
      ++work.rows_visited;
      if (g.valid) {
        spans->push(ImprovedSpanGenerator::to_span(g, in_.tri, in_.x0, in_.y0, j), x.pos, t);
        ++work.spans;
        work.pixels += uint64_t(g.end - g.begin);
      }
      if (j < in_.Ymax)
        for (ImprovedEdgeWalker& w : x.walker) w.advance();
    }
    ++counters.busy;
    ++span_generator.counters.busy;
    if (tr) {
      // Busy in cycle t; the next group's cycle overrides the 0 in t + 1.
      tr->value(sig_gen_busy_, t, 1);
      tr->value(sig_gen_busy_, t + 1, 0);
      for (int k = 0; k < 3; ++k)
        if (x.walker[k].work().rows_stepped != stepped[k]) {
          tr->value(sig_walker_busy_[k], t, 1);
          tr->value(sig_walker_busy_[k], t + 1, 0);
        }
    }
    t_last = t++;
  }
  for (int k = 0; k < 3; ++k) {
    work.edge[k] = x.walker[k].work();
    rows_stepped[k] += work.edge[k].rows_stepped;
  }
  // add_work() goes through a string-keyed map: once per read of the statistics (add_counters), not per triangle.
  for (int k = 0; k < 3; ++k) {
    work_sum_.edge[k].divisions += work.edge[k].divisions;
    work_sum_.edge[k].divider_iterations += work.edge[k].divider_iterations;
    work_sum_.edge[k].boundary_steps += work.edge[k].boundary_steps;
    work_sum_.edge[k].rows_stepped += work.edge[k].rows_stepped;
  }
  work_sum_.rows_visited += work.rows_visited;
  work_sum_.spans += work.spans;
  work_sum_.pixels += work.pixels;
  any_work_ = true;
  return t_last;
}

}  // namespace trirast::sc

namespace trirast {
namespace {
const int kUnit = sc::register_sc_unit(
    {"improved",
     [](const char* name, const RasterConfig& cfg, const sc_core::sc_time& period) {
       return std::unique_ptr<sc::RasterUnitSc>(new sc::ImprovedUnitSc(name, cfg, period));
     },
     [](const RasterConfig& cfg) { ImprovedUnit check(cfg); }});
}  // namespace

std::unique_ptr<Engine> make_improved_sc_engine() { return sc::make_sc_engine(kUnit); }

}  // namespace trirast
