// The second-generation unit's SystemC model (improved2-sc, docs/gen2-design.md, "The C++
// datapath and SystemC model"): its spans equal the golden's in both corner forms, whatever the
// sink; an empty box retires in the box stage; N > 1 and traces are refused. Its cycles against
// the whole-unit prototype's RTL (scripts/gen2_study/g2_unit.sv) are the ctest
// sc_improved2_vs_rtl_prototype (tests/sc/CMakeLists.txt).
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/setup.hpp"
#include "golden/golden.hpp"
#include "sc/sc_engine.hpp"
#include "scene/scene.hpp"

namespace trirast {
namespace {

EngineResult run_model(const SetupResult& setup, const RasterConfig& cfg) {
  EngineResult r;
  make_improved2_model_engine()->run(setup, cfg, r);
  return r;
}

SetupResult builtin_setup(const std::string& name, const RasterConfig& cfg) {
  return setup_scene(make_builtin(name, cfg, CameraOptions{}).tris, cfg);
}

TEST(ScImproved2, SpansEqualGoldenInBothFormsAndSinks) {
  for (const char* scene : {"hard-all", "mixed", "sphere", "highpoly-far"}) {
    RasterConfig cfg;
    const SetupResult setup = builtin_setup(scene, cfg);
    EngineResult g;
    make_golden_engine()->run(setup, cfg, g);
    sort_spans(g.spans);
    for (int form : {0, 1})
      for (const char* sink : {"none", "periodic:2:1", "random:5:40"}) {
        SCOPED_TRACE(std::string(scene) + " form " + std::to_string(form) + " sink " + sink);
        cfg.g2_corner_form = form;
        cfg.sink_stall = sink;
        cfg.fifo_depth = 4;
        EngineResult r = run_model(setup, cfg);
        sort_spans(r.spans);
        EXPECT_TRUE(r.spans == g.spans);
        ASSERT_EQ(r.cycles.size(), setup.tris.size());
        uint64_t spans = 0;
        for (size_t i = 0; i < r.cycles.size(); ++i) {
          const TriangleCycles& c = r.cycles[i];
          EXPECT_EQ(c.tri, setup.tris[i].index);
          EXPECT_LE(c.accept_cycle, c.first_span_cycle);
          EXPECT_LE(c.first_span_cycle, c.done_cycle);
          if (i > 0) {
            EXPECT_LT(r.cycles[i - 1].accept_cycle, c.accept_cycle);
          }
          spans += c.spans;
        }
        EXPECT_EQ(spans, g.spans.size());
      }
  }
}

// An empty box retires in a + 1 and the port takes the next triangle in that same cycle.
TEST(ScImproved2, EmptyBoxRetiresInTheBoxStage) {
  RasterConfig cfg;
  std::vector<InputTriangle> tris(3);
  for (auto& t : tris) t = InputTriangle{{10.6, 11.4, 10.6}, {10.6, 10.6, 11.4}, 0};
  const EngineResult r = run_model(setup_scene(tris, cfg), cfg);
  ASSERT_EQ(r.cycles.size(), 3u);
  for (uint64_t i = 0; i < 3; ++i) {
    EXPECT_EQ(r.cycles[i].accept_cycle, i);
    EXPECT_EQ(r.cycles[i].done_cycle, i + 1);
    EXPECT_EQ(r.cycles[i].spans, 0u);
  }
  EXPECT_EQ(r.total_cycles, 4u);
}

TEST(ScImproved2, RefusesOtherEndpointsAndTraces) {
  RasterConfig cfg;
  const SetupResult setup = builtin_setup("hard-all", cfg);
  cfg.endpoints = 2;
  cfg.fifo_depth = 8;
  try {
    run_model(setup, cfg);
    ADD_FAILURE() << "N = 2 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--endpoints: improved2-sc models N = 1 only"),
              std::string::npos)
        << e.what();
  }
  cfg.endpoints = 1;
  cfg.trace_path = "/tmp/never.vcd";
  EXPECT_THROW(run_model(setup, cfg), std::invalid_argument);
}

}  // namespace
}  // namespace trirast
