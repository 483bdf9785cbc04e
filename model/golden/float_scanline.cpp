// The float scanline of 002_267f91d5740f3ec8.txt, a non-exact baseline: vertices as float pixel
// coordinates, sorted by y, the long edge a->c on one side and a->b / b->c on the other, each
// row's edge crossings interpolated in float, and the devlog's top-left convention:
// rows ceil(y - 0.5), x from ceil(lx - 0.5) to floor(rx - 0.5) inclusive. It differs from the
// rule where float rounding moves a crossing across a pixel centre, and on right edges that pass
// exactly through pixel centres (floor(rx - 0.5) keeps them; the D3D rule does not).
// Its error against the golden is measured in tests/test_golden_variants.cpp.
#include <algorithm>
#include <cmath>
#include <utility>

#include "golden/golden.hpp"

namespace trirast {

namespace {

// Float to int for a pixel index: clamped first, so a huge or non-finite value cannot overflow.
int to_pixel(float v, int lo, int hi) {
  if (!(v >= float(lo))) return lo;  // also NaN
  if (v > float(hi)) return hi;
  return int(v);
}

}  // namespace

void float_scanline_triangle(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out) {
  const float scale = 1.0f / float(cfg.unit());
  // Snapped vertices as float pixels: exact, since |v| < 2^15 pixels with <= 8 fraction bits.
  float ax = float(t.v[0].x) * scale, ay = float(t.v[0].y) * scale;
  float bx = float(t.v[1].x) * scale, by = float(t.v[1].y) * scale;
  float cx = float(t.v[2].x) * scale, cy = float(t.v[2].y) * scale;
  // Step 1: sort by y so that ay <= by <= cy.
  if (ay > by) std::swap(ax, bx), std::swap(ay, by);
  if (ay > cy) std::swap(ax, cx), std::swap(ay, cy);
  if (by > cy) std::swap(bx, cx), std::swap(by, cy);
  // Step 2: the rows whose centres lie in [ay, cy), clamped to the screen.
  const int height = cfg.height, width = cfg.width;
  const int y_min = std::max(to_pixel(std::ceil(ay - 0.5f), -1, height + 1), 0);
  const int y_mid = std::min(std::max(to_pixel(std::ceil(by - 0.5f), -1, height + 1), 0), height);
  const int y_max = std::min(to_pixel(std::ceil(cy - 0.5f), -1, height + 1), height);
  for (int y = y_min; y < y_max; ++y) {
    const float pixel_center = float(y) + 0.5f;
    // Left edge: always a -> c; right edge: a -> b above the middle vertex, b -> c below.
    const float lt = (pixel_center - ay) / (cy - ay);
    float lx = ax + (cx - ax) * lt;
    float rx;
    if (y < y_mid) {
      const float rt = (pixel_center - ay) / (by - ay);
      rx = ax + (bx - ax) * rt;
    } else {
      const float rt = (pixel_center - by) / (cy - by);
      rx = bx + (cx - bx) * rt;
    }
    if (lx > rx) std::swap(lx, rx);
    if (!std::isfinite(lx) || !std::isfinite(rx)) continue;
    // Top-left rule of the devlog: ceil includes the left edge, floor excludes the right one.
    const int ilx = to_pixel(std::ceil(lx - 0.5f), -1, width + 1);
    const int irx = to_pixel(std::floor(rx - 0.5f), -2, width + 1);
    const int x_min = std::max(ilx, 0);
    const int x_max = std::min(irx + 1, width);
    if (x_min < x_max) out.push_back(Span{t.index, int32_t(y), x_min, x_max});
  }
}

}  // namespace trirast
