// The Verilated RTL of the half-space tile unit (rtl/trirast_halfspace.f, engine "halfspace-rtl"),
// in every Verilated configuration (StampSize / TileSize / walk order): its spans equal the
// golden's, span for span, and its cycles equal the SystemC model's (halfspace-sc,
// docs/timing.md "The half-space unit") for every triangle: accept, first span, done, spans,
// pixels and stall cycles, with the sink always ready and with stalling sinks and shallow FIFOs.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/setup.hpp"
#include "golden/golden.hpp"
#include "reference/reference_raster.hpp"
#include "sc/sc_engine.hpp"
#include "scene/scene.hpp"
#include "verilator/rtl_hs_engine.hpp"

namespace trirast {
namespace {

struct Built {
  int stamp, tile;
  HsWalk walk;
};
const Built kBuilt[] = {{2, 8, HsWalk::Zigzag}, {4, 16, HsWalk::Row}, {1, 0, HsWalk::Zigzag}};

size_t expect_equal(const SetupResult& setup, const RasterConfig& cfg, const std::string& what) {
  EngineResult rtl, sc;
  make_rtl_halfspace_engine()->run(setup, cfg, rtl);
  make_halfspace_model_engine()->run(setup, cfg, sc);
  SpanList g;
  for (const TriangleSetup& t : setup.tris) golden_triangle(t, cfg, g);
  sort_spans(g);
  sort_spans(rtl.spans);
  EXPECT_TRUE(rtl.spans == g) << what << ": " << rtl.spans.size() << " rtl spans, " << g.size()
                              << " golden";
  EXPECT_EQ(rtl.cycles.size(), sc.cycles.size()) << what;
  int reported = 0;
  for (size_t i = 0; i < std::min(rtl.cycles.size(), sc.cycles.size()); ++i) {
    const TriangleCycles& a = rtl.cycles[i];
    const TriangleCycles& b = sc.cycles[i];
    if (a.tri == b.tri && a.accept_cycle == b.accept_cycle &&
        a.first_span_cycle == b.first_span_cycle && a.done_cycle == b.done_cycle &&
        a.spans == b.spans && a.pixels == b.pixels && a.stall_cycles == b.stall_cycles)
      continue;
    ADD_FAILURE() << what << ": triangle " << a.tri << " rtl (" << a.accept_cycle << ","
                  << a.first_span_cycle << "," << a.done_cycle << "," << a.spans << "," << a.pixels
                  << "," << a.stall_cycles << ") sc (" << b.accept_cycle << ","
                  << b.first_span_cycle << "," << b.done_cycle << "," << b.spans << "," << b.pixels
                  << "," << b.stall_cycles << ")";
    if (++reported == 5) break;
  }
  EXPECT_EQ(rtl.total_cycles, sc.total_cycles) << what;
  return rtl.cycles.size();
}

RasterConfig config(const Built& b) {
  RasterConfig cfg;
  cfg.hs_stamp = b.stamp;
  cfg.hs_tile = b.tile;
  cfg.hs_walk = b.walk;
  return cfg;
}

std::string name(const Built& b, const std::string& sink, int depth) {
  return "stamp " + std::to_string(b.stamp) + " tile " + std::to_string(b.tile) + " " +
         hs_walk_name(b.walk) + " sink " + sink + " depth " + std::to_string(depth);
}

TEST(RtlHalfspace, RandomTrianglesEveryConfigurationSinkAndDepth) {
  test::TestRng rng(1515);
  auto tris = test::random_grid_triangles(rng, 120, -20, 140, -20, 100, 2, 12);
  auto big = test::random_grid_triangles(rng, 120, -20, 140, -20, 100, 8, 60);
  tris.insert(tris.end(), big.begin(), big.end());
  size_t n = 0;
  for (const Built& b : kBuilt)
    for (const char* sink : {"none", "periodic:1:3", "random:5:70"})
      for (int depth : {1, 2, 8}) {
        RasterConfig cfg = config(b);
        cfg.width = 128;
        cfg.height = 96;
        cfg.sink_stall = sink;
        cfg.fifo_depth = depth;
        n += expect_equal(setup_scene(tris, cfg), cfg, name(b, sink, depth));
      }
  EXPECT_GT(n, 5000u);
}

TEST(RtlHalfspace, HardCasesAndMeshes) {
  for (const Built& b : kBuilt)
    for (const char* spec : {"builtin:hard-all", "builtin:sphere"})
      for (const char* sink : {"none", "random:9:40"}) {
        if (std::string(spec) == "builtin:sphere" && std::string(sink) != "none") continue;
        RasterConfig cfg = config(b);
        cfg.sink_stall = sink;
        const SetupResult setup = setup_scene(load_scene(spec, cfg, CameraOptions{}).tris, cfg);
        expect_equal(setup, cfg, std::string(spec) + " " + name(b, sink, cfg.fifo_depth));
      }
}

TEST(RtlHalfspace, UnbuiltConfigurationIsNamed) {
  RasterConfig cfg;
  cfg.hs_stamp = 4;
  cfg.hs_tile = 8;
  const SetupResult setup = setup_scene({}, cfg);
  EngineResult r;
  try {
    make_rtl_halfspace_engine()->run(setup, cfg, r);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--stamp 4 --tile 8"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace trirast
