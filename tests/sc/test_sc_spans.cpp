// Spans of the SystemC models: the improved unit's equal the golden on every scene (hard cases,
// 100k random triangles, meshes), whatever the timing parameters; the timed traditional unit's
// equal the untimed one's. Several runs in one process go through the one elaborated model.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/setup.hpp"
#include "golden/golden.hpp"
#include "improved/improved_sc.hpp"
#include "trad/trad_sc.hpp"
#include "scene/scene.hpp"
#include "common/reference_raster.hpp"
#include "trad/trad_bresenham.hpp"
#include "common/unit_widths.hpp"

namespace trirast {
namespace {

SpanList sorted_spans(Engine& e, const SetupResult& setup, const RasterConfig& cfg,
                      EngineResult* keep = nullptr) {
  EngineResult r;
  e.run(setup, cfg, r);
  sort_spans(r.spans);
  if (keep) *keep = r;
  return r.spans;
}

// Golden against the model; also checks the cycles rows agree with the spans.
void expect_model_equals_golden(const Scene& scene, const RasterConfig& cfg) {
  const SetupResult setup = setup_scene(scene.tris, cfg);
  const SpanList golden = sorted_spans(*make_golden_engine(), setup, cfg);
  EngineResult r;
  const SpanList model = sorted_spans(*make_improved_sc_engine(), setup, cfg, &r);
  EXPECT_EQ(model.size(), golden.size()) << scene.name;
  EXPECT_TRUE(model == golden) << scene.name << ": the model's spans differ from the golden";
  ASSERT_EQ(r.cycles.size(), setup.tris.size());
  uint64_t spans = 0, pixels = 0;
  for (size_t i = 0; i < r.cycles.size(); ++i) {
    EXPECT_EQ(r.cycles[i].tri, setup.tris[i].index);
    EXPECT_LE(r.cycles[i].accept_cycle, r.cycles[i].first_span_cycle);
    EXPECT_LE(r.cycles[i].first_span_cycle, r.cycles[i].done_cycle);
    EXPECT_LT(r.cycles[i].done_cycle, r.total_cycles);
    spans += r.cycles[i].spans;
    pixels += r.cycles[i].pixels;
  }
  EXPECT_EQ(spans, golden.size());
  EXPECT_EQ(int64_t(pixels), count_pixels(golden));
}

Scene builtin(const std::string& spec, const RasterConfig& cfg) {
  return make_builtin(spec, cfg, CameraOptions{});
}

TEST(ScSpans, HardCasesEqualGolden) {
  for (BoundaryMode mode : {BoundaryMode::Step, BoundaryMode::Divide}) {
    RasterConfig cfg;
    cfg.boundary = mode;
    expect_model_equals_golden(builtin("hard-all", cfg), cfg);
  }
}

TEST(ScSpans, HardCasesWithEveryTimingParameter) {
  RasterConfig base;
  const Scene scene = builtin("hard-all", base);
  const SetupResult setup = setup_scene(scene.tris, base);
  const SpanList golden = sorted_spans(*make_golden_engine(), setup, base);
  for (int n : {1, 2, 4})
    for (const char* sink : {"periodic:2:3", "random:5:60"}) {
      RasterConfig cfg = base;
      cfg.endpoints = n;
      cfg.fifo_depth = n;
      cfg.sink_stall = sink;
      EXPECT_TRUE(sorted_spans(*make_improved_sc_engine(), setup, cfg) == golden)
          << "N=" << n << " sink " << sink;
    }
}

TEST(ScSpans, HundredThousandRandomEqualGolden) {
  RasterConfig cfg;
  test::TestRng rng(0x5C0DE15ull);  // fixed splitmix64 seed
  Scene s;
  s.name = "random 100k";
  const int classes[][2] = {{8, 4}, {2, 40}, {0, 300}};  // grid bits, max size (pixels)
  for (int k = 0; k < 3; ++k) {
    const int count = k == 0 ? 60000 : k == 1 ? 35000 : 5000;
    auto t = test::random_grid_triangles(rng, count, -80, cfg.width + 80, -80, cfg.height + 80,
                                         classes[k][0], classes[k][1]);
    s.tris.insert(s.tris.end(), t.begin(), t.end());
  }
  ASSERT_EQ(s.tris.size(), 100000u);
  expect_model_equals_golden(s, cfg);
  RasterConfig cfg4 = cfg;
  cfg4.endpoints = 4;
  cfg4.boundary = BoundaryMode::Divide;
  cfg4.sink_stall = "random:9:30";
  expect_model_equals_golden(s, cfg4);
}

TEST(ScSpans, MeshesEqualGolden) {
  RasterConfig cfg;
  for (const char* spec : {"sphere", "torus", "surface", "lowpoly-far", "lowpoly-near",
                           "highpoly-far", "highpoly-near", "mixed", "quad-grid", "fan:n=16"})
    expect_model_equals_golden(builtin(spec, cfg), cfg);
  for (const char* file : {"cube.obj", "cube.ply", "cube.stl", "cube.off", "cube.gltf"})
    expect_model_equals_golden(
        load_scene(std::string(TRIRAST_SOURCE_DIR) + "/tests/data/" + file, cfg, CameraOptions{}),
        cfg);
}

TEST(ScSpans, SubpixelZeroAndSmallViewport) {
  RasterConfig cfg;
  cfg.subpixel_bits = 0;
  cfg.width = 200;
  cfg.height = 150;
  expect_model_equals_golden(builtin("random:count=3000,size=mixed", cfg), cfg);
}

TEST(ScSpans, TradModelEqualsUntimedTrad) {
  RasterConfig cfg;
  for (const char* spec : {"hard-all", "mixed", "lowpoly-near", "highpoly-far"}) {
    const Scene scene = builtin(spec, cfg);
    const SetupResult setup = setup_scene(scene.tris, cfg);
    EngineResult untimed, timed;
    make_trad_datapath_engine()->run(setup, cfg, untimed);
    make_trad_sc_engine()->run(setup, cfg, timed);
    sort_spans(untimed.spans);
    sort_spans(timed.spans);
    EXPECT_TRUE(untimed.spans == timed.spans) << spec;
    EXPECT_EQ(timed.cycles.size(), setup.tris.size()) << spec;
    for (const char* key : {"trad_bresenham_steps", "rows_visited", "spans", "pixels"})
      EXPECT_EQ(untimed.work[key], timed.work[key]) << spec << " " << key;
  }
}

TEST(ScSpans, RepeatedRunsAreIdentical) {
  RasterConfig cfg;
  cfg.sink_stall = "random:3:40";
  const Scene scene = builtin("mixed", cfg);
  const SetupResult setup = setup_scene(scene.tris, cfg);
  EngineResult a, b, t, c;
  make_improved_sc_engine()->run(setup, cfg, a);
  make_trad_sc_engine()->run(setup, cfg, t);
  make_improved_sc_engine()->run(setup, cfg, b);
  auto engine = make_improved_sc_engine();
  engine->run(setup, cfg, c);
  for (const EngineResult* r : {&b, &c}) {
    EXPECT_EQ(r->spans, a.spans);
    EXPECT_EQ(r->total_cycles, a.total_cycles);
    ASSERT_EQ(r->cycles.size(), a.cycles.size());
    for (size_t i = 0; i < a.cycles.size(); ++i) {
      EXPECT_EQ(r->cycles[i].accept_cycle, a.cycles[i].accept_cycle);
      EXPECT_EQ(r->cycles[i].done_cycle, a.cycles[i].done_cycle);
    }
  }
}

TEST(ScSpans, WidthErrorIsThrownAndTheNextRunWorks) {
  RasterConfig cfg;
  cfg.box_bits = 4;  // boxes of at most 16 pixels
  const Scene scene = builtin("lowpoly-near", cfg);
  const SetupResult setup = setup_scene(scene.tris, cfg);
  EngineResult r;
  EXPECT_THROW(make_improved_sc_engine()->run(setup, cfg, r), WidthError);
  RasterConfig ok;
  expect_model_equals_golden(builtin("lowpoly-near", ok), ok);
}

TEST(ScSpans, EmptyScene) {
  RasterConfig cfg;
  const SetupResult setup = setup_scene({}, cfg);
  EngineResult r;
  make_improved_sc_engine()->run(setup, cfg, r);
  EXPECT_TRUE(r.spans.empty());
  EXPECT_TRUE(r.cycles.empty());
  EXPECT_EQ(r.total_cycles, 0u);
}

}  // namespace
}  // namespace trirast
