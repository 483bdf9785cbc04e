#include "common/watertight.hpp"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace trirast {

WatertightResult check_watertight(const SetupResult& setup, const SpanList& spans,
                                  const RasterConfig& cfg) {
  WatertightResult r;
  const size_t W = size_t(cfg.width), H = size_t(cfg.height);
  std::vector<uint8_t> count(W * H, 0);
  for (const Span& s : spans) {
    if (s.y < 0 || size_t(s.y) >= H) continue;
    for (int32_t x = std::max(s.x_begin, 0); x < s.x_end && size_t(x) < W; ++x) {
      uint8_t& c = count[size_t(s.y) * W + size_t(x)];
      if (c < 255) ++c;
    }
  }
  for (size_t at = 0; at < count.size(); ++at) {
    if (count[at] >= 1) ++r.covered;
    if (count[at] > 1) {
      ++r.doubles;
      if (r.first_problem.empty())
        r.first_problem = "pixel (" + std::to_string(at % W) + "," + std::to_string(at / W) +
                          ") covered " + std::to_string(count[at]) + " times";
    }
  }
  // The outline: edges used by exactly one triangle (by their snapped end points).
  using Point = std::pair<int64_t, int64_t>;
  auto key = [](const Vec2i& a, const Vec2i& b) {
    Point pa{a.x, a.y}, pb{b.x, b.y};
    return pa < pb ? std::make_pair(pa, pb) : std::make_pair(pb, pa);
  };
  std::map<std::pair<Point, Point>, int> uses;
  for (const TriangleSetup& t : setup.tris)
    for (int i = 0; i < 3; ++i) ++uses[key(t.v[i], t.v[(i + 1) % 3])];
  // Pixels whose centre lies on an outline edge may stay uncovered (the rule leaves one side).
  // Such a centre is in the box of the edge's triangle, so scanning that box finds every one,
  // including a vertex of an inner triangle that sits on the outline.
  std::vector<uint8_t> outline(W * H, 0);
  for (const TriangleSetup& t : setup.tris) {
    if (t.box.empty()) continue;
    for (int i = 0; i < 3; ++i) {
      const Vec2i a = t.v[i], b = t.v[(i + 1) % 3];
      if (uses[key(a, b)] != 1) continue;
      const EdgeSetup& e = t.edge[i];
      for (int32_t py = t.box.y0; py <= t.box.y1; ++py)
        for (int32_t px = t.box.x0; px <= t.box.x1; ++px) {
          const int64_t cx = pixel_centre(px, cfg), cy = pixel_centre(py, cfg);
          if (e.eval(cx, cy) != 0) continue;
          if (cx < std::min(a.x, b.x) || cx > std::max(a.x, b.x) || cy < std::min(a.y, b.y) ||
              cy > std::max(a.y, b.y))
            continue;
          outline[size_t(py) * W + size_t(px)] = 1;
        }
    }
  }
  // Cracks: uncovered centres inside or on a triangle, off the outline; each counted once.
  for (const TriangleSetup& t : setup.tris) {
    if (t.box.empty()) continue;
    for (int32_t py = t.box.y0; py <= t.box.y1; ++py)
      for (int32_t px = t.box.x0; px <= t.box.x1; ++px) {
        const size_t at = size_t(py) * W + size_t(px);
        if (count[at] != 0 || outline[at]) continue;
        const int64_t cx = pixel_centre(px, cfg), cy = pixel_centre(py, cfg);
        if (t.edge[0].eval(cx, cy) < 0 || t.edge[1].eval(cx, cy) < 0 || t.edge[2].eval(cx, cy) < 0)
          continue;
        ++r.cracks;
        count[at] = 255;
        if (r.first_problem.empty())
          r.first_problem = "crack at pixel (" + std::to_string(px) + "," + std::to_string(py) +
                            ") inside triangle " + std::to_string(t.index);
      }
  }
  return r;
}

}  // namespace trirast
