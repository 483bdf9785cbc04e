// The traditional Bresenham baseline (model/trad/trad_bresenham.hpp): its own behaviour,
// hand-derived, and its difference from the golden rule (001_efbf726a8c96efcc.txt, 2.1.1). The
// baseline is not exact; these tests pin down what it does, not that it agrees with golden.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "common/fixed_point.hpp"
#include "common/setup.hpp"
#include "common/span_diff.hpp"
#include "golden/golden.hpp"
#include "common/reference_raster.hpp"
#include "trad/trad_bresenham.hpp"
#include "support/scene_helpers.hpp"

namespace trirast {
namespace {

using test::tri;
using test::TestRng;

struct Raster {
  SpanList spans;
  std::vector<TradTriangleResult> results;
};

Raster run_trad(const SetupResult& setup, const RasterConfig& cfg) {
  Raster r;
  TradSpanFiller filler(cfg);
  for (const TriangleSetup& t : setup.tris) r.results.push_back(filler.run_triangle(t, r.spans));
  sort_spans(r.spans);
  return r;
}

// ---------------------------------------------------------------------------------------------
// Figure 2.4: three vertices in one pixel whose centre is inside. Golden covers the pixel; the
// traditional rasterizer makes no Bresenham step and draws nothing.
TEST(TradBresenham, Figure24OnePixelTriangleIsLost) {
  RasterConfig cfg;
  const SetupResult setup = setup_scene({tri(10.3, 10.3, 10.8, 10.4, 10.4, 10.8)}, cfg);
  ASSERT_EQ(setup.tris.size(), 1u);  // setup accepts it: it has area

  const SpanList golden = test::golden_spans(setup, cfg);
  ASSERT_EQ(golden.size(), 1u);
  EXPECT_EQ(golden[0], (Span{0, 10, 10, 11}));
  EXPECT_EQ(count_pixels(golden), 1);

  const Raster trad = run_trad(setup, cfg);
  EXPECT_TRUE(trad.spans.empty());
  EXPECT_TRUE(trad.results[0].verts.empty);
  EXPECT_EQ(trad.results[0].steps(), 0u);

  const SpanDiff d = diff_spans(golden, trad.spans);
  EXPECT_EQ(d.missing_pixels, 1);
  EXPECT_EQ(d.extra_pixels, 0);
}

// ---------------------------------------------------------------------------------------------
// A right triangle with vertices on pixel corners, (2,2), (8,2), (2,8), derived by hand.
//
// Golden (docs/coverage-rule.md): centres (px+.5, py+.5). The legs x = 2 and y = 2 pass no centre.
// The hypotenuse x + y = 10 passes the centres with px + py = 9; it is a right edge (A < 0), so
// those are out. Covered: px >= 2, py >= 2, px + py <= 8:
//   row 2: [2,7)  row 3: [2,6)  row 4: [2,5)  row 5: [2,4)  row 6: [2,3)     = 15 pixels.
// Traditional: integer pixels (2,2), (8,2), (2,8); sorted by (y, x): p0 (2,2), p1 (8,2), p2 (2,8).
//   p0->p1 is horizontal: row 2, x 2..8.   p0->p2 is vertical: x = 2, rows 2..8.
//   p1->p2 is the 45-degree diagonal: (8,2) (7,3) (6,4) (5,5) (4,6) (3,7) (2,8).
//   Row py: leftmost 2, rightmost 10 - py, span [2, 11 - py):
//   row 2: [2,9)  row 3: [2,8)  row 4: [2,7)  row 5: [2,6)  row 6: [2,5)  row 7: [2,4)  row 8:
//   [2,3) = 28 pixels. Every golden pixel is drawn (missing 0); 13 pixels are extra, all at the
//   hypotenuse and the bottom vertex.
// Steps: 6 + 6 + 6 = 18.
TEST(TradBresenham, HandDerivedRightTriangle) {
  for (int s : {8, 0, 3}) {
    SCOPED_TRACE("subpixel bits " + std::to_string(s));
    RasterConfig cfg;
    cfg.subpixel_bits = s;
    const SetupResult setup = setup_scene({tri(2, 2, 8, 2, 2, 8)}, cfg);
    ASSERT_EQ(setup.tris.size(), 1u);

    const SpanList golden = test::golden_spans(setup, cfg);
    const SpanList golden_expected = {
        {0, 2, 2, 7}, {0, 3, 2, 6}, {0, 4, 2, 5}, {0, 5, 2, 4}, {0, 6, 2, 3}};
    EXPECT_EQ(golden, golden_expected);

    const Raster trad = run_trad(setup, cfg);
    const SpanList trad_expected = {{0, 2, 2, 9}, {0, 3, 2, 8}, {0, 4, 2, 7}, {0, 5, 2, 6},
                                    {0, 6, 2, 5}, {0, 7, 2, 4}, {0, 8, 2, 3}};
    EXPECT_EQ(trad.spans, trad_expected);
    EXPECT_EQ(trad.results[0].steps(), 18u);
    EXPECT_EQ(trad.results[0].rows_visited, 7u);
    EXPECT_EQ(trad.results[0].spans, 7u);
    EXPECT_EQ(trad.results[0].pixels, 28u);

    const SpanDiff d = diff_spans(golden, trad.spans);
    EXPECT_EQ(d.missing_pixels, 0);
    EXPECT_EQ(d.extra_pixels, 13);
  }
}

// The same shape, large: (a,a), (a+n,a), (a,a+n). By the derivation above, golden row py in
// [a, a+n-2] is [a, 2a+n-1-py) and trad row py in [a, a+n] is [a, 2a+n+1-py): the interior and the
// left/top edges agree, the hypotenuse side differs by two pixels per row, plus the two rows below.
// Extra = (n+1)(n+2)/2 - n(n-1)/2 = 2n + 1.
TEST(TradBresenham, LargeRightTriangleDiffersOnlyAtHypotenuse) {
  RasterConfig cfg;
  const int64_t a = 100, n = 300;
  const SetupResult setup = setup_scene(
      {tri(double(a), double(a), double(a + n), double(a), double(a), double(a + n))}, cfg);
  const SpanList golden = test::golden_spans(setup, cfg);
  const Raster trad = run_trad(setup, cfg);
  ASSERT_EQ(int64_t(golden.size()), n - 1);
  ASSERT_EQ(int64_t(trad.spans.size()), n + 1);
  for (int64_t i = 0; i <= n; ++i) {
    const int64_t py = a + i;
    EXPECT_EQ(trad.spans[i], (Span{0, int32_t(py), int32_t(a), int32_t(2 * a + n + 1 - py)}));
    if (i < n - 1) {
      EXPECT_EQ(golden[i], (Span{0, int32_t(py), int32_t(a), int32_t(2 * a + n - 1 - py)}));
    }
  }
  const SpanDiff d = diff_spans(golden, trad.spans);
  EXPECT_EQ(d.missing_pixels, 0);
  EXPECT_EQ(d.extra_pixels, 2 * n + 1);
  EXPECT_EQ(trad.results[0].steps(), uint64_t(3 * n));
}

// ---------------------------------------------------------------------------------------------
// Bresenham lines in all 8 octants (and the axes and diagonals) against the obvious reference: at
// major step j the minor coordinate is the exact line's value j*dmin/dmaj rounded to the nearest
// integer, a tie going to the side of the start point.
struct Pixel {
  int64_t x, y;
  bool operator==(const Pixel& o) const { return x == o.x && y == o.y; }
};

std::vector<Pixel> reference_line(Vec2i a, Vec2i b) {
  const int64_t dx = b.x - a.x, dy = b.y - a.y;
  const bool x_major = std::llabs(dx) >= std::llabs(dy);
  const int64_t dmaj = x_major ? std::llabs(dx) : std::llabs(dy);
  const int64_t dmin = x_major ? std::llabs(dy) : std::llabs(dx);
  const int64_t smaj = (x_major ? dx : dy) < 0 ? -1 : 1;
  const int64_t smin = (x_major ? dy : dx) < 0 ? -1 : 1;
  std::vector<Pixel> px;
  for (int64_t j = 0; j <= dmaj; ++j) {
    const double exact = dmaj == 0 ? 0.0 : double(j) * double(dmin) / double(dmaj);
    const int64_t k = int64_t(std::ceil(exact - 0.5));  // nearest, ties toward the start
    const int64_t maj = smaj * j, mn = smin * k;
    px.push_back(x_major ? Pixel{a.x + maj, a.y + mn} : Pixel{a.x + mn, a.y + maj});
  }
  return px;
}

std::vector<Pixel> stepped_line(Vec2i a, Vec2i b, int64_t* steps = nullptr) {
  BresenhamLine line;
  line.start(a, b);
  std::vector<Pixel> px{{line.x(), line.y()}};
  int64_t n = 0;
  while (line.step()) {
    px.push_back({line.x(), line.y()});
    ++n;
  }
  if (steps) *steps = n;
  return px;
}

TEST(TradBresenham, LinesInAllOctantsMatchRounding) {
  int octants_seen[2][2][2] = {};
  for (int64_t dx = -23; dx <= 23; ++dx) {
    for (int64_t dy = -23; dy <= 23; ++dy) {
      const Vec2i a{5 - dx / 3, -7 + dy / 5};
      const Vec2i b{a.x + dx, a.y + dy};
      int64_t steps = 0;
      const std::vector<Pixel> got = stepped_line(a, b, &steps);
      const std::vector<Pixel> want = reference_line(a, b);
      ASSERT_EQ(got.size(), want.size()) << dx << "," << dy;
      for (size_t i = 0; i < got.size(); ++i)
        ASSERT_TRUE(got[i] == want[i])
            << "dx " << dx << " dy " << dy << " step " << i << ": (" << got[i].x << "," << got[i].y
            << ") want (" << want[i].x << "," << want[i].y << ")";
      EXPECT_EQ(steps, std::max(std::llabs(dx), std::llabs(dy)));
      EXPECT_TRUE(got.back() == (Pixel{b.x, b.y}));  // ends exactly on b
      // Unit steps: the major axis moves by one, the minor by at most one.
      for (size_t i = 1; i < got.size(); ++i) {
        EXPECT_LE(std::llabs(got[i].x - got[i - 1].x), 1);
        EXPECT_LE(std::llabs(got[i].y - got[i - 1].y), 1);
      }
      if (dx != 0 && dy != 0 && std::llabs(dx) != std::llabs(dy))
        octants_seen[dx > 0][dy > 0][std::llabs(dx) > std::llabs(dy)] = 1;
    }
  }
  for (auto& p : octants_seen)
    for (auto& q : p)
      for (int r : q) EXPECT_EQ(r, 1);
}

// seek(j) lands in the state j steps reach, and row_run(y) is the extent of the stepped pixels on
// row y: the closed forms the engine uses to skip off-screen parts.
TEST(TradBresenham, SeekAndRowRunMatchStepping) {
  TestRng rng(7);
  for (int n = 0; n < 3000; ++n) {
    const int64_t lim = n < 2500 ? 40 : 5000;
    const Vec2i a{rng.range(-lim, lim), rng.range(-lim, lim)};
    const Vec2i b{rng.range(-lim, lim), rng.range(-lim, lim)};
    BresenhamLine walker, seeker;
    walker.start(a, b);
    seeker.start(a, b);
    std::map<int64_t, RowRun> rows;
    const int64_t every = std::max<int64_t>(1, walker.steps() / 50);
    do {
      auto it = rows.find(walker.y());
      if (it == rows.end()) {
        rows[walker.y()] = RowRun{walker.x(), walker.x()};
      } else {
        it->second.x_first = std::min(it->second.x_first, walker.x());
        it->second.x_last = std::max(it->second.x_last, walker.x());
      }
      if (walker.index() % every == 0 || walker.index() == walker.steps()) {
        seeker.seek(walker.index());
        ASSERT_EQ(seeker.x(), walker.x());
        ASSERT_EQ(seeker.y(), walker.y());
        ASSERT_EQ(seeker.decision(), walker.decision());
      }
    } while (walker.step());
    const int64_t y_lo = std::min(a.y, b.y), y_hi = std::max(a.y, b.y);
    for (int64_t y = y_lo - 2; y <= y_hi + 2; ++y) {
      RowRun run{0, 0};
      const bool on = seeker.row_run(y, run);
      const auto it = rows.find(y);
      ASSERT_EQ(on, it != rows.end()) << "row " << y;
      if (on) {
        ASSERT_EQ(run.x_first, it->second.x_first) << "row " << y;
        ASSERT_EQ(run.x_last, it->second.x_last) << "row " << y;
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The whole rasterizer against a slow reference that walks every pixel of the three lines with
// step() (what the hardware does cycle by cycle), fills each row between its extreme pixels and
// clips. Small triangles and huge ones (vertices anywhere in +-2^15 pixels).
SpanList walk_reference(const TriangleSetup& t, const RasterConfig& cfg) {
  SpanList out;
  const TradVertices v = TradVertexQuantizer(cfg).run(t);
  if (v.empty) return out;
  std::map<int64_t, RowRun> rows;
  const Vec2i ends[3][2] = {{v.p[0], v.p[2]}, {v.p[0], v.p[1]}, {v.p[1], v.p[2]}};
  for (const auto& e : ends) {
    BresenhamLine line;
    line.start(e[0], e[1]);
    do {
      auto it = rows.find(line.y());
      if (it == rows.end()) {
        rows[line.y()] = RowRun{line.x(), line.x()};
      } else {
        it->second.x_first = std::min(it->second.x_first, line.x());
        it->second.x_last = std::max(it->second.x_last, line.x());
      }
    } while (line.step());
  }
  for (const auto& [y, run] : rows) {
    if (y < 0 || y >= cfg.height) continue;
    const int64_t b = std::max<int64_t>(run.x_first, 0);
    const int64_t e = std::min<int64_t>(run.x_last + 1, cfg.width);
    if (b < e) out.push_back(Span{t.index, int32_t(y), int32_t(b), int32_t(e)});
  }
  return out;
}

std::vector<InputTriangle> random_triangles(TestRng& rng, int count, int64_t lo, int64_t hi,
                                            int64_t max_size) {
  std::vector<InputTriangle> tris;
  for (int n = 0; n < count; ++n) {
    const int64_t cx = rng.range(lo, hi), cy = rng.range(lo, hi);
    InputTriangle t{};
    for (int k = 0; k < 3; ++k) {
      // 1/256-pixel grid, clamped to [-32768, 32768).
      const int64_t x = std::clamp<int64_t>(cx * 256 + rng.range(-max_size * 256, max_size * 256),
                                            -32768 * 256, 32768 * 256 - 1);
      const int64_t y = std::clamp<int64_t>(cy * 256 + rng.range(-max_size * 256, max_size * 256),
                                            -32768 * 256, 32768 * 256 - 1);
      t.x[k] = double(x) / 256.0;
      t.y[k] = double(y) / 256.0;
    }
    tris.push_back(t);
  }
  return tris;
}

TEST(TradBresenham, MatchesFullPixelWalk) {
  TestRng rng(11);
  RasterConfig cfg;
  std::vector<InputTriangle> tris = random_triangles(rng, 3000, -50, 1100, 40);
  const std::vector<InputTriangle> huge = random_triangles(rng, 60, -32768, 32767, 40000);
  tris.insert(tris.end(), huge.begin(), huge.end());
  const SetupResult setup = setup_scene(tris, cfg);
  ASSERT_GT(setup.tris.size(), 2500u);
  TradSpanFiller filler(cfg);
  for (const TriangleSetup& t : setup.tris) {
    SpanList got;
    filler.run_triangle(t, got);
    const SpanList want = walk_reference(t, cfg);
    ASSERT_EQ(got, want) << "triangle " << t.index;
  }
}

// ---------------------------------------------------------------------------------------------
// Work counts: steps are the sum of max(|dx|, |dy|) over the three edges of the integer pixels;
// rows, spans and pixels are what came out.
TEST(TradBresenham, WorkCountsAreEdgeLengths) {
  TestRng rng(3);
  RasterConfig cfg;
  const std::vector<InputTriangle> tris = random_triangles(rng, 5000, -30, 1060, 60);
  const SetupResult setup = setup_scene(tris, cfg);
  EngineResult res;
  make_trad_datapath_engine()->run(setup, cfg, res);

  uint64_t steps = 0, rows = 0, collinear = 0;
  for (const TriangleSetup& t : setup.tris) {
    const InputTriangle& in = tris[t.index];  // vertices on the 1/256 grid: floor is exact
    int64_t px[3], py[3];
    for (int k = 0; k < 3; ++k) {
      px[k] = int64_t(std::floor(in.x[k]));
      py[k] = int64_t(std::floor(in.y[k]));
    }
    if ((px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0]) == 0) {
      ++collinear;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3;
      steps += uint64_t(std::max(std::llabs(px[k1] - px[k]), std::llabs(py[k1] - py[k])));
    }
    const int64_t y0 = std::max<int64_t>(*std::min_element(py, py + 3), 0);
    const int64_t y1 = std::min<int64_t>(*std::max_element(py, py + 3), cfg.height - 1);
    if (y1 >= y0) rows += uint64_t(y1 - y0 + 1);
  }
  EXPECT_GT(steps, 0u);
  EXPECT_EQ(res.work["trad_bresenham_steps"], steps);
  EXPECT_EQ(res.work["rows_visited"], rows);
  EXPECT_EQ(res.work["trad_collinear"], collinear);
  EXPECT_EQ(res.work["triangles"], setup.tris.size());
  EXPECT_EQ(res.work["spans"], res.spans.size());
  EXPECT_EQ(res.work["pixels"], uint64_t(count_pixels(res.spans)));
  EXPECT_TRUE(res.cycles.empty());
}

// ---------------------------------------------------------------------------------------------
TEST(TradBresenham, Deterministic) {
  TestRng rng(5);
  RasterConfig cfg;
  const std::vector<InputTriangle> tris = random_triangles(rng, 4000, -100, 1100, 200);
  const SetupResult setup = setup_scene(tris, cfg);
  EngineResult r1, r2;
  make_trad_datapath_engine()->run(setup, cfg, r1);
  make_trad_datapath_engine()->run(setup, cfg, r2);
  EXPECT_EQ(r1.spans, r2.spans);
  EXPECT_EQ(r1.work, r2.work);
  // And the same engine object run twice (no state leaks between runs).
  auto engine = make_trad_datapath_engine();
  EngineResult r3, r4;
  engine->run(setup, cfg, r3);
  engine->run(setup, cfg, r4);
  EXPECT_EQ(r3.spans, r1.spans);
  EXPECT_EQ(r4.spans, r1.spans);
  // Spans leave each triangle in row order, inside the viewport.
  for (size_t i = 0; i < r1.spans.size(); ++i) {
    const Span& s = r1.spans[i];
    ASSERT_GE(s.y, 0);
    ASSERT_LT(s.y, cfg.height);
    ASSERT_GE(s.x_begin, 0);
    ASSERT_LE(s.x_end, cfg.width);
    ASSERT_LT(s.x_begin, s.x_end);
    if (i > 0 && r1.spans[i - 1].tri == s.tri) {
      ASSERT_GT(s.y, r1.spans[i - 1].y);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Vertices at the ends of the coordinate range: no crash, only viewport rows visited, the full
// (unclipped) line lengths counted as steps.
TEST(TradBresenham, BigCoordinates) {
  RasterConfig cfg;
  const std::vector<InputTriangle> tris = {
      // Covers the whole viewport.
      tri(-32768, -32768, 32767, -32768, 0, 32767),
      // The extreme corners of the range, fractional.
      tri(-32768, -32768, 32767.99609375, 32767.99609375, -32768, 32767.99609375),
      // Entirely off screen.
      tri(-32768, 20000, 32767, 20001, 0, 32767),
      // A sliver through the viewport.
      tri(-32768, 100, 32767, 101, 32767, 99),
  };
  const SetupResult setup = setup_scene(tris, cfg);
  ASSERT_EQ(setup.tris.size(), 4u);
  const Raster trad = run_trad(setup, cfg);

  // Triangle 0: every row [0, W); steps 65535 * 3.
  EXPECT_EQ(trad.results[0].steps(), 3u * 65535u);
  EXPECT_EQ(trad.results[0].rows_visited, uint64_t(cfg.height));
  EXPECT_EQ(trad.results[0].pixels, uint64_t(cfg.width) * uint64_t(cfg.height));
  // Triangle 2: nothing, no rows visited, yet the hardware would still walk its edges.
  EXPECT_EQ(trad.results[2].rows_visited, 0u);
  EXPECT_EQ(trad.results[2].spans, 0u);
  EXPECT_GT(trad.results[2].steps(), 0u);
  for (const TradTriangleResult& r : trad.results) EXPECT_LE(r.rows_visited, uint64_t(cfg.height));

  // Against the slow walk and against golden: they agree on the whole-viewport triangle.
  for (const TriangleSetup& t : setup.tris) {
    SpanList got;
    TradSpanFiller(cfg).run_triangle(t, got);
    EXPECT_EQ(got, walk_reference(t, cfg)) << "triangle " << t.index;
  }
  SpanList g0, t0;
  golden_triangle(setup.tris[0], cfg, g0);
  TradSpanFiller(cfg).run_triangle(setup.tris[0], t0);
  EXPECT_EQ(g0, t0);
}

// ---------------------------------------------------------------------------------------------
// The baseline is wrong only near the edges: every pixel it adds or misses has its centre within
// 1.5 pixels of the triangle's boundary (integer vertices move the edges by at most half a pixel
// per axis, Bresenham rounds by at most half a pixel more). And it is really wrong: on a random
// scene it both adds and misses pixels.
double distance_to_segment(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
}

TEST(TradBresenham, DiffersFromGoldenOnlyNearEdges) {
  TestRng rng(9);
  RasterConfig cfg;
  const std::vector<InputTriangle> tris = random_triangles(rng, 5000, -20, 1050, 30);
  const SetupResult setup = setup_scene(tris, cfg);
  const SpanList golden = test::golden_spans(setup, cfg);
  const Raster trad = run_trad(setup, cfg);
  const SpanDiff d = diff_spans(golden, trad.spans);
  EXPECT_GT(d.missing_pixels, 0);
  EXPECT_GT(d.extra_pixels, 0);
  double worst = 0;
  for (const SpanList* list : {&d.missing, &d.extra}) {
    for (const Span& s : *list) {
      const InputTriangle& t = tris[s.tri];
      for (int32_t x = s.x_begin; x < s.x_end; ++x) {
        double dist = 1e30;
        for (int k = 0; k < 3; ++k) {
          const int k1 = (k + 1) % 3;
          dist = std::min(
              dist, distance_to_segment(x + 0.5, s.y + 0.5, t.x[k], t.y[k], t.x[k1], t.y[k1]));
        }
        worst = std::max(worst, dist);
        ASSERT_LE(dist, 1.5) << "triangle " << s.tri << " pixel (" << x << "," << s.y << ")";
      }
    }
  }
  RecordProperty("worst_distance_x1000", int(worst * 1000));
}

}  // namespace
}  // namespace trirast
