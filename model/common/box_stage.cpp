#include "common/box_stage.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace trirast {

BoxStage::BoxStage(const RasterConfig& cfg) : cfg_(cfg), w_(unit_widths(cfg)) {}

void BoxStage::centre_range(int64_t lo, int64_t hi, int64_t limit, int64_t& first,
                             int64_t& last) const {
  const int F = w_.frac;
  // ceil((lo - h) / u): an arithmetic shift of the negated value, negated back.
  first = -((cfg_.half() - lo) >> F);
  // floor((hi - h) / u): an arithmetic shift.
  last = (hi - cfg_.half()) >> F;
  // Clip to the viewport.
  first = std::max<int64_t>(first, 0);
  last = std::min<int64_t>(last, limit - 1);
}

BoxStageOut BoxStage::run(const TriangleSetup& t) const {
  BoxStageOut out{};
  out.tri = t.index;
  // Vertex coordinates and edge coefficients as the ports carry them.
  for (int k = 0; k < 3; ++k) {
    check_signed(t.v[k].x, w_.vertex, t.index, "vertex x", "coordinate");
    check_signed(t.v[k].y, w_.vertex, t.index, "vertex y", "coordinate");
    check_signed(t.edge[k].A, w_.edge_coef, t.index, "A", "edge coefficient");
    check_signed(t.edge[k].B, w_.edge_coef, t.index, "B", "edge coefficient");
  }
  // Vertex extent.
  int64_t xmin = t.v[0].x, xmax = xmin, ymin = t.v[0].y, ymax = ymin;
  for (int k = 1; k < 3; ++k) {
    xmin = std::min(xmin, t.v[k].x);
    xmax = std::max(xmax, t.v[k].x);
    ymin = std::min(ymin, t.v[k].y);
    ymax = std::max(ymax, t.v[k].y);
  }
  // Bounding box of the pixel centres inside the extent, clipped to the viewport.
  int64_t x0, x1, y0, y1;
  centre_range(xmin, xmax, cfg_.width, x0, x1);
  centre_range(ymin, ymax, cfg_.height, y0, y1);
  out.empty = x0 > x1 || y0 > y1;
  // The setup computed the same box: any difference is a bug in one of the two.
  const bool setup_empty = t.box.empty();
  if (out.empty != setup_empty ||
      (!out.empty && (x0 != t.box.x0 || x1 != t.box.x1 || y0 != t.box.y0 || y1 != t.box.y1)))
    throw std::logic_error("triangle " + std::to_string(t.index) +
                           ": interface box differs from the setup's box");
  if (out.empty) return out;  // retires with no span
  out.x0 = int32_t(x0);
  out.y0 = int32_t(y0);
  // Box-relative extent: the box may be at most 2^box_bits pixels wide and tall.
  out.Xmax = x1 - x0;
  out.Ymax = y1 - y0;
  check_unsigned(out.Xmax, w_.box, t.index, "Xmax", "box-relative coordinate");
  check_unsigned(out.Ymax, w_.box, t.index, "Ymax", "box-relative coordinate");
  // Edge terms: per-pixel steps and the values at the two top corners' pixel centres.
  const int64_t cx0 = x0 * cfg_.unit() + cfg_.half();
  const int64_t cy0 = y0 * cfg_.unit() + cfg_.half();
  for (int k = 0; k < 3; ++k) {
    const EdgeSetup& e = t.edge[k];
    BoxStageEdge& o = out.edge[k];
    o.a = e.A * cfg_.unit();
    o.b = e.B * cfg_.unit();
    o.E_L = e.A * cx0 + e.B * cy0 + e.C + e.bias;
    check_signed(o.E_L, w_.edge_value, t.index, "E_L", "edge value");
    o.E_R = o.E_L + out.Xmax * o.a;
    check_signed(o.E_R, w_.edge_value, t.index, "E_R", "edge value");
  }
  return out;
}

}  // namespace trirast
