#include "improved2/improved2_unit.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "improved/improved_unit.hpp"

namespace trirast {

RasterConfig Improved2Unit::gen2_config(const RasterConfig& cfg) {
  RasterConfig c = cfg;
  c.boundary = BoundaryMode::Step;
  c.divider = DividerMode::Adaptive;
  c.divider_quotient_bits = 0;
  return c;
}

namespace {
const RasterConfig& checked(const RasterConfig& cfg) {
  ImprovedUnit width_check(cfg);  // gen1's width limits of the 64-bit model apply as they are
  return cfg;
}
}  // namespace

Improved2Unit::Improved2Unit(const RasterConfig& cfg, bool cross_check)
    : cfg_(gen2_config(checked(cfg))),
      cross_check_(cross_check),
      box_stage_(cfg_),
      corner_(cfg_),
      normalizer_(cfg_),
      divider_(cfg_),
      walker_{{cfg_, divider_}, {cfg_, divider_}, {cfg_, divider_}} {}

void Improved2Unit::set_up(const TriangleSetup& t, Improved2Triangle& r) {
  r.rows.clear();
  r.tiny = false;
  r.corner_digits_l = r.corner_digits_r = 0;
  r.lane_cycles = 0;
  r.spans = r.pixels = r.rows_stepped = 0;
  for (Improved2LaneWork& l : r.lane) l = Improved2LaneWork{};
  // B: the box (gen1's interface computes the same one, E_L and E_R included).
  r.box = box_stage_.run(t);
  if (r.box.empty) return;
  // C: vertex-relative corner values (checked against the box stage's, which r.box holds); the
  // digit-serial unit's run lengths.
  if (cross_check_) {
    const BoxStageOut gen1 = r.box;
    corner_.run(t, r.box, gen1);
  }
  const BoxStageOut& b = r.box;
  r.corner_digits_l = corner_.digits(t, b.x0, b.y0);
  r.tiny = Improved2DirectTest2x2::takes(b);
  if (r.tiny) {
    // T: the direct test; the walk stage emits its rows, ending after row 0 when row 1 is empty.
    const Improved2DirectTestOut d = Improved2DirectTest2x2::run(b);
    const int rows = d.valid[1] ? 2 : 1;
    for (int j = 0; j < rows; ++j) {
      Improved2Row row{j, d.valid[j], Span{}};
      if (d.valid[j]) {
        row.span =
            Span{t.index, int32_t(b.y0 + j), int32_t(b.x0 + d.begin[j]), int32_t(b.x0 + d.end[j])};
        ++r.spans;
        r.pixels += uint64_t(d.end[j] - d.begin[j]);
      }
      r.rows.push_back(row);
    }
    return;
  }
  r.corner_digits_r = corner_.digits(t, b.x0 + b.Xmax, b.y0);
  // L: three lanes (gen1's normalizer and walker registers; the gen2 lane's cycles from the
  // traversal's steps, which the walker takes as the lane does).
  for (int k = 0; k < 3; ++k) {
    norm_[k] = normalizer_.run(b.edge[k], b.Xmax, t.index);
    walker_[k].start(norm_[k], b.Xmax, b.Ymax, t.index);
    const int64_t steps = int64_t(walker_[k].work().boundary_steps);
    if (cross_check_) {
      const int64_t own = Improved2EdgeLane::traverse(norm_[k], b.Ymax);
      if (own != steps || (own <= b.Ymax) != walker_[k].state().enters)
        throw std::logic_error("triangle " + std::to_string(t.index) + ": edge " +
                               std::to_string(k) +
                               ": the gen2 lane's traversal differs from gen1's");
    }
    r.lane[k] = Improved2EdgeLane::from_traversal(norm_[k], b.Xmax, b.Ymax, steps);
    r.lane_cycles = std::max(r.lane_cycles, r.lane[k].cycles);
  }
}

Improved2Row Improved2Unit::walk_row(const TriangleSetup& t, Improved2Triangle& r, int64_t j) {
  const BoxStageOut& b = r.box;
  const WalkerRow bound[3] = {walker_[0].row(), walker_[1].row(), walker_[2].row()};
  const SpanGenOut g = ImprovedSpanGenerator::row(norm_, bound, b.Xmax);
  Improved2Row row{j, g.valid, Span{}};
  if (g.valid) {
    row.span = ImprovedSpanGenerator::to_span(g, t.index, b.x0, b.y0, j);
    ++r.spans;
    r.pixels += uint64_t(g.end - g.begin);
  }
  if (j < b.Ymax)
    for (ImprovedEdgeWalker& w : walker_) w.advance();
  return row;
}

void Improved2Unit::run_triangle(const TriangleSetup& t, Improved2Triangle& r) {
  set_up(t, r);
  if (r.box.empty || r.tiny) return;
  // W: one row per step, the three walkers in lock step.
  for (int64_t j = 0; j <= r.box.Ymax; ++j) r.rows.push_back(walk_row(t, r, j));
  for (const ImprovedEdgeWalker& w : walker_) r.rows_stepped += w.work().rows_stepped;
}

namespace {

class Improved2Engine : public Engine {
 public:
  void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) override {
    Improved2Unit unit(cfg);
    Improved2Triangle r;
    uint64_t empty = 0, tiny = 0, lanes = 0, iters = 0, steps = 0, rows = 0, stepped = 0, spans = 0,
             pixels = 0;
    for (const TriangleSetup& t : setup.tris) {
      unit.run_triangle(t, r);
      for (const Improved2Row& row : r.rows)
        if (row.valid) out.spans.push_back(row.span);
      if (r.box.empty) {
        ++empty;
        continue;
      }
      ++(r.tiny ? tiny : lanes);
      for (const Improved2LaneWork& l : r.lane) {
        iters += l.iterations;
        steps += uint64_t(l.steps);
      }
      rows += r.rows.size();
      stepped += r.rows_stepped;
      spans += r.spans;
      pixels += r.pixels;
    }
    out.work["triangles"] += setup.tris.size();
    out.work["empty_boxes"] += empty;
    out.work["tiny_boxes"] += tiny;
    out.work["lane_boxes"] += lanes;
    out.work["divider_iterations"] += iters;
    out.work["boundary_steps"] += steps;
    out.work["rows_visited"] += rows;
    out.work["rows_stepped"] += stepped;
    out.work["spans"] += spans;
    out.work["pixels"] += pixels;
  }
};

}  // namespace

std::unique_ptr<Engine> make_improved2_datapath_engine() { return std::make_unique<Improved2Engine>(); }

}  // namespace trirast
