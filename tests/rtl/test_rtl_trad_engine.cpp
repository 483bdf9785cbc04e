// The Verilated RTL of the traditional-Bresenham unit (rtl/trad/trirast_trad_*.sv, engine "trad-rtl"):
// its spans equal the C++ trad model's (model/trad_bresenham.*, engine make_trad_datapath_engine),
// pixel for pixel, and its cycles equal the SystemC trad model's (engine "trad-sc", docs/timing.md
// "The traditional unit"): accept, first span, done and stall cycles of every triangle, with the
// sink always ready and with stalling sinks, on the hard cases, random triangles and meshes.
// Nothing here is a stored result: every expectation comes from running the two models.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/setup.hpp"
#include "engines.hpp"
#include "common/cycle_columns.hpp"
#include "trad/trad_rtl_engine.hpp"
#include "scene/scene.hpp"
#include "trad/trad_sc.hpp"
#include "trad/trad_bresenham.hpp"
#include "support/rtl_helpers.hpp"

namespace trirast {
namespace {

using test::scene;

EngineResult run_rtl_trad(const SetupResult& setup, const RasterConfig& cfg, uint32_t seed = 1) {
  return test::run_verilated(rtl::run_rtl_trad, setup, cfg, seed);
}

// Spans of the C++ model, cycles of the SystemC model, against one RTL run. Returns the number
// of triangles compared.
size_t expect_trad(const SetupResult& setup, const RasterConfig& cfg, const std::string& what) {
  EngineResult rtl = run_rtl_trad(setup, cfg);
  EngineResult cpp, sc;
  make_trad_datapath_engine()->run(setup, cfg, cpp);
  make_trad_sc_engine()->run(setup, cfg, sc);
  sort_spans(rtl.spans);
  sort_spans(cpp.spans);
  EXPECT_EQ(test::first_span_difference(rtl.spans, "rtl", cpp.spans, "trad"), "") << what;
  EXPECT_EQ(rtl.work["trad_collinear"], cpp.work["trad_collinear"]) << what;
  EXPECT_EQ(sc.work["trad_collinear"], cpp.work["trad_collinear"]) << what;
  EXPECT_EQ(rtl.cycles.size(), setup.tris.size()) << what;
  EXPECT_EQ(sc.cycles.size(), setup.tris.size()) << what;
  // Every column, the stage breakdown too (docs/timing.md, "Outputs").
  std::string rows;
  EXPECT_EQ(test::cycle_rows_mismatch(rtl.cycles, "rtl", sc.cycles, "trad model", what, rows), 0u)
      << rows;
  EXPECT_EQ(rtl.total_cycles, sc.total_cycles) << what;
  // The statistics: the model's module busy and stall cycles and Bresenham steps (its
  // rows_visited has no RTL counterpart).
  int stats = 0;
  EXPECT_EQ(test::statistics_mismatch(sc.work, rtl.work, {"rows_visited"}, stats), "") << what;
  EXPECT_GE(stats, 12) << what;
  return setup.tris.size();
}

RasterConfig cfg_with(const std::string& sink, int depth, int endpoints = 1) {
  RasterConfig cfg;
  cfg.sink_stall = sink;
  cfg.fifo_depth = depth;
  cfg.endpoints = endpoints;
  cfg.validate();
  return cfg;
}

const char* const kSinks[] = {"none", "random:7:30", "periodic:3:2"};

TEST(RtlTrad, RegisteredNotExact) {
  const EngineInfo* e = find_engine("trad-rtl");
  ASSERT_NE(e, nullptr);
  EXPECT_FALSE(e->exact);
}

// The worked example of docs/timing.md ("Closed form", TradSmallTriangle): integer vertices
// (0,0), (4,0), (0,2); c = 5, 2, 1; spans popped in 9, 11, 12.
TEST(RtlTrad, ClosedFormSmallTriangle) {
  const RasterConfig cfg = cfg_with("none", 8);
  InputTriangle t{};
  t.x[0] = 0.5, t.y[0] = 0.5, t.x[1] = 4.5, t.y[1] = 0.5, t.x[2] = 0.5, t.y[2] = 2.5;
  const SetupResult setup = setup_scene({t}, cfg);
  ASSERT_EQ(setup.tris.size(), 1u);
  const EngineResult r = run_rtl_trad(setup, cfg);
  ASSERT_EQ(r.cycles.size(), 1u);
  EXPECT_EQ(r.cycles[0].accept_cycle, 0u);
  EXPECT_EQ(r.cycles[0].first_span_cycle, 9u);
  EXPECT_EQ(r.cycles[0].done_cycle, 12u);
  EXPECT_EQ(r.total_cycles, 13u);
  EXPECT_EQ(r.spans.size(), 3u);
}

// hard-all walks 33.6 million cycles (long off-screen edges): two sinks keep the test short.
TEST(RtlTrad, HardCasesTwoSinks) {
  for (const char* sink : {"none", "random:7:30"}) {
    const RasterConfig cfg = cfg_with(sink, 8);
    expect_trad(scene("builtin:hard-all", cfg), cfg, std::string("hard-all sink=") + sink);
  }
}

// 2,400 random triangles of every size class, by three sinks and two FIFO depths (1: every row
// waits for the previous span to leave).
TEST(RtlTrad, RandomTriangles) {
  size_t compared = 0;
  for (const char* sink : kSinks)
    for (int depth : {1, 8}) {
      const RasterConfig cfg = cfg_with(sink, depth);
      compared += expect_trad(scene("builtin:random:count=2400,size=mixed,seed=11", cfg), cfg,
                              std::string("random sink=") + sink + " depth=" + std::to_string(depth));
    }
  EXPECT_EQ(compared, 6u * 2400u);
}

// Small triangles (many collinear after quantization, many back-to-back hand-offs).
TEST(RtlTrad, SmallAndTinyTriangles) {
  for (const char* size : {"tiny", "small"}) {
    const RasterConfig cfg = cfg_with("random:3:40", 2);
    expect_trad(scene(std::string("builtin:random:count=3000,seed=5,size=") + size, cfg), cfg,
                std::string("random size=") + size);
  }
}

TEST(RtlTrad, Meshes) {
  for (const char* sink : {"none", "periodic:3:2"}) {
    const RasterConfig cfg = cfg_with(sink, 8);
    expect_trad(scene("builtin:torus", cfg), cfg, std::string("torus sink=") + sink);
    expect_trad(scene(std::string(TRIRAST_SOURCE_DIR) + "/tests/data/cube.obj", cfg), cfg,
                std::string("cube.obj sink=") + sink);
  }
}

// --endpoints does not apply to the traditional unit: every value the trad model accepts gives
// the same spans and cycles there and here.
TEST(RtlTrad, EveryEndpointsSetting) {
  for (int n : {1, 2, 4}) {
    const RasterConfig cfg = cfg_with("random:7:30", 4, n);
    expect_trad(scene("builtin:hard-tiny", cfg), cfg, "hard-tiny endpoints=" + std::to_string(n));
  }
}

// Rows outside the viewport are walked (and cost cycles) but make no span; a small viewport.
TEST(RtlTrad, ClippedViewport) {
  RasterConfig cfg = cfg_with("periodic:3:2", 8);
  cfg.width = 200;
  cfg.height = 120;
  cfg.validate();
  expect_trad(scene("builtin:random:count=1500,size=large,seed=4,margin=100", cfg), cfg,
              "clipped viewport");
}

TEST(RtlTrad, IndependentOfTheXSeed) {
  const RasterConfig cfg = cfg_with("random:7:30", 8);
  const SetupResult setup = scene("builtin:random:count=300,seed=9", cfg);
  const EngineResult a = run_rtl_trad(setup, cfg, 1), b = run_rtl_trad(setup, cfg, 12345);
  EXPECT_EQ(a.spans, b.spans);
  ASSERT_EQ(a.cycles.size(), b.cycles.size());
  for (size_t p = 0; p < a.cycles.size(); ++p) EXPECT_EQ(a.cycles[p].done_cycle, b.cycles[p].done_cycle);
}

TEST(RtlTrad, RefusesUnbuiltWidths) {
  RasterConfig cfg;
  cfg.subpixel_bits = 5;  // no build (docs/synth.md: S = 8, 4, 0)
  cfg.validate();
  EngineResult r;
  try {
    rtl::run_rtl_trad(SetupResult{}, cfg, rtl::RtlRunOptions{}, r);
    FAIL() << "accepted --subpixel-bits 5";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--subpixel-bits"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace trirast
