#include "common/reference_raster.hpp"

#include <algorithm>
#include <cmath>

#include "common/span.hpp"

namespace trirast::test {

namespace {

using i128 = __int128;

struct P {
  i128 x, y;
};

// Snap to S bits, round half to even, in units of 1/2^S; doubled when S == 0 so centres are odd.
i128 snap(double v, const RasterConfig& cfg) {
  const double scaled = std::nearbyint(v * std::pow(2.0, cfg.subpixel_bits));
  return i128((long long)scaled) * (cfg.subpixel_bits == 0 ? 2 : 1);
}

// Cross product (b - a) x (p - a): positive when p is on the interior side of edge a->b of a
// triangle with positive orientation.
i128 edge(const P& a, const P& b, const P& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Top-left: a "top" edge is horizontal with the interior below it (y down), i.e. it runs toward +x;
// a "left" edge runs upward (toward -y).
bool top_left(const P& a, const P& b) {
  const bool top = a.y == b.y && b.x > a.x;
  const bool left = b.y < a.y;
  return top || left;
}

}  // namespace

SpanList reference_raster(const std::vector<InputTriangle>& tris, const RasterConfig& cfg) {
  const int F = cfg.subpixel_bits == 0 ? 1 : cfg.subpixel_bits;
  const i128 u = i128(1) << F, h = u / 2;
  SpanList out;
  for (size_t t = 0; t < tris.size(); ++t) {
    P v[3];
    for (int i = 0; i < 3; ++i) v[i] = P{snap(tris[t].x[i], cfg), snap(tris[t].y[i], cfg)};
    i128 area = edge(v[0], v[1], v[2]);
    if (area == 0) continue;
    const bool front = area < 0;  // counter-clockwise as seen on a y-down screen
    if ((cfg.cull == CullMode::Back && !front) || (cfg.cull == CullMode::Front && front)) continue;
    if (area < 0) std::swap(v[1], v[2]);
    // Every pixel whose centre could be near the triangle, clipped to the viewport.
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (int i = 0; i < 3; ++i) {
      lo_x = std::min(lo_x, double(v[i].x) / double(u));
      hi_x = std::max(hi_x, double(v[i].x) / double(u));
      lo_y = std::min(lo_y, double(v[i].y) / double(u));
      hi_y = std::max(hi_y, double(v[i].y) / double(u));
    }
    const long x0 = std::max(0L, long(std::floor(lo_x)) - 1);
    const long x1 = std::min(long(cfg.width) - 1, long(std::ceil(hi_x)) + 1);
    const long y0 = std::max(0L, long(std::floor(lo_y)) - 1);
    const long y1 = std::min(long(cfg.height) - 1, long(std::ceil(hi_y)) + 1);
    for (long py = y0; py <= y1; ++py) {
      long run_begin = -1;
      for (long px = x0; px <= x1 + 1; ++px) {
        bool in = false;
        if (px <= x1) {
          const P c{i128(px) * u + h, i128(py) * u + h};
          in = true;
          for (int i = 0; i < 3 && in; ++i) {
            const P& a = v[i];
            const P& b = v[(i + 1) % 3];
            const i128 e = edge(a, b, c);
            in = e > 0 || (e == 0 && top_left(a, b));
          }
        }
        if (in && run_begin < 0) run_begin = px;
        if (!in && run_begin >= 0) {
          out.push_back(Span{uint32_t(t), int32_t(py), int32_t(run_begin), int32_t(px)});
          run_begin = -1;
        }
      }
    }
  }
  sort_spans(out);
  return out;
}

std::vector<InputTriangle> random_grid_triangles(TestRng& rng, int count, double lo_x, double hi_x,
                                                 double lo_y, double hi_y, int grid_bits,
                                                 double max_size) {
  const double step = std::ldexp(1.0, -grid_bits);
  std::vector<InputTriangle> tris;
  tris.reserve(count);
  auto grid = [&](double lo, double hi) {
    return double(rng.range(int64_t(lo / step), int64_t(hi / step) - 1)) * step;
  };
  for (int n = 0; n < count; ++n) {
    InputTriangle t;
    t.x[0] = grid(lo_x, hi_x);
    t.y[0] = grid(lo_y, hi_y);
    for (int i = 1; i < 3; ++i) {
      t.x[i] = std::clamp(t.x[0] + grid(-max_size, max_size), lo_x, hi_x - step);
      t.y[i] = std::clamp(t.y[0] + grid(-max_size, max_size), lo_y, hi_y - step);
    }
    tris.push_back(t);
  }
  return tris;
}

}  // namespace trirast::test
