#include "common/setup.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/fixed_point.hpp"

namespace trirast {

namespace {

std::string where(uint32_t tri, int line) {
  std::string s = "triangle " + std::to_string(tri);
  if (line > 0) s += " (line " + std::to_string(line) + ")";
  return s;
}

// Twice the signed area of (v0, v1, v2); positive when the vertices run clockwise on screen
// (y down), which is the orientation whose interior has every edge function E > 0.
int64_t area2_of(const Vec2i v[3]) {
  return (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
}

EdgeSetup make_edge(const Vec2i& a, const Vec2i& b) {
  EdgeSetup e;
  e.A = a.y - b.y;
  e.B = b.x - a.x;
  e.C = a.x * b.y - a.y * b.x;
  // Top-left rule: a left edge (A > 0) or a top edge (A == 0, B > 0) owns its pixel centres.
  const bool top_left = e.A > 0 || (e.A == 0 && e.B > 0);
  e.bias = top_left ? 0 : -1;
  return e;
}

// Pixels whose centres lie within [lo, hi] (frac_bits() units), clipped to [0, limit).
void centre_range(int64_t lo, int64_t hi, const RasterConfig& cfg, int64_t limit, int32_t& first,
                  int32_t& last) {
  // centre(p) = p*u + h >= lo  <=>  p >= ceil((lo - h) / u)
  int64_t p0 = ceil_div(lo - cfg.half(), cfg.unit());
  // centre(p) <= hi  <=>  p <= floor((hi - h) / u)
  int64_t p1 = floor_div(hi - cfg.half(), cfg.unit());
  if (p0 < 0) p0 = 0;
  if (p1 > limit - 1) p1 = limit - 1;
  first = int32_t(p0);
  last = int32_t(p1);
  if (p0 > p1) {  // normalise every empty range to the same shape
    first = 0;
    last = -1;
  }
}

}  // namespace

int64_t snap_coordinate(double value, const RasterConfig& cfg, uint32_t tri, int line) {
  if (std::isnan(value)) throw SetupError(where(tri, line) + ": coordinate is NaN", tri, line);
  if (std::isinf(value)) throw SetupError(where(tri, line) + ": coordinate is infinite", tri, line);
  const double limit = double(cfg.coord_limit_px());
  // Scale by 2^S exactly (a power of two), then round half to even (the default FP rounding mode).
  const double scaled = std::nearbyint(std::ldexp(value, cfg.subpixel_bits));
  const double lo = -std::ldexp(limit, cfg.subpixel_bits);
  const double hi = std::ldexp(limit, cfg.subpixel_bits);
  if (!(scaled >= lo && scaled < hi))
    throw SetupError(where(tri, line) + ": coordinate " + std::to_string(value) +
                         " is outside the representable range [-" +
                         std::to_string(cfg.coord_limit_px()) + ", " +
                         std::to_string(cfg.coord_limit_px()) + ")",
                     tri, line);
  return int64_t(scaled) * cfg.snap_scale();
}

namespace {

// The snapped vertices' extent in subpixel units (the box and the off-screen test start from it).
struct VertexExtent {
  int64_t xmin, xmax, ymin, ymax;
};
VertexExtent vertex_extent(const TriangleSetup& t) {
  VertexExtent e{t.v[0].x, t.v[0].x, t.v[0].y, t.v[0].y};
  for (int k = 1; k < 3; ++k) {
    e.xmin = std::min(e.xmin, t.v[k].x);
    e.xmax = std::max(e.xmax, t.v[k].x);
    e.ymin = std::min(e.ymin, t.v[k].y);
    e.ymax = std::max(e.ymax, t.v[k].y);
  }
  return e;
}

}  // namespace

bool setup_triangle(const InputTriangle& in, uint32_t index, const RasterConfig& cfg,
                    TriangleSetup& out, const char** why) {
  out.index = index;
  for (int i = 0; i < 3; ++i) {
    out.v[i].x = snap_coordinate(in.x[i], cfg, index, in.line);
    out.v[i].y = snap_coordinate(in.y[i], cfg, index, in.line);
  }
  // Area and facing come from the snapped integers, never from the floats (hard case 9).
  int64_t area2 = area2_of(out.v);
  if (area2 == 0) {
    *why = "degenerate";
    return false;
  }
  // Front faces run counter-clockwise as a viewer sees the screen (OpenGL's default, and how
  // meshes wind their outward faces); with y down that is a negative area2.
  const bool front_facing = area2 < 0;
  if ((cfg.cull == CullMode::Back && !front_facing) ||
      (cfg.cull == CullMode::Front && front_facing)) {
    *why = "culled";
    return false;
  }
  out.swapped = area2 < 0;
  if (out.swapped) {
    std::swap(out.v[1], out.v[2]);
    area2 = -area2;
  }
  out.area2 = area2;
  for (int i = 0; i < 3; ++i) out.edge[i] = make_edge(out.v[i], out.v[(i + 1) % 3]);

  const VertexExtent e = vertex_extent(out);
  centre_range(e.xmin, e.xmax, cfg, cfg.width, out.box.x0, out.box.x1);
  centre_range(e.ymin, e.ymax, cfg, cfg.height, out.box.y0, out.box.y1);
  if (out.box.x0 > out.box.x1 || out.box.y0 > out.box.y1) out.box = PixelBox{0, 0, -1, -1};
  *why = nullptr;
  return true;
}

SetupResult setup_scene(const std::vector<InputTriangle>& tris, const RasterConfig& cfg) {
  SetupResult result;
  result.counts.read = tris.size();
  result.tris.reserve(tris.size());
  for (size_t i = 0; i < tris.size(); ++i) {
    TriangleSetup t;
    const char* why = nullptr;
    if (!setup_triangle(tris[i], uint32_t(i), cfg, t, &why)) {
      if (why[0] == 'd') ++result.counts.degenerate;
      else ++result.counts.culled;
      continue;
    }
    if (t.box.empty()) ++result.counts.no_pixel_centre;
    // Off screen: the snapped vertex extent does not overlap the viewport [0, W) x [0, H).
    const auto [xmin, xmax, ymin, ymax] = vertex_extent(t);
    if (xmax <= 0 || ymax <= 0 || xmin >= int64_t(cfg.width) * cfg.unit() ||
        ymin >= int64_t(cfg.height) * cfg.unit())
      ++result.counts.offscreen;
    result.tris.push_back(t);
  }
  result.counts.accepted = result.tris.size();
  return result;
}

}  // namespace trirast
