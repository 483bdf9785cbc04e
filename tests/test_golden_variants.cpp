// Every golden traversal against the independent per-pixel reference (tests/support), span for
// span; the multi-threaded golden against the single-threaded one; the float scanline baseline's
// error measured against the golden.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <stdexcept>
#include <utility>

#include "common/setup.hpp"
#include "common/span_diff.hpp"
#include "golden/golden.hpp"
#include "scene/scene.hpp"
#include "common/reference_raster.hpp"
#include "support/scene_helpers.hpp"

namespace trirast {
namespace {

using test::tri;
using test::TestRng;

std::vector<Traversal> traversals() {
  int n = 0;
  const Traversal* all = all_traversals(&n);
  return std::vector<Traversal>(all, all + n);
}

SpanList spans_of(const SetupResult& setup, const RasterConfig& cfg, Traversal traversal) {
  SpanList spans;
  for (const TriangleSetup& t : setup.tris) golden_triangle(t, cfg, traversal, spans);
  return spans;
}

// Every traversal's spans equal the reference's, span for span, and come out in the same order
// (triangle order, rows increasing) without sorting.
void expect_all_match_reference(const std::vector<InputTriangle>& tris, const RasterConfig& cfg,
                                bool expect_pixels = true) {
  const SetupResult setup = setup_scene(tris, cfg);
  const SpanList reference = test::reference_raster(tris, cfg);
  if (expect_pixels) {
    ASSERT_GT(count_pixels(reference), 0);
  }
  for (Traversal tr : traversals()) {
    SCOPED_TRACE(traversal_name(tr));
    const SpanList unsorted = spans_of(setup, cfg, tr);
    SpanList spans = unsorted;
    sort_spans(spans);
    EXPECT_EQ(unsorted, spans) << "spans not emitted in triangle/row order";
    const SpanDiff d = diff_spans(reference, spans);
    ASSERT_TRUE(d.identical_spans)
        << d.missing_pixels << " missing, " << d.extra_pixels << " extra pixels; first missing tri "
        << (d.missing.empty() ? -1 : int64_t(d.missing[0].tri)) << ", first extra tri "
        << (d.extra.empty() ? -1 : int64_t(d.extra[0].tri)) << " (" << spans.size() << " vs "
        << reference.size() << " spans)";
  }
  // The two-argument golden_triangle (what other code calls) is the same too.
  SpanList plain;
  for (const TriangleSetup& t : setup.tris) golden_triangle(t, cfg, plain);
  EXPECT_EQ(plain, reference);
}

// Random triangles on a grid: test::random_grid_triangles' arguments after the generator.
struct Grid {
  int count;
  double lo_x, hi_x, lo_y, hi_y;
  int grid_bits;
  double max_size;
};

// The triangles of each grid in turn, all drawn from `rng`.
std::vector<InputTriangle> grid_triangles(TestRng& rng, const std::vector<Grid>& grids) {
  std::vector<InputTriangle> tris;
  for (const Grid& g : grids) {
    const auto more = test::random_grid_triangles(rng, g.count, g.lo_x, g.hi_x, g.lo_y, g.hi_y,
                                                  g.grid_bits, g.max_size);
    tris.insert(tris.end(), more.begin(), more.end());
  }
  return tris;
}

// expect_all_match_reference on the triangles of `grids` drawn from a generator seeded `seed`.
void expect_grids_match_reference(uint64_t seed, const RasterConfig& cfg,
                                  const std::vector<Grid>& grids) {
  TestRng rng(seed);
  expect_all_match_reference(grid_triangles(rng, grids), cfg);
}

// Arbitrary doubles (not on any grid) within the 256 x 192 viewport and around it, clustered:
// every tenth triangle spans up to 200 pixels, the others up to 30.
std::vector<InputTriangle> clustered_arbitrary_triangles(TestRng& rng, int count) {
  std::vector<InputTriangle> tris;
  for (int n = 0; n < count; ++n) {
    InputTriangle t;
    const double size = n % 10 == 0 ? 20000 : 3000;  // every tenth one large
    const double bx = double(rng.range(-2000, 27600)), by = double(rng.range(-2000, 21200));
    for (int i = 0; i < 3; ++i) {
      t.x[i] = (bx + double(rng.range(-int64_t(size), int64_t(size)))) / 100.0 +
               double(rng.next() % 1000) * 1e-6;
      t.y[i] = (by + double(rng.range(-int64_t(size), int64_t(size)))) / 100.0 +
               double(rng.next() % 1000) * 1e-6;
    }
    tris.push_back(t);
  }
  return tris;
}

// ---- names -------------------------------------------------------------------------------------

TEST(Traversal, NamesRoundTripAndUnknownIsRejected) {
  const auto all = traversals();
  ASSERT_EQ(all.size(), 9u);
  for (Traversal t : all) EXPECT_EQ(parse_traversal(traversal_name(t)), t);
  EXPECT_EQ(parse_traversal("sat-block"), Traversal::SatBlock);
  try {
    parse_traversal("zigzag");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "--traversal: unknown traversal 'zigzag' (known: simple, incremental, block, "
              "adaptive, bisector, sat-block, window, scanline, auto)");
  }
}

// ---- every traversal against the reference -----------------------------------------------------

TEST(GoldenVariants, RandomOnSubpixelGrid) {
  // The default configuration: 1024x768, S = 8.
  expect_grids_match_reference(101, RasterConfig{}, {{20000, -40, 1064, -40, 808, 8, 24},
                                                     {600, -200, 1224, -200, 968, 8, 300}});
}

TEST(GoldenVariants, RandomOnHalfPixelLattice) {
  // Vertices on the half-pixel lattice: pixel centres fall exactly on edges and vertices.
  expect_grids_match_reference(102, RasterConfig{}, {{20000, -8, 1032, -8, 776, 1, 12},
                                                     {600, -64, 1088, -64, 832, 1, 200}});
}

TEST(GoldenVariants, WholePixelLatticeAndAxisAligned) {
  TestRng rng(103);
  const RasterConfig cfg = test::config_at(8, 300, 200);
  // Integer vertices: every horizontal and vertical edge and many diagonals hit centres' rows
  // and columns exactly half a pixel away; axis-aligned right triangles of all sizes.
  auto tris = test::random_grid_triangles(rng, 5000, -4, 304, -4, 204, 0, 40);
  for (int n = 0; n < 2000; ++n) {
    const double x = double(rng.range(-20, 300)) / 2, y = double(rng.range(-20, 200)) / 2;
    const double w = double(rng.range(1, 120)) / 2, h = double(rng.range(1, 120)) / 2;
    tris.push_back(tri(x, y, x + w, y, x, y + h));
    tris.push_back(tri(x + w, y, x + w, y + h, x, y + h));
  }
  expect_all_match_reference(tris, cfg);
}

TEST(GoldenVariants, LargeViewport4096) {
  expect_grids_match_reference(104, test::config_at(8, 4096, 4096),
                               {{3000, -100, 4196, -100, 4196, 8, 160},
                                {30, -2000, 6000, -2000, 6000, 8, 4000}});
}

TEST(GoldenVariants, LargeCoordinatesAndNegative) {
  TestRng rng(105);
  const RasterConfig cfg = test::config_at(8, 640, 480);
  // One vertex near the viewport, two far away near the +-32768 limit.
  std::vector<InputTriangle> tris = test::far_vertex_triangles(rng, 400, 690, 530);
  // Slivers from far outside across the screen.
  for (int n = 0; n < 200; ++n) {
    const double x = double(rng.range(-32768 * 256, -32000 * 256)) / 256;
    const double y = double(rng.range(-100 * 256, 580 * 256)) / 256;
    tris.push_back(tri(x, y, 32767.5, y + double(rng.range(-9000, 9000)) / 256,
                       32767.5, y + double(rng.range(-9000, 9000)) / 256 + 0.75));
  }
  expect_all_match_reference(tris, cfg);
}

TEST(GoldenVariants, EverySubpixelPrecision) {
  for (int s = 0; s <= 8; ++s) {
    SCOPED_TRACE("subpixel bits " + std::to_string(s));
    TestRng rng(110 + s);
    const RasterConfig cfg = test::config_at(s, 256, 192);
    // Arbitrary doubles: snapping and S = 0 doubling are exercised too.
    expect_all_match_reference(clustered_arbitrary_triangles(rng, 2000), cfg);
  }
}

TEST(GoldenVariants, TinyTriangles) {
  // Under two pixels across: most cover zero, one or two pixel centres.
  expect_grids_match_reference(106, test::config_at(8, 512, 512),
                               {{40000, 0, 512, 0, 512, 8, 1.5}, {20000, 0, 512, 0, 512, 2, 1}});
}

TEST(GoldenVariants, Slivers) {
  TestRng rng(107);
  const RasterConfig cfg = test::config_at(8, 800, 600);
  std::vector<InputTriangle> tris;
  for (int n = 0; n < 4000; ++n) {
    // A long edge at any angle and a third vertex a fraction of a pixel off it.
    const double x0 = double(rng.range(-100 * 256, 900 * 256)) / 256;
    const double y0 = double(rng.range(-100 * 256, 700 * 256)) / 256;
    const double x1 = double(rng.range(-100 * 256, 900 * 256)) / 256;
    const double y1 = double(rng.range(-100 * 256, 700 * 256)) / 256;
    const double f = double(rng.range(0, 256)) / 256;
    const double off = double(rng.range(-200, 200)) / 256;
    const double len = std::hypot(x1 - x0, y1 - y0) + 1e-9;
    const double x2 = std::nearbyint((x0 + f * (x1 - x0) - off * (y1 - y0) / len) * 256) / 256;
    const double y2 = std::nearbyint((y0 + f * (y1 - y0) + off * (x1 - x0) / len) * 256) / 256;
    tris.push_back(tri(x0, y0, x1, y1, x2, y2));
  }
  // Horizontal and vertical slivers a fraction of a pixel thick, on and off the centre lines.
  for (int n = 0; n < 1000; ++n) {
    const double a = double(rng.range(0, 600 * 4)) / 4, b = double(rng.range(-50, 850));
    const double t = double(rng.range(1, 200)) / 256, l = double(rng.range(1, 700));
    tris.push_back(tri(b, a, b + l, a, b, a + t));
    tris.push_back(tri(a, b, a + t, b + l, a, b + l));
  }
  expect_all_match_reference(tris, cfg);
}

TEST(GoldenVariants, HardCasesAndMeshes) {
  RasterConfig cfg;
  for (const char* name : {"hard-all", "sphere", "torus", "lowpoly-near", "highpoly-far"}) {
    SCOPED_TRACE(name);
    expect_all_match_reference(make_builtin(name, cfg, CameraOptions{}).tris, cfg);
  }
  for (int s : {0, 4}) {
    const RasterConfig c2 = test::config_at(s, 640, 480);
    SCOPED_TRACE("hard-all S=" + std::to_string(s));
    expect_all_match_reference(make_builtin("hard-all", c2, CameraOptions{}).tris, c2);
  }
}

// ---- the multi-threaded golden -----------------------------------------------------------------

TEST(GoldenParallel, SameSpansInSameOrderForAnyThreadCount) {
  TestRng rng(201);
  RasterConfig cfg;
  auto tris = grid_triangles(rng, {{30000, -40, 1064, -40, 808, 8, 30},
                                   {300, -200, 1224, -200, 968, 8, 600}});
  const auto mesh = make_builtin("highpoly-near", cfg, CameraOptions{}).tris;
  tris.insert(tris.end(), mesh.begin(), mesh.end());
  const SetupResult setup = setup_scene(tris, cfg);
  const SpanList reference = test::reference_raster(tris, cfg);
  for (Traversal tr : {Traversal::Auto, Traversal::Scanline, Traversal::Incremental}) {
    SCOPED_TRACE(traversal_name(tr));
    EngineResult one;
    make_golden_engine(tr, 1)->run(setup, cfg, one);
    EXPECT_EQ(one.spans, reference);
    for (int threads : {1, 2, 3, 8}) {
      SCOPED_TRACE(std::to_string(threads) + " threads");
      EngineResult many;
      make_golden_engine(tr, threads)->run(setup, cfg, many);
      // Not merely the same set: the same list, unsorted, as one thread gives.
      EXPECT_EQ(many.spans, one.spans);
    }
  }
  // The default engine is the same as well.
  EngineResult dflt;
  make_golden_engine()->run(setup, cfg, dflt);
  EXPECT_EQ(dflt.spans, reference);
}

// Scenes of >= 100,000 triangles, as the 2-thread target measures them, and lopsided ones whose
// cost sits at one end, so that the writer thread has to take chunks from the helpers' range and
// the helpers from the writer's: every thread count gives the one-thread list, span for span.
TEST(GoldenParallel, LargeScenesSameAsOneThread) {
  TestRng rng(202);
  RasterConfig cfg;
  const auto small = test::random_grid_triangles(rng, 120000, -20, 1044, -20, 788, 8, 14);
  const auto big = test::random_grid_triangles(rng, 400, -200, 1224, -200, 968, 8, 900);
  std::vector<std::pair<const char*, std::vector<InputTriangle>>> scenes;
  scenes.emplace_back("120000 small", small);
  std::vector<InputTriangle> big_first = big;
  big_first.insert(big_first.end(), small.begin(), small.end());
  scenes.emplace_back("big first", big_first);
  std::vector<InputTriangle> big_last = small;
  big_last.insert(big_last.end(), big.begin(), big.end());
  scenes.emplace_back("big last", big_last);
  scenes.emplace_back("highpoly-near", make_builtin("highpoly-near", cfg, CameraOptions{}).tris);
  for (const auto& [name, tris] : scenes) {
    SCOPED_TRACE(name);
    const SetupResult setup = setup_scene(tris, cfg);
    ASSERT_GE(setup.tris.size(), 100000u);
    for (Traversal tr : {Traversal::Auto, Traversal::Scanline}) {
      SCOPED_TRACE(traversal_name(tr));
      EngineResult one;
      make_golden_engine(tr, 1)->run(setup, cfg, one);
      ASSERT_GT(one.spans.size(), setup.tris.size());
      for (int threads : {2, 3, 4}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        auto engine = make_golden_engine(tr, threads);
        for (int round = 0; round < 2; ++round) {  // the second run reuses the chunk lists
          EngineResult many;
          engine->run(setup, cfg, many);
          ASSERT_EQ(many.spans.size(), one.spans.size());
          EXPECT_TRUE(many.spans == one.spans);
        }
      }
    }
  }
}

// One engine object run on scene after scene: its helper threads sleep between runs and are
// woken for the next one, whatever its size (a scene of a few chunks that the writer finishes
// before a helper wakes, then a large one, then a small one again); destroying the engine with its
// helpers asleep ends them.
TEST(GoldenParallel, OneEngineManyScenes) {
  TestRng rng(204);
  RasterConfig cfg;
  auto engine = make_golden_engine(Traversal::Auto, 3);
  auto one = make_golden_engine(Traversal::Auto, 1);
  for (int n : {40, 70000, 3, 500, 0, 20000, 64}) {
    SCOPED_TRACE(std::to_string(n) + " triangles");
    const auto tris = test::random_grid_triangles(rng, n, -20, 1044, -20, 788, 8, 60);
    const SetupResult setup = setup_scene(tris, cfg);
    EngineResult expect, got;
    one->run(setup, cfg, expect);
    engine->run(setup, cfg, got);
    EXPECT_TRUE(got.spans == expect.spans);
  }
}

// The engine appends to what the result already holds, as the single-threaded one does.
TEST(GoldenParallel, AppendsToExistingSpans) {
  TestRng rng(203);
  RasterConfig cfg;
  const auto tris = test::random_grid_triangles(rng, 5000, -20, 1044, -20, 788, 8, 40);
  const SetupResult setup = setup_scene(tris, cfg);
  const Span marker{7, 1, 2, 3};
  EngineResult one, two;
  one.spans.assign(3, marker);
  two.spans.assign(3, marker);
  make_golden_engine(Traversal::Auto, 1)->run(setup, cfg, one);
  make_golden_engine(Traversal::Auto, 2)->run(setup, cfg, two);
  EXPECT_GT(one.spans.size(), 3u);
  EXPECT_EQ(two.spans, one.spans);
}

TEST(GoldenParallel, FewTrianglesAndEmptyScene) {
  RasterConfig cfg;
  const SetupResult empty = setup_scene({}, cfg);
  EngineResult r;
  make_golden_engine(Traversal::Auto, 8)->run(empty, cfg, r);
  EXPECT_TRUE(r.spans.empty());
  const std::vector<InputTriangle> one = {tri(10, 10, 500, 20, 30, 700)};
  const SetupResult s = setup_scene(one, cfg);
  EngineResult a;
  make_golden_engine(Traversal::Auto, 8)->run(s, cfg, a);
  EXPECT_EQ(a.spans, test::reference_raster(one, cfg));
}

// ---- the float scanline baseline ---------------------------------------------------------------

struct FloatError {
  int64_t pixels = 0, missing = 0, extra = 0;
};

FloatError float_error(const std::vector<InputTriangle>& tris, const RasterConfig& cfg) {
  const SetupResult setup = setup_scene(tris, cfg);
  EngineResult golden, fl;
  make_golden_engine()->run(setup, cfg, golden);
  make_float_scanline_engine()->run(setup, cfg, fl);
  sort_spans(golden.spans);
  sort_spans(fl.spans);
  for (const Span& s : fl.spans) {  // never outside the viewport, never backwards
    EXPECT_GE(s.y, 0);
    EXPECT_LT(s.y, cfg.height);
    EXPECT_GE(s.x_begin, 0);
    EXPECT_LE(s.x_end, cfg.width);
    EXPECT_LT(s.x_begin, s.x_end);
  }
  const SpanDiff d = diff_spans(golden.spans, fl.spans);
  return FloatError{count_pixels(golden.spans), d.missing_pixels, d.extra_pixels};
}

void report(const char* what, const FloatError& e) {
  std::cout << "[ float-scanline ] " << what << ": " << e.missing << " missing + " << e.extra
            << " extra of " << e.pixels << " pixels ("
            << (e.pixels ? 1e6 * double(e.missing + e.extra) / double(e.pixels) : 0.0)
            << " per million)\n";
}

TEST(FloatScanline, RightEdgeThroughPixelCentresIsAnError) {
  RasterConfig cfg;
  // The right edge x = 10.5 runs through the centres of column 10: the D3D rule leaves them to
  // the neighbour on the right; the devlog's floor(rx - 0.5) keeps them (one per row, 10 rows).
  const std::vector<InputTriangle> tris = {tri(10.5, 10, 10.5, 20, 2, 15)};
  const FloatError e = float_error(tris, cfg);
  report("vertical right edge on centres", e);
  EXPECT_EQ(e.missing, 0);
  EXPECT_EQ(e.extra, 10);
  // Its neighbour across that edge covers them too: the devlog's rule is not watertight there.
  const std::vector<InputTriangle> pair = {tri(10.5, 10, 10.5, 20, 2, 15),
                                           tri(10.5, 10, 19, 15, 10.5, 20)};
  const SetupResult setup = setup_scene(pair, cfg);
  EngineResult fl;
  make_float_scanline_engine()->run(setup, cfg, fl);
  int owners_of_10_15 = 0;
  for (const Span& s : fl.spans)
    if (s.y == 15 && s.x_begin <= 10 && 10 < s.x_end) ++owners_of_10_15;
  EXPECT_EQ(owners_of_10_15, 2);
}

TEST(FloatScanline, ErrorMeasuredOnRandomAndLargeCoordinates) {
  TestRng rng(301);
  RasterConfig cfg;
  const FloatError grid =
      float_error(test::random_grid_triangles(rng, 20000, -40, 1064, -40, 808, 8, 24), cfg);
  report("random, 1/256 grid", grid);
  const FloatError lattice =
      float_error(test::random_grid_triangles(rng, 20000, -8, 1032, -8, 776, 1, 12), cfg);
  report("random, half-pixel lattice", lattice);
  EXPECT_GT(lattice.missing + lattice.extra, 0);  // ties on right edges at least
  // Far vertices: the float crossings are rounded at 1/256 pixel or worse.
  const FloatError large = float_error(test::far_vertex_triangles(rng, 3000, 1070, 810), cfg);
  report("large coordinates", large);
  // Never more than a sliver of error: the baseline is close, just not exact.
  EXPECT_LT(double(grid.missing + grid.extra), 0.02 * double(grid.pixels));
  EXPECT_LT(double(large.missing + large.extra), 0.001 * double(large.pixels));
  EXPECT_GT(large.pixels, 0);
}

}  // namespace
}  // namespace trirast
