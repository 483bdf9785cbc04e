// The golden rasterizer against an independent per-pixel implementation of docs/coverage-rule.md,
// and watertightness on closed configurations.
#include <gtest/gtest.h>

#include <cmath>

#include "common/setup.hpp"
#include "common/span_diff.hpp"
#include "golden/golden.hpp"
#include "common/reference_raster.hpp"
#include "scene/scene.hpp"
#include "common/watertight.hpp"
#include "support/scene_helpers.hpp"

namespace trirast {
namespace {

using test::golden_spans;
using test::tri;
using test::TestRng;

// Golden spans must equal the reference's, span for span.
void expect_matches_reference(const std::vector<InputTriangle>& tris, const RasterConfig& cfg,
                              bool expect_pixels = true) {
  const SetupResult setup = setup_scene(tris, cfg);
  const SpanList golden = golden_spans(setup, cfg);
  const SpanList reference = test::reference_raster(tris, cfg);
  const SpanDiff d = diff_spans(reference, golden);
  ASSERT_TRUE(d.identical_spans) << d.missing_pixels << " missing, " << d.extra_pixels
                                 << " extra pixels; first missing tri "
                                 << (d.missing.empty() ? -1 : int64_t(d.missing[0].tri))
                                 << ", first extra tri "
                                 << (d.extra.empty() ? -1 : int64_t(d.extra[0].tri));
  if (expect_pixels) {
    EXPECT_GT(count_pixels(golden), 0);
  }
}

TEST(GoldenVsReference, RandomOnSubpixelGrid) {
  TestRng rng(1);
  RasterConfig cfg;  // 1024x768, S = 8
  // Vertices on the 1/256 grid, some triangles straddling the viewport edges.
  auto tris = test::random_grid_triangles(rng, 100000, -40, 1064, -40, 808, 8, 24);
  expect_matches_reference(tris, cfg);
}

TEST(GoldenVsReference, RandomOnHalfPixelLattice) {
  TestRng rng(2);
  RasterConfig cfg;
  // Vertices on the half-pixel lattice: pixel centres fall exactly on edges and vertices.
  auto tris = test::random_grid_triangles(rng, 100000, -8, 1032, -8, 776, 1, 12);
  expect_matches_reference(tris, cfg);
}

TEST(GoldenVsReference, LargeViewport4096) {
  TestRng rng(3);
  RasterConfig cfg;
  cfg.width = cfg.height = 4096;
  auto tris = test::random_grid_triangles(rng, 10000, -100, 4196, -100, 4196, 8, 160);
  expect_matches_reference(tris, cfg);
}

// Arbitrary doubles (not on any grid) within the 256 x 192 viewport and around it.
std::vector<InputTriangle> arbitrary_triangles(TestRng& rng, int count) {
  std::vector<InputTriangle> tris;
  for (int n = 0; n < count; ++n) {
    InputTriangle t;
    for (int i = 0; i < 3; ++i) {
      t.x[i] = double(rng.range(-2000, 27600)) / 100.0 + double(rng.next() % 1000) * 1e-6;
      t.y[i] = double(rng.range(-2000, 21200)) / 100.0 + double(rng.next() % 1000) * 1e-6;
    }
    tris.push_back(t);
  }
  return tris;
}

TEST(GoldenVsReference, EverySubpixelPrecision) {
  for (int s = 0; s <= 8; ++s) {
    SCOPED_TRACE("subpixel bits " + std::to_string(s));
    TestRng rng(10 + s);
    const RasterConfig cfg = test::config_at(s, 256, 192);
    // Arbitrary doubles: snapping itself is under test.
    expect_matches_reference(arbitrary_triangles(rng, 5000), cfg);
  }
}

TEST(GoldenVsReference, CullModes) {
  TestRng rng(4);
  auto tris = test::random_grid_triangles(rng, 5000, 0, 512, 0, 512, 8, 40);
  for (CullMode m : {CullMode::None, CullMode::Back, CullMode::Front}) {
    RasterConfig cfg;
    cfg.cull = m;
    SCOPED_TRACE(cull_mode_name(m));
    expect_matches_reference(tris, cfg);
  }
  // Back and front culling split the accepted triangles between them.
  RasterConfig back, front;
  back.cull = CullMode::Back;
  front.cull = CullMode::Front;
  const auto sb = setup_scene(tris, back), sf = setup_scene(tris, front);
  const auto sn = setup_scene(tris, RasterConfig{});
  EXPECT_GT(sb.counts.accepted, 0u);
  EXPECT_GT(sf.counts.accepted, 0u);
  EXPECT_EQ(sb.counts.accepted + sf.counts.accepted, sn.counts.accepted);
}

TEST(GoldenVsReference, LargeCoordinatesAndNegative) {
  TestRng rng(5);
  RasterConfig cfg;
  // One vertex near the viewport, two far away near the +-32768 limit.
  expect_matches_reference(test::far_vertex_triangles(rng, 2000, 1070, 810), cfg);
}

// ---- watertightness ----------------------------------------------------------------------------

double snap256(double v) { return std::nearbyint(v * 256) / 256; }

void expect_watertight(const std::vector<InputTriangle>& tris, const RasterConfig& cfg,
                       bool whole_screen) {
  const SetupResult setup = setup_scene(tris, cfg);
  const SpanList spans = golden_spans(setup, cfg);
  const auto w = check_watertight(setup, spans, cfg);
  EXPECT_EQ(w.doubles, 0) << w.first_problem;
  EXPECT_EQ(w.cracks, 0) << w.first_problem;
  EXPECT_GT(w.covered, 0);
  if (whole_screen) {
    EXPECT_EQ(w.covered, int64_t(cfg.width) * cfg.height);
  }
}

TEST(GoldenWatertight, FansAroundPixelCentre) {
  RasterConfig cfg;
  cfg.width = cfg.height = 128;
  for (int n = 3; n <= 8; ++n)
    for (int rot = 0; rot < 12; ++rot) {
      SCOPED_TRACE("fan of " + std::to_string(n) + ", rotation " + std::to_string(rot));
      const double cx = 64.5, cy = 63.5;  // a pixel centre: every triangle meets there
      std::vector<InputTriangle> fan;
      for (int k = 0; k < n; ++k) {
        const double a0 = 2 * M_PI * k / n + rot * 0.13, a1 = 2 * M_PI * (k + 1) / n + rot * 0.13;
        const double r = 40;
        fan.push_back(tri(cx, cy, snap256(cx + r * std::cos(a0)), snap256(cy + r * std::sin(a0)),
                          snap256(cx + r * std::cos(a1)), snap256(cy + r * std::sin(a1))));
        if (k % 2) {  // mixed windings: coverage must not depend on it
          std::swap(fan.back().x[1], fan.back().x[2]);
          std::swap(fan.back().y[1], fan.back().y[2]);
        }
      }
      expect_watertight(fan, cfg, false);
    }
}

TEST(GoldenWatertight, RotatedQuadGrids) {
  RasterConfig cfg;
  cfg.width = cfg.height = 160;
  for (int deg = 0; deg <= 90; deg += 5)
    for (int diag = 0; diag < 2; ++diag) {
      SCOPED_TRACE("angle " + std::to_string(deg) + ", diagonal " + std::to_string(diag));
      const double a = deg * M_PI / 180, c = std::cos(a), s = std::sin(a), step = 9.37;
      auto grid_point = [&](int i, int j, double& x, double& y) {
        x = snap256(80 + (i - 4) * step * c - (j - 4) * step * s);
        y = snap256(80 + (i - 4) * step * s + (j - 4) * step * c);
      };
      std::vector<InputTriangle> tris;
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
          double x00, y00, x10, y10, x01, y01, x11, y11;
          grid_point(i, j, x00, y00);
          grid_point(i + 1, j, x10, y10);
          grid_point(i, j + 1, x01, y01);
          grid_point(i + 1, j + 1, x11, y11);
          if (diag == 0) {
            tris.push_back(tri(x00, y00, x10, y10, x11, y11));
            tris.push_back(tri(x00, y00, x11, y11, x01, y01));
          } else {
            tris.push_back(tri(x00, y00, x10, y10, x01, y01));
            tris.push_back(tri(x10, y10, x11, y11, x01, y01));
          }
        }
      expect_watertight(tris, cfg, false);
    }
}

TEST(GoldenWatertight, WholeScreenCovers) {
  RasterConfig cfg;
  cfg.width = 200;
  cfg.height = 150;
  // Two triangles exactly on the viewport, both diagonals.
  expect_watertight({tri(0, 0, 200, 0, 200, 150), tri(0, 0, 200, 150, 0, 150)}, cfg, true);
  expect_watertight({tri(0, 0, 200, 0, 0, 150), tri(200, 0, 200, 150, 0, 150)}, cfg, true);
  // A rotated square much larger than the screen, split on its diagonal, partly off-screen.
  for (int deg = 0; deg < 90; deg += 7) {
    SCOPED_TRACE("rotation " + std::to_string(deg));
    const double a = deg * M_PI / 180, r = 600;
    double x[4], y[4];
    for (int k = 0; k < 4; ++k) {
      x[k] = snap256(100 + r * std::cos(a + k * M_PI / 2));
      y[k] = snap256(75 + r * std::sin(a + k * M_PI / 2));
    }
    expect_watertight({tri(x[0], y[0], x[1], y[1], x[2], y[2]), tri(x[0], y[0], x[2], y[2], x[3], y[3])},
                      cfg, true);
  }
}

TEST(GoldenWatertight, ManyTrianglesMeetingOnACentreVertex) {
  RasterConfig cfg;
  cfg.width = cfg.height = 64;
  // 16 triangles around (32.5, 32.5): exactly one of them owns that centre.
  std::vector<InputTriangle> tris;
  for (int k = 0; k < 16; ++k) {
    const double a0 = 2 * M_PI * k / 16, a1 = 2 * M_PI * (k + 1) / 16;
    tris.push_back(tri(32.5, 32.5, snap256(32.5 + 20 * std::cos(a0)), snap256(32.5 + 20 * std::sin(a0)),
                       snap256(32.5 + 20 * std::cos(a1)), snap256(32.5 + 20 * std::sin(a1))));
  }
  const SetupResult setup = setup_scene(tris, cfg);
  const SpanList spans = golden_spans(setup, cfg);
  int owners = 0;
  for (const Span& s : spans)
    if (s.y == 32 && s.x_begin <= 32 && 32 < s.x_end) ++owners;
  EXPECT_EQ(owners, 1);
  expect_watertight(tris, cfg, false);
}

// ---- setup -------------------------------------------------------------------------------------

TEST(Setup, SnapsHalfwayToEven) {
  RasterConfig cfg;
  // 1/512 is exactly halfway between two 1/256 steps: ties go to the even step.
  EXPECT_EQ(snap_coordinate(1.0 / 512, cfg, 0, 0), 0);
  EXPECT_EQ(snap_coordinate(3.0 / 512, cfg, 0, 0), 2);
  EXPECT_EQ(snap_coordinate(-1.0 / 512, cfg, 0, 0), 0);
  EXPECT_EQ(snap_coordinate(-3.0 / 512, cfg, 0, 0), -2);
  cfg.subpixel_bits = 0;  // whole pixels, doubled internally: 2.5 -> 2 -> 4, 3.5 -> 4 -> 8
  EXPECT_EQ(snap_coordinate(2.5, cfg, 0, 0), 4);
  EXPECT_EQ(snap_coordinate(3.5, cfg, 0, 0), 8);
}

TEST(Setup, RejectsNonFiniteAndOutOfRange) {
  RasterConfig cfg;
  EXPECT_THROW(snap_coordinate(std::nan(""), cfg, 3, 7), SetupError);
  EXPECT_THROW(snap_coordinate(INFINITY, cfg, 3, 7), SetupError);
  EXPECT_THROW(snap_coordinate(32768.0, cfg, 3, 7), SetupError);
  EXPECT_THROW(snap_coordinate(1e300, cfg, 3, 7), SetupError);
  EXPECT_NO_THROW(snap_coordinate(32767.99, cfg, 3, 7));
  EXPECT_NO_THROW(snap_coordinate(-32768.0, cfg, 3, 7));
  // 32767.999 rounds up to 32768 at 1/256: out of range after snapping.
  EXPECT_THROW(snap_coordinate(32767.999, cfg, 3, 7), SetupError);
  try {
    snap_coordinate(std::nan(""), cfg, 3, 7);
  } catch (const SetupError& e) {
    EXPECT_EQ(e.tri, 3u);
    EXPECT_EQ(e.line, 7);
    EXPECT_NE(std::string(e.what()).find("line 7"), std::string::npos);
  }
}

TEST(Setup, DegenerateAfterSnappingHasNoPixels) {
  RasterConfig cfg;
  // Distinct as floats, collinear after snapping to 1/256.
  auto tris = std::vector<InputTriangle>{tri(10, 10, 20, 20.001, 30, 30),
                                         tri(5, 5, 5, 5, 5, 5),
                                         tri(1, 1, 1.0001, 9, 1, 17)};
  const SetupResult s = setup_scene(tris, cfg);
  EXPECT_EQ(s.counts.degenerate, 3u);
  EXPECT_EQ(s.counts.accepted, 0u);
}

TEST(Setup, BoxHoldsCentresWithinTheVertexExtent) {
  RasterConfig cfg;
  TriangleSetup t;
  const char* why;
  // x extent [10.5, 20.5]: centres 10.5 .. 20.5 -> pixels 10..20 (both end centres on the extent).
  ASSERT_TRUE(setup_triangle(tri(10.5, 10.5, 20.5, 10.5, 10.5, 30.2), 0, cfg, t, &why));
  EXPECT_EQ(t.box.x0, 10);
  EXPECT_EQ(t.box.x1, 20);
  EXPECT_EQ(t.box.y0, 10);
  EXPECT_EQ(t.box.y1, 29);
  // Negative coordinates: floor, not truncation.
  ASSERT_TRUE(setup_triangle(tri(-10.7, -3.2, 5.1, -3.2, -10.7, 4.0), 0, cfg, t, &why));
  EXPECT_EQ(t.box.x0, 0);
  EXPECT_EQ(t.box.x1, 4);
  EXPECT_EQ(t.box.y0, 0);
  EXPECT_EQ(t.box.y1, 3);
  // Between two centres: empty box.
  ASSERT_TRUE(setup_triangle(tri(10.6, 10.6, 11.4, 10.6, 10.6, 11.4), 0, cfg, t, &why));
  EXPECT_TRUE(t.box.empty());
}

}  // namespace
}  // namespace trirast

// ---- built-in scenes: every hard case, meshes through Assimp, closed configurations ----------

namespace trirast {
namespace {

std::vector<std::string> hard_case_names() {
  std::vector<std::string> names;
  for (const BuiltinInfo& b : builtin_scenes())
    if (b.name.rfind("hard-", 0) == 0 && b.name != "hard-all") names.push_back(b.name);
  return names;
}

TEST(GoldenHardCases, EveryHardCaseMatchesReference) {
  const auto names = hard_case_names();
  ASSERT_GE(names.size(), 18u);
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    RasterConfig cfg;
    const Scene scene = make_builtin(name, cfg, CameraOptions{});
    ASSERT_FALSE(scene.tris.empty());
    expect_matches_reference(scene.tris, cfg, name != "hard-degenerate");
  }
}

TEST(GoldenHardCases, OtherPrecisionsAndViewports) {
  for (int s : {0, 4}) {
    const RasterConfig cfg = test::config_at(s, 640, 480);
    SCOPED_TRACE("S=" + std::to_string(s));
    expect_matches_reference(make_builtin("hard-all", cfg, CameraOptions{}).tris, cfg);
  }
}

TEST(GoldenMeshes, AssimpFilesAndMeshScenesMatchReference) {
  RasterConfig cfg;
  for (const char* file : {"cube.obj", "cube.ply", "cube.stl", "cube.off", "cube.gltf"}) {
    SCOPED_TRACE(file);
    const Scene s = load_scene(std::string(TRIRAST_SOURCE_DIR) + "/tests/data/" + file, cfg,
                               CameraOptions{});
    expect_matches_reference(s.tris, cfg);
  }
  for (const char* name : {"sphere", "torus", "surface", "lowpoly-near", "highpoly-far", "mixed",
                           "hard-projected"}) {
    SCOPED_TRACE(name);
    expect_matches_reference(make_builtin(name, cfg, CameraOptions{}).tris, cfg);
  }
}

TEST(GoldenMeshes, ClosedMeshesAreWatertight) {
  RasterConfig cfg;
  // Convex closed meshes only: their front faces cover the silhouette exactly once (a torus's
  // front faces overlap themselves in projection).
  for (const char* name : {"sphere", "lowpoly-far", "highpoly-near", "sphere:tess=7"}) {
    SCOPED_TRACE(name);
    const Scene s = make_builtin(name, cfg, CameraOptions{});
    RasterConfig front_only = cfg;
    front_only.cull = CullMode::Back;
    const SetupResult setup = setup_scene(s.tris, front_only);
    const auto w = check_watertight(setup, golden_spans(setup, front_only), front_only);
    EXPECT_EQ(w.doubles, 0) << w.first_problem;
    EXPECT_EQ(w.cracks, 0) << w.first_problem;
    EXPECT_GT(w.covered, 1000);
  }
}

TEST(GoldenWatertight, BuiltinClosedConfigurations) {
  RasterConfig cfg;
  for (const char* name : {"fan", "fan:n=3,centre=pixel", "fan:n=8,rotation=17", "quad-grid",
                           "quad-grid:angle=0,diag=main", "quad-grid:angle=45,diag=anti",
                           "quad-grid:angle=90", "strip", "hard-one-vertex", "hard-shared-edges"}) {
    SCOPED_TRACE(name);
    expect_watertight(make_builtin(name, cfg, CameraOptions{}).tris, cfg, false);
  }
  // hard-whole-screen: consecutive pairs each cover the whole viewport, except the axis-aligned
  // rectangle shifted partly off-screen, which covers exactly its integer overlap with it.
  const Scene ws = make_builtin("hard-whole-screen", cfg, CameraOptions{});
  ASSERT_EQ(ws.tris.size() % 2, 0u);
  int partial_pairs = 0;
  for (size_t i = 0; i < ws.tris.size(); i += 2) {
    SCOPED_TRACE("whole-screen pair " + std::to_string(i / 2));
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    bool axis_aligned = true;
    for (size_t k = i; k < i + 2; ++k)
      for (int v = 0; v < 3; ++v) {
        x0 = std::min(x0, ws.tris[k].x[v]), x1 = std::max(x1, ws.tris[k].x[v]);
        y0 = std::min(y0, ws.tris[k].y[v]), y1 = std::max(y1, ws.tris[k].y[v]);
      }
    for (size_t k = i; k < i + 2; ++k)
      for (int v = 0; v < 3; ++v)
        axis_aligned = axis_aligned && (ws.tris[k].x[v] == x0 || ws.tris[k].x[v] == x1) &&
                       (ws.tris[k].y[v] == y0 || ws.tris[k].y[v] == y1);
    const bool covers_screen = x0 <= 0 && y0 <= 0 && x1 >= cfg.width && y1 >= cfg.height;
    if (axis_aligned && !covers_screen) {
      ++partial_pairs;
      const SetupResult setup = setup_scene({ws.tris[i], ws.tris[i + 1]}, cfg);
      const auto w = check_watertight(setup, golden_spans(setup, cfg), cfg);
      EXPECT_EQ(w.doubles, 0) << w.first_problem;
      EXPECT_EQ(w.covered, int64_t(std::min(x1, double(cfg.width)) - std::max(x0, 0.0)) *
                               int64_t(std::min(y1, double(cfg.height)) - std::max(y0, 0.0)));
    } else {
      expect_watertight({ws.tris[i], ws.tris[i + 1]}, cfg, true);
    }
  }
  EXPECT_GT(partial_pairs, 0);
}

}  // namespace
}  // namespace trirast
