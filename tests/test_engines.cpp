// Every engine in the registry on the foundation's scenes: the exact ones give the golden's spans
// span for span; every engine runs on every built-in scene without error.
#include <gtest/gtest.h>

#include "common/engine.hpp"
#include "engines.hpp"
#include "common/span_diff.hpp"
#include "scene/scene.hpp"

namespace trirast {
namespace {

SpanList run_spans(const EngineInfo& info, const SetupResult& setup, const RasterConfig& cfg) {
  EngineResult r;
  info.make()->run(setup, cfg, r);
  sort_spans(r.spans);
  return r.spans;
}

// Scenes of the foundation's acceptance list that are not random: every hard case, meshes through
// Assimp, the mesh built-ins.
std::vector<std::string> acceptance_scenes() {
  std::vector<std::string> scenes;
  for (const BuiltinInfo& b : builtin_scenes())
    if (b.name.rfind("hard-", 0) == 0 && b.name != "hard-all") scenes.push_back("builtin:" + b.name);
  for (const char* f : {"cube.obj", "cube.ply", "cube.stl", "cube.off", "cube.gltf"})
    scenes.push_back(std::string(TRIRAST_SOURCE_DIR) + "/tests/data/" + f);
  for (const char* m : {"builtin:sphere", "builtin:torus", "builtin:surface", "builtin:mixed",
                        "builtin:lowpoly-near", "builtin:highpoly-far"})
    scenes.push_back(m);
  return scenes;
}

// Engines whose whole-suite runs are long get the same scenes in their own test programs.
bool runs_here(const EngineInfo& e) {
  return e.name != "improved-rtl" && e.name != "trad-rtl" && e.name != "halfspace-rtl" &&
         e.name != "improved2-rtl";
}

TEST(ExactEngines, AgreeWithGoldenOnEveryAcceptanceScene) {
  const EngineInfo* golden = find_engine("golden");
  ASSERT_NE(golden, nullptr);
  int compared = 0;
  for (const EngineInfo& e : engine_registry()) {
    if (!e.exact || e.name == "golden" || !runs_here(e)) continue;
    for (const std::string& scene : acceptance_scenes()) {
      SCOPED_TRACE(e.name + " on " + scene);
      RasterConfig cfg;
      const Scene s = load_scene(scene, cfg, CameraOptions{});
      const SetupResult setup = setup_scene(s.tris, cfg);
      const SpanDiff d = diff_spans(run_spans(*golden, setup, cfg), run_spans(e, setup, cfg));
      EXPECT_TRUE(d.identical_spans) << d.missing_pixels << " missing, " << d.extra_pixels << " extra";
      ++compared;
    }
  }
  EXPECT_GT(compared, 0) << "no exact engine besides the golden is registered";
}

TEST(ExactEngines, AgreeWithGoldenAtOtherPrecisionsAndBoundaryModes) {
  const EngineInfo* golden = find_engine("golden");
  for (const EngineInfo& e : engine_registry()) {
    if (!e.exact || e.name == "golden" || !runs_here(e)) continue;
    for (int s : {0, 3, 8})
      for (BoundaryMode mode : {BoundaryMode::Step, BoundaryMode::Divide}) {
        RasterConfig cfg;
        cfg.subpixel_bits = s;
        cfg.boundary = mode;
        cfg.width = 800;
        cfg.height = 600;
        SCOPED_TRACE(e.name + " S=" + std::to_string(s) + " " + boundary_mode_name(mode));
        const SetupResult setup =
            setup_scene(make_builtin("hard-all", cfg, CameraOptions{}).tris, cfg);
        const SpanDiff d = diff_spans(run_spans(*golden, setup, cfg), run_spans(e, setup, cfg));
        EXPECT_TRUE(d.identical_spans) << d.missing_pixels << " missing, " << d.extra_pixels;
      }
  }
}

TEST(AllEngines, RunOnEveryBuiltinScene) {
  for (const EngineInfo& e : engine_registry()) {
    if (!runs_here(e)) continue;
    for (const BuiltinInfo& b : builtin_scenes()) {
      SCOPED_TRACE(e.name + " on builtin:" + b.name);
      RasterConfig cfg;
      cfg.width = 640;
      cfg.height = 480;
      const Scene s = make_builtin(b.name, cfg, CameraOptions{});
      const SetupResult setup = setup_scene(s.tris, cfg);
      EngineResult r;
      EXPECT_NO_THROW(e.make()->run(setup, cfg, r));
      for (const Span& sp : r.spans) {  // whatever their coverage, spans stay in the viewport
        ASSERT_LT(sp.x_begin, sp.x_end);
        ASSERT_GE(sp.x_begin, 0);
        ASSERT_LE(sp.x_end, cfg.width);
        ASSERT_GE(sp.y, 0);
        ASSERT_LT(sp.y, cfg.height);
      }
    }
  }
}

}  // namespace
}  // namespace trirast
