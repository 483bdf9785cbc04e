// The half-space tile unit's datapath (model/halfspace_*) against the golden rasterizer:
// at every stamp size (1, 2, 4), tile size (none, 8, 16) and walk order, the span lists are
// identical (the same spans, not only the same pixels) on the acceptance scenes, on random
// triangles and at other precisions. Plus the walker's own claims: the zig-zag walk tests no more
// units than the row walk, and accepted tiles appear.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "common/span_diff.hpp"
#include "golden/golden.hpp"
#include "scene/scene.hpp"
#include "halfspace/halfspace_unit.hpp"
#include "support/scene_helpers.hpp"

namespace trirast {
namespace {

using test::HalfspaceShape;

// Runs every configuration on one set-up scene; returns the work of the last one's row and
// zig-zag walks through `units` (indexed [stamp][tile][walk]) for the walker checks.
void expect_all_equal(const SetupResult& setup, RasterConfig cfg, const std::string& what) {
  const SpanList g = test::golden_spans(setup, cfg);
  for (const HalfspaceShape& h : test::every_halfspace_shape()) {
    cfg = test::with_halfspace_shape(cfg, h);
    EngineResult r;
    make_halfspace_datapath_engine()->run(setup, cfg, r);
    EXPECT_EQ(r.work["spans"], r.spans.size());
    EXPECT_EQ(int64_t(r.work["pixels"]), count_pixels(r.spans));
    sort_spans(r.spans);
    if (r.spans == g) continue;
    const SpanDiff d = diff_spans(g, r.spans);
    ADD_FAILURE() << what << ", " << test::halfspace_shape_name(h) << ": " << g.size()
                  << " golden spans, " << r.spans.size() << " unit spans; " << d.missing_pixels
                  << " missing, " << d.extra_pixels << " extra pixels";
  }
}

std::vector<std::string> acceptance_scenes() {
  std::vector<std::string> scenes;
  for (const BuiltinInfo& b : builtin_scenes())
    if (b.name.rfind("hard-", 0) == 0 && b.name != "hard-all") scenes.push_back("builtin:" + b.name);
  for (const char* f : {"cube.obj", "cube.off"})
    scenes.push_back(std::string(TRIRAST_SOURCE_DIR) + "/tests/data/" + f);
  for (const char* m : {"builtin:sphere", "builtin:torus", "builtin:surface", "builtin:mixed",
                        "builtin:lowpoly-near", "builtin:highpoly-far"})
    scenes.push_back(m);
  return scenes;
}

TEST(HalfspaceDatapath, EqualsGoldenOnAcceptanceScenesAtEveryStampTileAndWalk) {
  int scenes = 0;
  for (const std::string& sc : acceptance_scenes()) {
    RasterConfig cfg;
    const Scene s = load_scene(sc, cfg, CameraOptions{});
    expect_all_equal(setup_scene(s.tris, cfg), cfg, sc);
    ++scenes;
  }
  EXPECT_GT(scenes, 10);
}

TEST(HalfspaceDatapath, EqualsGoldenAtOtherPrecisions) {
  // S = 8 is the acceptance scenes' precision.
  for (int s : {0, 3}) {
    const RasterConfig cfg = test::config_at(s, 800, 600);
    const Scene sc = make_builtin("hard-all", cfg, CameraOptions{});
    expect_all_equal(setup_scene(sc.tris, cfg), cfg, "hard-all S=" + std::to_string(s));
  }
}

// splitmix64 with a fixed seed: every run checks the same triangles.
uint64_t mix(uint64_t& s) {
  uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

TEST(HalfspaceDatapath, EqualsGoldenOnRandomTriangles) {
  RasterConfig cfg;
  cfg.width = 300;
  cfg.height = 200;
  uint64_t seed = 15;
  std::vector<InputTriangle> tris;
  for (int i = 0; i < 3000; ++i) {
    InputTriangle t{};
    // Sizes from sub-pixel slivers to larger than the viewport, 1/256 grid.
    const int64_t ext = (i % 3 == 0) ? 3 : (i % 3 == 1) ? 40 : 400;
    const double cx = double(mix(seed) % 340) - 20, cy = double(mix(seed) % 240) - 20;
    for (int k = 0; k < 3; ++k) {
      t.x[k] = cx + double(int64_t(mix(seed) % uint64_t(2 * ext * 256)) - ext * 256) / 256.0;
      t.y[k] = cy + double(int64_t(mix(seed) % uint64_t(2 * ext * 256)) - ext * 256) / 256.0;
    }
    tris.push_back(t);
  }
  const SetupResult setup = setup_scene(tris, cfg);
  ASSERT_GT(setup.tris.size(), 2500u);
  expect_all_equal(setup, cfg, "random");
}

TEST(HalfspaceDatapath, WalkerWorkIsPlausible) {
  // One large triangle: 16x16 tiles are accepted inside it; the zig-zag and forward walks, which
  // end a band after its last non-rejected tile, test fewer units than the row walk.
  RasterConfig cfg;
  cfg.halfspace.tile = 16;
  std::vector<InputTriangle> tris = {{{10, 500, 30}, {10, 40, 400}, 0}};
  const SetupResult setup = setup_scene(tris, cfg);
  ASSERT_EQ(setup.tris.size(), 1u);
  uint64_t units[3];
  for (HalfspaceWalk w : {HalfspaceWalk::Row, HalfspaceWalk::Zigzag, HalfspaceWalk::Forward}) {
    cfg.halfspace.walk = w;
    EngineResult r;
    make_halfspace_datapath_engine()->run(setup, cfg, r);
    units[int(w)] = r.work["hs_units_tested"];
    EXPECT_GT(r.work["hs_tiles_accepted"], 100u);
    EXPECT_GT(r.work["hs_units_rejected"], 0u);
  }
  EXPECT_LT(units[1], units[0]);
  EXPECT_LT(units[2], units[0]);
}

// A partial tile's stamp values of the edges that cross the tile fit UnitWidths::hs_stamp_value
// bits, and hard-large-coords needs every one of them at 8- and 16-pixel tiles: the width is not
// loose, and one bit fewer (a planted RTL or datapath bug) fails on that scene.
TEST(HalfspaceDatapath, HardLargeCoordsReachTheTileRelativeStampWidth) {
  for (int tile : {8, 16}) {
    RasterConfig cfg;
    cfg.halfspace.tile = tile;
    const UnitWidths w = unit_widths(cfg);
    const Scene sc = make_builtin("hard-large-coords", cfg, CameraOptions{});
    const SetupResult setup = setup_scene(sc.tris, cfg);
    const HalfspaceSetupStage stage(cfg);
    const HalfspaceTileWalker walker(cfg);
    int64_t most = 0;  // the largest |value| of a crossing edge at a pixel of a partial tile
    for (const TriangleSetup& t : setup.tris) {
      const HalfspaceSetupOut s = stage.run(t);
      if (s.empty) continue;
      for (int64_t j0 = 0; j0 <= s.Ymax; j0 += tile)
        for (int64_t i0 = 0; i0 <= s.Xmax; i0 += tile) {
          const HalfspaceUnitTest u = walker.classify(s, i0, j0);
          if (u.cls != HalfspaceClass::Partial) continue;
          for (int k = 0; k < 3; ++k) {
            if (u.edges_inside >> k & 1u) continue;
            const HalfspaceEdge& e = s.edge[k];
            for (int64_t j = j0; j < j0 + tile; ++j)
              for (int64_t i = i0; i < i0 + tile; ++i) {
                const int64_t v = e.E0 + i * e.a + j * e.b;
                EXPECT_TRUE(fits_signed(v, w.hs_stamp_value)) << "tile " << tile << ": " << v;
                most = std::max(most, v < 0 ? -v : v);
              }
          }
        }
    }
    EXPECT_FALSE(fits_signed(most, w.hs_stamp_value - 1)) << "tile " << tile << ": " << most;
  }
}

TEST(HalfspaceDatapath, RejectsBadParameters) {
  RasterConfig cfg;
  cfg.halfspace.stamp = 3;
  EXPECT_THROW(HalfspaceUnit u(cfg), std::invalid_argument);
  cfg.halfspace.stamp = 2;
  cfg.halfspace.tile = 4;
  EXPECT_THROW(HalfspaceUnit u(cfg), std::invalid_argument);
}

}  // namespace
}  // namespace trirast
