#include "reference/watertight.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace trirast::test {

namespace {

using Key = std::pair<std::pair<int64_t, int64_t>, std::pair<int64_t, int64_t>>;

Key edge_key(const Vec2i& a, const Vec2i& b) {
  auto pa = std::make_pair(a.x, a.y), pb = std::make_pair(b.x, b.y);
  return pa < pb ? Key{pa, pb} : Key{pb, pa};
}

// Closed-segment test for a point known to be on the line through a and b.
bool within_segment(const Vec2i& a, const Vec2i& b, int64_t x, int64_t y) {
  return x >= std::min(a.x, b.x) && x <= std::max(a.x, b.x) && y >= std::min(a.y, b.y) &&
         y <= std::max(a.y, b.y);
}

}  // namespace

WatertightResult check_watertight(const SetupResult& setup, const SpanList& spans,
                                  const RasterConfig& cfg) {
  WatertightResult r;
  std::vector<uint8_t> count(size_t(cfg.width) * cfg.height, 0);
  for (const Span& s : spans)
    for (int32_t x = s.x_begin; x < s.x_end; ++x) {
      uint8_t& c = count[size_t(s.y) * cfg.width + x];
      if (c < 255) ++c;
    }
  // Outer boundary: edges used by exactly one triangle.
  std::map<Key, int> uses;
  for (const TriangleSetup& t : setup.tris)
    for (int i = 0; i < 3; ++i) ++uses[edge_key(t.v[i], t.v[(i + 1) % 3])];
  std::vector<std::pair<Vec2i, Vec2i>> boundary;
  for (const auto& kv : uses)
    if (kv.second == 1)
      boundary.push_back({Vec2i{kv.first.first.first, kv.first.first.second},
                          Vec2i{kv.first.second.first, kv.first.second.second}});
  // A centre on any outer boundary edge (not only the edges of the triangle being scanned: a
  // vertex of an interior triangle can sit on the outline) may stay uncovered.
  auto on_outline = [&](int64_t x, int64_t y) {
    for (const auto& [a, b] : boundary) {
      const int64_t cross = (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
      if (cross == 0 && within_segment(a, b, x, y)) return true;
    }
    return false;
  };

  for (int32_t py = 0; py < cfg.height; ++py)
    for (int32_t px = 0; px < cfg.width; ++px) {
      const uint8_t c = count[size_t(py) * cfg.width + px];
      if (c >= 1) ++r.covered;
      if (c > 1) {
        ++r.doubled;
        if (r.first_problem.empty())
          r.first_problem = "pixel (" + std::to_string(px) + "," + std::to_string(py) +
                            ") covered " + std::to_string(c) + " times";
      }
    }
  // Holes: scan each triangle's box for uncovered centres that are inside or on it.
  for (const TriangleSetup& t : setup.tris) {
    if (t.box.empty()) continue;
    for (int32_t py = t.box.y0; py <= t.box.y1; ++py)
      for (int32_t px = t.box.x0; px <= t.box.x1; ++px) {
        if (count[size_t(py) * cfg.width + px] != 0) continue;
        const int64_t cx = pixel_centre(px, cfg), cy = pixel_centre(py, cfg);
        int64_t e[3];
        bool closed_inside = true;
        for (int i = 0; i < 3; ++i) {
          e[i] = t.edge[i].eval(cx, cy);
          closed_inside = closed_inside && e[i] >= 0;
        }
        if (!closed_inside) continue;
        if (on_outline(cx, cy)) continue;
        ++r.holes;
        count[size_t(py) * cfg.width + px] = 255;  // count each hole once
        if (r.first_problem.empty())
          r.first_problem = "hole at pixel (" + std::to_string(px) + "," + std::to_string(py) +
                            ") inside triangle " + std::to_string(t.index);
      }
  }
  return r;
}

}  // namespace trirast::test
