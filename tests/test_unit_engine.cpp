// The improved-Bresenham unit against the golden rasterizer, triangle for triangle: the spans must
// be identical (docs/unit.md; docs/coverage-rule.md). Random triangles come from a fixed-seed
// splitmix64, so every run checks the same ones. TRIRAST_RANDOM_COUNT overrides the size of the
// RandomViewport family (scripts/unit_million.sh runs a million).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

#include "common/fixed_point.hpp"
#include "common/setup.hpp"
#include "golden/golden.hpp"
#include "common/reference_raster.hpp"
#include "improved/improved_unit.hpp"

namespace trirast {
namespace {

// The fixed-seed generator of the reference checks (splitmix64, identical on every platform).
using test::TestRng;

// A vertex coordinate given in 1/2^S units, clamped to the representable range, as a double.
double coord(int64_t sub, const RasterConfig& cfg) {
  const int64_t lim = cfg.coord_limit_px() << cfg.subpixel_bits;
  sub = std::clamp<int64_t>(sub, -lim, lim - 1);
  return double(sub) / double(int64_t(1) << cfg.subpixel_bits);
}

// Builds a triangle from three vertices in 1/2^S units.
InputTriangle tri_sub(const int64_t x[3], const int64_t y[3], const RasterConfig& cfg) {
  InputTriangle t{};
  for (int k = 0; k < 3; ++k) {
    t.x[k] = coord(x[k], cfg);
    t.y[k] = coord(y[k], cfg);
  }
  return t;
}

// Three vertices within +-ext pixels of a centre inside the viewport (a margin around it), on a
// grid of `grid` subpixels.
InputTriangle random_near(TestRng& rng, const RasterConfig& cfg, int64_t ext_px, int64_t grid) {
  const int64_t u = int64_t(1) << cfg.subpixel_bits;
  const int64_t cx = rng.range(-64 * u, (cfg.width + 64) * u);
  const int64_t cy = rng.range(-64 * u, (cfg.height + 64) * u);
  int64_t x[3], y[3];
  for (int k = 0; k < 3; ++k) {
    x[k] = (cx + rng.range(-ext_px * u, ext_px * u)) / grid * grid;
    y[k] = (cy + rng.range(-ext_px * u, ext_px * u)) / grid * grid;
  }
  return tri_sub(x, y, cfg);
}

// The mixed family: mostly small, some medium, a few huge ones reaching the coordinate limit.
InputTriangle random_mixed(TestRng& rng, const RasterConfig& cfg, int64_t grid) {
  const uint64_t r = rng.next() % 1000;
  if (r < 700) return random_near(rng, cfg, 24, grid);
  if (r < 950) return random_near(rng, cfg, 200, grid);
  if (r < 990) return random_near(rng, cfg, 2048, grid);
  // One vertex near the viewport, two anywhere up to +-(coord limit).
  InputTriangle t = random_near(rng, cfg, 64, grid);
  const int64_t lim = cfg.coord_limit_px() << cfg.subpixel_bits;
  for (int k = 1; k < 3; ++k) {
    t.x[k] = coord(rng.range(-lim, lim - 1) / grid * grid, cfg);
    t.y[k] = coord(rng.range(-lim, lim - 1) / grid * grid, cfg);
  }
  return t;
}

struct Compared {
  uint64_t triangles = 0;  // set-up triangles compared
  uint64_t spans = 0;      // golden spans
  uint64_t pixels = 0;
};

// Sets the scene up, runs golden and the unit in both boundary modes, and compares the sorted
// spans. Reports the first few differing triangles with their vertices.
Compared compare_with_golden(const std::vector<InputTriangle>& tris, RasterConfig cfg) {
  Compared c;
  const SetupResult setup = setup_scene(tris, cfg);
  SpanList golden;
  for (const TriangleSetup& t : setup.tris) golden_triangle(t, cfg, golden);
  sort_spans(golden);
  for (BoundaryMode mode : {BoundaryMode::Step, BoundaryMode::Divide}) {
    cfg.boundary = mode;
    EngineResult r;
    make_improved_datapath_engine()->run(setup, cfg, r);
    sort_spans(r.spans);
    // Work counters agree with the spans.
    EXPECT_EQ(r.work["spans"], r.spans.size());
    EXPECT_EQ(int64_t(r.work["pixels"]), count_pixels(r.spans));
    if (mode == BoundaryMode::Divide) {
      EXPECT_EQ(r.work["boundary_steps"], 0u);
    }
    if (r.spans == golden) continue;
    // Find and report the differing triangles.
    int reported = 0;
    for (const TriangleSetup& t : setup.tris) {
      SpanList g, u;
      golden_triangle(t, cfg, g);
      ImprovedUnit unit(cfg);
      unit.run_triangle(t, u);
      if (g == u) continue;
      const InputTriangle& in = tris[t.index];
      ADD_FAILURE() << boundary_mode_name(mode) << ": triangle " << t.index << " (" << in.x[0]
                    << "," << in.y[0] << ") (" << in.x[1] << "," << in.y[1] << ") (" << in.x[2]
                    << "," << in.y[2] << "): golden " << g.size() << " spans, unit " << u.size();
      if (++reported == 5) break;
    }
    if (reported == 0) ADD_FAILURE() << boundary_mode_name(mode) << ": span lists differ";
  }
  c.triangles = setup.tris.size();
  c.spans = golden.size();
  c.pixels = uint64_t(count_pixels(golden));
  return c;
}

// Generates `count` triangles with `gen` and compares them in batches.
Compared run_family(uint64_t count, const RasterConfig& cfg,
                    const std::function<InputTriangle(TestRng&)>& gen, uint64_t seed) {
  TestRng rng{seed};
  Compared total;
  const uint64_t batch = 20000;
  for (uint64_t done = 0; done < count; done += batch) {
    std::vector<InputTriangle> tris;
    for (uint64_t i = done; i < std::min(count, done + batch); ++i) tris.push_back(gen(rng));
    const Compared c = compare_with_golden(tris, cfg);
    total.triangles += c.triangles;
    total.spans += c.spans;
    total.pixels += c.pixels;
    if (::testing::Test::HasFailure()) break;
  }
  std::printf("compared %llu triangles (%llu spans, %llu pixels) unit vs golden\n",
              (unsigned long long)total.triangles, (unsigned long long)total.spans,
              (unsigned long long)total.pixels);
  return total;
}

uint64_t count_from_env(uint64_t fallback) {
  const char* s = std::getenv("TRIRAST_RANDOM_COUNT");
  return s ? std::strtoull(s, nullptr, 10) : fallback;
}

TEST(UnitEngine, RandomViewport) {
  // 1/256 grid, 1024x768, straddling the edges, some vertices out to the coordinate limit.
  RasterConfig cfg;
  const uint64_t count = count_from_env(100000);
  const Compared c = run_family(
      count, cfg, [&](TestRng& r) { return random_mixed(r, cfg, 1); }, 1);
  EXPECT_GT(c.triangles, count * 9 / 10);  // few degenerate
  EXPECT_GT(c.spans, count);
}

TEST(UnitEngine, HalfPixelLattice) {
  // Vertices on the half-pixel lattice: edges through pixel centres, exact ties everywhere.
  RasterConfig cfg;
  const Compared c = run_family(
      100000, cfg,
      [&](TestRng& r) {
        return r.next() % 4 ? random_near(r, cfg, 6, 128) : random_mixed(r, cfg, 128);
      },
      2);
  EXPECT_GT(c.spans, 100000u);
}

TEST(UnitEngine, LargeViewport) {
  RasterConfig cfg;
  cfg.width = cfg.height = 4096;
  const Compared c = run_family(
      10000, cfg, [&](TestRng& r) { return random_mixed(r, cfg, 1); }, 3);
  EXPECT_GT(c.spans, 10000u);
}

TEST(UnitEngine, NearHorizontalAndNearVertical) {
  // dy of 1-3 subpixels with a huge dx, and the transpose.
  RasterConfig cfg;
  const Compared c = run_family(
      20000, cfg,
      [&](TestRng& r) {
        const int64_t u = 256;
        const int64_t x0 = r.range(-500 * u, 1500 * u), y0 = r.range(-10 * u, 780 * u);
        const int64_t dx = r.range(-3000 * u, 3000 * u),
                      d = r.range(1, 3) * (r.next() & 1 ? 1 : -1);
        const int64_t t = r.range(-u, 2 * u);  // third vertex offset along the short side
        int64_t x[3] = {x0, x0 + dx, x0 + r.range(-3000 * u, 3000 * u)};
        int64_t y[3] = {y0, y0 + d, y0 + t};
        if (r.next() & 1) {  // near-vertical: swap the axes
          for (int k = 0; k < 3; ++k) std::swap(x[k], y[k]);
        }
        return tri_sub(x, y, cfg);
      },
      4);
  EXPECT_GT(c.spans, 20000u);
}

TEST(UnitEngine, SliversAndTinyTriangles) {
  RasterConfig cfg;
  const Compared c = run_family(
      40000, cfg,
      [&](TestRng& r) {
        const int64_t u = 256;
        if (r.next() & 1) return random_near(r, cfg, 2, 1);  // tiny: within a few pixels
        // Sliver: two far-apart vertices and a third a few subpixels off the line between them.
        const int64_t x0 = r.range(-100 * u, 1100 * u), y0 = r.range(-100 * u, 850 * u);
        const int64_t dx = r.range(-1500 * u, 1500 * u), dy = r.range(-1500 * u, 1500 * u);
        const int64_t m = r.range(0, 1024);
        const int64_t off = r.next() & 1 ? 4 : 200;
        int64_t x[3] = {x0, x0 + dx, x0 + dx * m / 1024 + r.range(-off, off)};
        int64_t y[3] = {y0, y0 + dy, y0 + dy * m / 1024 + r.range(-off, off)};
        return tri_sub(x, y, cfg);
      },
      5);
  EXPECT_GT(c.spans, 20000u);
}

TEST(UnitEngine, CoordinatesNearTheLimit) {
  // Vertices near +-32767 pixels: edge values close to the 2p+2-bit width.
  RasterConfig cfg;
  const int64_t lim = 32768 * 256;
  const Compared c = run_family(
      400, cfg,
      [&](TestRng& r) {
        int64_t x[3], y[3];
        for (int k = 0; k < 3; ++k) {
          x[k] = r.next() & 1 ? r.range(-lim, -lim + 300 * 256) : r.range(lim - 300 * 256, lim - 1);
          y[k] = r.next() & 1 ? r.range(-lim, -lim + 300 * 256) : r.range(lim - 300 * 256, lim - 1);
        }
        if (r.next() % 3 == 0) {  // one vertex inside the viewport
          x[0] = r.range(0, 1024 * 256);
          y[0] = r.range(0, 768 * 256);
        }
        return tri_sub(x, y, cfg);
      },
      6);
  EXPECT_GT(c.spans, 10000u);
}

TEST(UnitEngine, SubpixelBits) {
  for (int S : {0, 2, 4, 8}) {
    RasterConfig cfg;
    cfg.subpixel_bits = S;
    SCOPED_TRACE("S = " + std::to_string(S));
    const Compared c = run_family(
        15000, cfg, [&](TestRng& r) { return random_mixed(r, cfg, 1); }, 7 + S);
    EXPECT_GT(c.spans, 15000u);
  }
}

TEST(UnitEngine, NarrowCoordinateRange) {
  // A narrower configured range (12 integer bits) with small boxes (box_bits 11).
  RasterConfig cfg;
  cfg.coord_int_bits = 12;
  cfg.box_bits = 11;
  const Compared c = run_family(
      20000, cfg, [&](TestRng& r) { return random_mixed(r, cfg, 1); }, 20);
  EXPECT_GT(c.spans, 20000u);
}

TEST(UnitEngine, BoxTooBigForBoxBits) {
  RasterConfig cfg;
  cfg.box_bits = 6;  // boxes up to 64 x 64 pixels
  // Small triangles run.
  const Compared c = run_family(
      5000, cfg, [&](TestRng& r) { return random_near(r, cfg, 20, 1); }, 21);
  EXPECT_GT(c.spans, 5000u);
  // A 100-pixel-wide one is refused with a message naming the triangle and the value.
  const SetupResult s = setup_scene(
      {InputTriangle{{1, 2, 1}, {1, 1, 2}}, InputTriangle{{10, 110, 10}, {10, 10, 30}}}, cfg);
  EngineResult r;
  try {
    make_improved_datapath_engine()->run(s, cfg, r);
    FAIL() << "a 100-pixel box was accepted with box_bits = 6";
  } catch (const WidthError& e) {
    EXPECT_NE(std::string(e.what()).find("triangle 1: Xmax = 99 does not fit 6-bit"),
              std::string::npos)
        << e.what();
  }
}

TEST(UnitEngine, WorkCounters) {
  // One known triangle: the counters the timing model reads, per edge and in total.
  RasterConfig cfg;
  const SetupResult s = setup_scene({InputTriangle{{10.5, 40.25, 20.5}, {5.5, 15.5, 30.75}}}, cfg);
  ASSERT_EQ(s.tris.size(), 1u);
  for (BoundaryMode mode : {BoundaryMode::Step, BoundaryMode::Divide})
  for (DividerMode divider : {DividerMode::Fixed, DividerMode::Adaptive}) {
    cfg.boundary = mode;
    cfg.divider = divider;
    ImprovedUnit unit(cfg);
    SpanList spans;
    const UnitTriangleResult r = unit.run_triangle(s.tris[0], spans);
    const int64_t rows = r.iface.Ymax + 1;
    EXPECT_EQ(r.work.rows_visited, uint64_t(rows));
    EXPECT_EQ(r.work.spans, spans.size());
    EXPECT_EQ(int64_t(r.work.pixels), count_pixels(spans));
    // Box 30 x 26 pixels (Xmax = 29, Ymax = 25): adaptive divisions run bits(29) + 1 = 6
    // iterations along x; fixed ones Q = 15.
    ASSERT_EQ(r.iface.Xmax, 29);
    ASSERT_EQ(r.iface.Ymax, 25);
    if (divider == DividerMode::Fixed || mode == BoundaryMode::Step) {
      EXPECT_EQ(r.work.divider_iterations(),
                (divider == DividerMode::Fixed ? 15 : 6) * r.work.divisions());
    }
    for (int k = 0; k < 3; ++k) {
      // Every edge divides its slope and its entry x (all three enter this box).
      EXPECT_GE(r.work.edge[k].divisions, 2u) << k;
      EXPECT_LE(r.work.edge[k].rows_stepped, uint64_t(rows - 1)) << k;
      if (mode == BoundaryMode::Divide) {
        EXPECT_EQ(r.work.edge[k].boundary_steps, 0u);
      } else {
        EXPECT_EQ(r.work.edge[k].boundary_steps, uint64_t(r.walker_entry[k].j_entry)) << k;
      }
    }
    EngineResult er;
    make_improved_datapath_engine()->run(s, cfg, er);
    EXPECT_EQ(er.work["divider_iterations"], r.work.divider_iterations());
    EXPECT_EQ(er.work["boundary_steps"], r.work.boundary_steps());
    EXPECT_EQ(er.work["rows_stepped"], r.work.rows_stepped());
    EXPECT_EQ(er.work["rows_visited"], r.work.rows_visited);
    EXPECT_EQ(er.work["spans"], r.work.spans);
  }
}

}  // namespace
}  // namespace trirast
