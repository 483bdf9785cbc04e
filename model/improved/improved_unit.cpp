#include "improved/improved_unit.hpp"

#include <string>

namespace trirast {

uint64_t TriangleWork::divisions() const {
  return edge[0].divisions + edge[1].divisions + edge[2].divisions;
}
uint64_t TriangleWork::divider_iterations() const {
  return edge[0].divider_iterations + edge[1].divider_iterations + edge[2].divider_iterations;
}
uint64_t TriangleWork::boundary_steps() const {
  return edge[0].boundary_steps + edge[1].boundary_steps + edge[2].boundary_steps;
}
uint64_t TriangleWork::rows_stepped() const {
  return edge[0].rows_stepped + edge[1].rows_stepped + edge[2].rows_stepped;
}

namespace {

// The model keeps every value in an int64: refuse configurations whose edge values need more.
const RasterConfig& checked_config(const RasterConfig& cfg) {
  const UnitWidths w = unit_widths(cfg);
  if (w.edge_value > 63)
    throw WidthError("unit: " + std::to_string(w.edge_value) +
                     "-bit edge values (2p + 2, p = " + std::to_string(w.vertex) +
                     ") exceed the 64-bit model; use fewer --coord-bits or --subpixel-bits");
  return cfg;
}

}  // namespace

ImprovedUnit::ImprovedUnit(const RasterConfig& cfg)
    : cfg_(checked_config(cfg)),
      interface_(cfg),
      normalizer_(cfg),
      divider_(cfg),
      walker_{{cfg, divider_}, {cfg, divider_}, {cfg, divider_}} {}

UnitTriangleResult ImprovedUnit::run_triangle(const TriangleSetup& t, SpanList& out) {
  UnitTriangleResult res{};
  // 1. interface: box and box-relative edge terms; an empty box retires with no span.
  res.iface = interface_.run(t);
  const BoxStageOut& in = res.iface;
  if (in.empty) return res;
  // 2. edge_normalizer x3, 3./4. adder_divider and edge_walker x3 up to row 0.
  for (int k = 0; k < 3; ++k) {
    res.norm[k] = normalizer_.run(in.edge[k], in.Xmax, t.index);
    walker_[k].start(res.norm[k], in.Xmax, in.Ymax, t.index);
    res.walker_entry[k] = walker_[k].state();
  }
  // 5. span_generator: one row per step, the three walkers in lock step.
  for (int64_t j = 0; j <= in.Ymax; ++j) {
    const WalkerRow bound[3] = {walker_[0].row(), walker_[1].row(), walker_[2].row()};
    const SpanGenOut g = ImprovedSpanGenerator::row(res.norm, bound, in.Xmax);
    ++res.work.rows_visited;
    if (g.valid) {
      out.push_back(ImprovedSpanGenerator::to_span(g, t.index, in.x0, in.y0, j));
      ++res.work.spans;
      res.work.pixels += uint64_t(g.end - g.begin);
    }
    // Every walker moves to the next row (no step past the last row).
    if (j < in.Ymax)
      for (ImprovedEdgeWalker& w : walker_) w.advance();
  }
  for (int k = 0; k < 3; ++k) res.work.edge[k] = walker_[k].work();
  return res;
}

void add_work(const TriangleWork& w, std::map<std::string, uint64_t>& work) {
  work["divisions"] += w.divisions();
  work["divider_iterations"] += w.divider_iterations();
  work["boundary_steps"] += w.boundary_steps();
  work["rows_stepped"] += w.rows_stepped();
  work["rows_visited"] += w.rows_visited;
  work["spans"] += w.spans;
  work["pixels"] += w.pixels;
}

std::unique_ptr<Engine> make_improved_datapath_engine() {
  return make_datapath_engine<ImprovedUnit>(
      [](const UnitTriangleResult& r, std::map<std::string, uint64_t>& work) {
        add_work(r.work, work);
      });
}

}  // namespace trirast
