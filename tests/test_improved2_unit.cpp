// The second-generation improved unit's datapath (improved2-datapath, docs/improved2.md, "Views
// and files") against the golden rasterizer: spans identical on every
// built-in scene (every hard case among them), the meshes and random triangles at several
// precisions; and its gen2-only stages against their definitions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "common/setup.hpp"
#include "common/span_diff.hpp"
#include "golden/golden.hpp"
#include "common/reference_raster.hpp"
#include "scene/scene.hpp"
#include "improved2/improved2_unit.hpp"

namespace trirast {
namespace {

using test::TestRng;

SpanList sorted(SpanList s) {
  sort_spans(s);
  return s;
}

// Golden against improved2-datapath on a scene; returns the datapath's work counters.
std::map<std::string, uint64_t> expect_equals_golden(const std::vector<InputTriangle>& tris,
                                                     const RasterConfig& cfg,
                                                     const std::string& what) {
  const SetupResult setup = setup_scene(tris, cfg);
  EngineResult g, u;
  make_golden_engine()->run(setup, cfg, g);
  make_improved2_datapath_engine()->run(setup, cfg, u);
  const SpanDiff d = diff_spans(sorted(g.spans), sorted(u.spans));
  EXPECT_TRUE(d.identical_spans) << what << ": " << d.missing_pixels << " missing, "
                                 << d.extra_pixels << " extra pixels";
  EXPECT_EQ(u.work["spans"], u.spans.size()) << what;
  EXPECT_EQ(u.work["triangles"], setup.tris.size()) << what;
  EXPECT_EQ(u.work["empty_boxes"] + u.work["tiny_boxes"] + u.work["lane_boxes"], setup.tris.size())
      << what;
  return u.work;
}

TEST(Improved2Datapath, EveryBuiltinSceneEqualsGolden) {
  uint64_t tiny = 0, lanes = 0, scenes = 0;
  for (const BuiltinInfo& b : builtin_scenes()) {
    RasterConfig cfg;
    const Scene s = make_builtin(b.name, cfg, CameraOptions{});
    auto w = expect_equals_golden(s.tris, cfg, "builtin:" + b.name);
    tiny += w["tiny_boxes"];
    lanes += w["lane_boxes"];
    ++scenes;
  }
  EXPECT_GE(scenes, 20u);
  // Both paths of the unit ran: the direct 2x2 test and the lanes.
  EXPECT_GT(tiny, 1000u);
  EXPECT_GT(lanes, 1000u);
}

TEST(Improved2Datapath, MeshFilesEqualGolden) {
  for (const char* f : {"cube.obj", "cube.ply", "cube.stl", "cube.off", "cube.gltf"}) {
    RasterConfig cfg;
    const Scene s =
        load_scene(std::string(TRIRAST_SOURCE_DIR) + "/tests/data/" + f, cfg, CameraOptions{});
    expect_equals_golden(s.tris, cfg, f);
  }
}

TEST(Improved2Datapath, HardCasesAtOtherPrecisionsAndViewports) {
  for (int s : {0, 3, 8}) {
    RasterConfig cfg;
    cfg.subpixel_bits = s;
    cfg.width = 800;
    cfg.height = 600;
    expect_equals_golden(make_builtin("hard-all", cfg, CameraOptions{}).tris, cfg,
                         "hard-all S=" + std::to_string(s));
  }
}

TEST(Improved2Datapath, RandomSmallTrianglesEqualGolden) {
  // Mostly boxes of a few pixels (the direct test's and the lanes' border), on grids of 1/2^g.
  for (int grid : {0, 2, 8}) {
    RasterConfig cfg;
    cfg.width = 96;
    cfg.height = 64;
    TestRng rng{0x9e2 + uint64_t(grid)};
    const auto tris = test::random_grid_triangles(rng, 20000, -4, 100, -4, 68, grid, 4.0);
    auto w = expect_equals_golden(tris, cfg, "random grid " + std::to_string(grid));
    EXPECT_GT(w["tiny_boxes"], 100u);
  }
}

// The direct test's spans are the covered centres of the box, tested one by one.
TEST(Improved2Datapath, DirectTestIsTheFourCentreTests) {
  RasterConfig cfg;
  TestRng rng{77};
  BoxStage iface(cfg);
  uint64_t tested = 0, spans = 0;
  for (int n = 0; n < 20000; ++n) {
    const auto tris = test::random_grid_triangles(rng, 1, 10, 14, 10, 14, 3, 2.5);
    const SetupResult setup = setup_scene(tris, cfg);
    if (setup.tris.empty()) continue;
    const TriangleSetup& t = setup.tris[0];
    const BoxStageOut box = iface.run(t);
    if (box.empty || !Improved2DirectTest2x2::takes(box)) continue;
    const Improved2DirectTestOut d = Improved2DirectTest2x2::run(box);
    for (int j = 0; j < 2; ++j) {
      bool c[2];
      for (int i = 0; i < 2; ++i) {
        c[i] = i <= box.Xmax && j <= box.Ymax;
        for (int k = 0; k < 3; ++k) {
          const EdgeSetup& e = t.edge[k];
          c[i] = c[i] &&
                 e.eval(pixel_centre(box.x0 + i, cfg), pixel_centre(box.y0 + j, cfg)) + e.bias >= 0;
        }
      }
      ASSERT_EQ(d.valid[j], c[0] || c[1]) << "triangle " << n << " row " << j;
      if (d.valid[j]) {
        EXPECT_EQ(d.begin[j], c[0] ? 0 : 1);
        EXPECT_EQ(d.end[j], c[1] ? 2 : 1);
        ++spans;
      }
    }
    ++tested;
  }
  EXPECT_GT(tested, 2000u);
  EXPECT_GT(spans, 1000u);
}

// The digit-serial corner unit's run length: the fewest digits of 4 bits in which every operand of
// v0 and v1 fits as a two's complement number (edge 2 takes its operands from v0).
TEST(Improved2Datapath, CornerDigits) {
  RasterConfig cfg;  // S = 8: a pixel centre is x * 256 + 128
  TriangleSetup t{};
  for (auto& v : t.v) v = Vec2i{128, 128};
  Improved2CornerUnit c(cfg);
  EXPECT_EQ(c.digits(t, 0, 0), 1);  // all operands 0
  EXPECT_EQ(c.digits(t, 0, 1), 3);  // 256: 10 signed bits
  t.v[1] = Vec2i{128 + 8, 128};     // dx = -8: one digit
  EXPECT_EQ(c.digits(t, 0, 0), 1);
  t.v[1] = Vec2i{128 + 9, 128};  // dx = -9: two digits
  EXPECT_EQ(c.digits(t, 0, 0), 2);
  t.v[1] = Vec2i{128 - 7, 128};  // dx = 7: one digit
  EXPECT_EQ(c.digits(t, 0, 0), 1);
  t.v[1] = Vec2i{128 - 8, 128};  // dx = 8: two digits
  EXPECT_EQ(c.digits(t, 0, 0), 2);
  t.v[2] = Vec2i{128, 128 - (int64_t(1) << 23)};  // v2 is no operand
  EXPECT_EQ(c.digits(t, 0, 0), 2);
  t.v[0] = Vec2i{128, 128 - (int64_t(1) << 23)};  // 2^23: 25 signed bits, 7 digits
  EXPECT_EQ(c.digits(t, 0, 0), 7);
  t.v[0] = Vec2i{128, 128 + (int64_t(1) << 23)};  // -2^23: 24 signed bits, 6 digits
  EXPECT_EQ(c.digits(t, 0, 0), 6);
  EXPECT_EQ(Improved2CornerUnit::operand_vertex(0), 0);
  EXPECT_EQ(Improved2CornerUnit::operand_vertex(1), 1);
  EXPECT_EQ(Improved2CornerUnit::operand_vertex(2), 0);  // v0 lies on edge 2 (v2 -> v0)
}

// The redesigned lane's cycles on edges whose traversal and divisions are known.
TEST(Improved2Datapath, LaneCycles) {
  NormalizedEdge n{};
  n.horizontal = false;
  n.dir_down = true;
  n.D = 256;
  n.s = 512;
  n.T = 0;  // inside at row 0: T = 0 steps, enters
  // Xmax = 5: m = 3 + 1 = 4; slope 512 / 256 = 2 < 16, entry 0 / 256: no saturation.
  Improved2LaneWork w = Improved2EdgeLane::run(n, 5, 3);
  EXPECT_EQ(w.m, 4);
  EXPECT_EQ(w.steps, 0);
  EXPECT_TRUE(w.enters);
  EXPECT_EQ(w.cycles, uint64_t(4 + 1 + 4));  // max(m, T) + 1 + m
  // Outside for three rows (T = -3*512 + 1 needs 3 steps of 512), a saturated slope (s >= D*2^m).
  n.T = -3 * 512 + 1;
  n.s = 512;
  n.D = 16;  // 16 * 2^4 = 256 <= 512: saturated; entry value 1 < 256: not
  w = Improved2EdgeLane::run(n, 5, 10);
  EXPECT_EQ(w.steps, 3);
  EXPECT_TRUE(w.slope_saturated);
  EXPECT_FALSE(w.entry_saturated);
  EXPECT_EQ(w.cycles, uint64_t(3 + 1 + 4));  // max(2, 3) + 1 + m
  // Never enters (Ymax = 1): T = Ymax + 1 = 2 steps, no entry division.
  w = Improved2EdgeLane::run(n, 5, 1);
  EXPECT_FALSE(w.enters);
  EXPECT_EQ(w.cycles, uint64_t(2 + 1));  // max(2, 2) + 1
  // dir -: u = -T1 - 1; T1 = -1 is already past the far column (u = 0 >= 0).
  n.dir_down = false;
  n.T1 = -1;
  n.T = n.T1 + 5 * n.D;
  w = Improved2EdgeLane::run(n, 5, 1);
  EXPECT_EQ(w.steps, 0);
  EXPECT_TRUE(w.enters);
  // Horizontal: T + 1.
  NormalizedEdge h{};
  h.horizontal = true;
  h.dir_down = true;
  h.s = 256;
  h.T = -256 * 2;
  w = Improved2EdgeLane::run(h, 3, 5);
  EXPECT_EQ(w.steps, 2);
  EXPECT_EQ(w.cycles, uint64_t(3));
}

// The cross-check (Improved2Unit's cross_check, on in improved2-datapath, off in improved2-sc
// unless TRIRAST_IMPROVED2_CHECK=1): with it, each lane's own traversal
// (Improved2EdgeLane::traverse) runs and must equal gen1's walker's steps and entry, and the
// corner stage's values the box stage's; without it the lanes' cycles take the walker's steps.
// Both give the same triangle, field by field, on scenes with both kinds of box, and the
// checked unit throws nothing: a bug in the gen2 lane's traversal makes it throw here.
TEST(Improved2Datapath, CrossCheckedAndUncheckedUnitsAgree) {
  uint64_t lane_boxes = 0, rows = 0;
  for (const char* name : {"mixed", "hard-all", "lowpoly-near"}) {
    RasterConfig cfg;
    const SetupResult setup = setup_scene(make_builtin(name, cfg, CameraOptions{}).tris, cfg);
    Improved2Unit checked(cfg, true), unchecked(cfg, false);
    Improved2Triangle a, b;
    for (const TriangleSetup& t : setup.tris) {
      ASSERT_NO_THROW(checked.run_triangle(t, a)) << name << " triangle " << t.index;
      unchecked.run_triangle(t, b);
      ASSERT_EQ(a.box.empty, b.box.empty);
      ASSERT_EQ(a.tiny, b.tiny);
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(a.box.edge[k].E_L, b.box.edge[k].E_L);
        EXPECT_EQ(a.box.edge[k].E_R, b.box.edge[k].E_R);
        const Improved2LaneWork &x = a.lane[k], &y = b.lane[k];
        EXPECT_EQ(x.m, y.m);
        EXPECT_EQ(x.steps, y.steps);
        EXPECT_EQ(x.enters, y.enters);
        EXPECT_EQ(x.slope_saturated, y.slope_saturated);
        EXPECT_EQ(x.entry_saturated, y.entry_saturated);
        EXPECT_EQ(x.iterations, y.iterations);
        EXPECT_EQ(x.cycles, y.cycles) << name << " triangle " << t.index << " edge " << k;
      }
      EXPECT_EQ(a.lane_cycles, b.lane_cycles);
      EXPECT_EQ(a.corner_digits_l, b.corner_digits_l);
      EXPECT_EQ(a.corner_digits_r, b.corner_digits_r);
      ASSERT_EQ(a.rows.size(), b.rows.size());
      for (size_t i = 0; i < a.rows.size(); ++i) {
        EXPECT_EQ(a.rows[i].valid, b.rows[i].valid);
        if (a.rows[i].valid) EXPECT_TRUE(a.rows[i].span == b.rows[i].span);
      }
      EXPECT_EQ(a.rows_stepped, b.rows_stepped);
      if (!a.box.empty && !a.tiny) ++lane_boxes;
      rows += a.rows.size();
    }
  }
  EXPECT_GT(lane_boxes, 1000u);
  EXPECT_GT(rows, 10000u);
}

}  // namespace
}  // namespace trirast
