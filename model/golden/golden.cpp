#include "golden/golden.hpp"

namespace trirast {

void golden_triangle(const TriangleSetup& t, const RasterConfig& cfg, SpanList& out) {
  if (t.box.empty()) return;
  const int64_t u = cfg.unit();
  const int64_t cx0 = pixel_centre(t.box.x0, cfg);
  for (int32_t y = t.box.y0; y <= t.box.y1; ++y) {
    const int64_t cy = pixel_centre(y, cfg);
    // Edge values (bias folded in) at the first pixel centre of the row; one add per step in x.
    int64_t e[3];
    for (int i = 0; i < 3; ++i) e[i] = t.edge[i].eval(cx0, cy) + t.edge[i].bias;
    int32_t begin = -1;
    int32_t x = t.box.x0;
    for (; x <= t.box.x1; ++x) {
      const bool inside = e[0] >= 0 && e[1] >= 0 && e[2] >= 0;
      if (inside && begin < 0) begin = x;
      if (!inside && begin >= 0) break;  // a row of a triangle is one run: leave at its end
      for (int i = 0; i < 3; ++i) e[i] += t.edge[i].A * u;
    }
    if (begin >= 0) out.push_back(Span{t.index, y, begin, x});
  }
}

namespace {

class GoldenEngine : public Engine {
 public:
  void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) override {
    for (const TriangleSetup& t : setup.tris) golden_triangle(t, cfg, out.spans);
  }
};

}  // namespace

std::unique_ptr<Engine> make_golden_engine() { return std::make_unique<GoldenEngine>(); }

}  // namespace trirast
