// Cycle counts of the SystemC models (docs/timing.md): hand-derived expectations for small
// triangles, and an independent cycle-by-cycle reading of the contract (cycle_reference.hpp) on
// random scenes with every sink pattern, N = 1, 2, 4 and several FIFO depths.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/setup.hpp"
#include "common/sink_pattern.hpp"
#include "common/cycle_columns.hpp"
#include "common/cycle_reference.hpp"
#include "improved/improved_sc.hpp"
#include "trad/trad_sc.hpp"
#include "common/reference_raster.hpp"
#include "improved/improved_unit.hpp"
#include "trad/trad_timing.hpp"
#include "support/scene_helpers.hpp"

namespace trirast {
namespace {

using test::tri;

// The right triangle of the hand derivations: box 8 x 8 (x, y = 1..8), row j covers x = 1..8-j,
// 8 spans, 36 pixels. Edges: the top one (y = 1) is horizontal (no division, in at row 0: L = 0);
// the left one (x = 1) is vertical, in at row 0: slope + entry x = 2Q = 30; the hypotenuse is clear
// at row 0 and enters at row 1: step mode 1 step + slope + entry x = 31 (divide mode: + the entry
// row division = 45). So L = 31 (step), 45 (divide); with Q = 15 (box_bits 14).
InputTriangle right_triangle(double dx = 0) { return tri(1 + dx, 1, 9.25 + dx, 1, 1 + dx, 9.25); }

EngineResult run(std::unique_ptr<Engine> e, const std::vector<InputTriangle>& tris,
                 const RasterConfig& cfg) {
  const SetupResult setup = setup_scene(tris, cfg);
  EngineResult r;
  e->run(setup, cfg, r);
  return r;
}
EngineResult run_model(const std::vector<InputTriangle>& tris, const RasterConfig& cfg) {
  return run(make_improved_sc_engine(), tris, cfg);
}

void expect_cycles(const TriangleCycles& c, uint64_t accept, uint64_t first, uint64_t done,
                   uint64_t spans, uint64_t pixels, uint64_t stall) {
  EXPECT_EQ(c.accept_cycle, accept);
  EXPECT_EQ(c.first_span_cycle, first);
  EXPECT_EQ(c.done_cycle, done);
  EXPECT_EQ(c.spans, spans);
  EXPECT_EQ(c.pixels, pixels);
  EXPECT_EQ(c.stall_cycles, stall);
}

// The hand derivations below take Q = 15 iterations per division: the fixed divider.
RasterConfig fixed_divider() {
  RasterConfig cfg;
  cfg.divider = DividerMode::Fixed;
  return cfg;
}

// The adaptive divider (the default) runs bits(7) + 1 = 4 iterations for this 8 x 8 box:
// step mode L = 1 + 4 + 4 = 9, h = 12, rows in 13..20, popped in 14..21;
// divide mode L = 4 (entry row) + 4 + 4 = 12, h = 15, popped in 17..24.
TEST(ScCyclesHand, AdaptiveDividerSingleTriangle) {
  RasterConfig cfg;
  EngineResult r = run_model({right_triangle()}, cfg);
  ASSERT_EQ(r.cycles.size(), 1u);
  expect_cycles(r.cycles[0], 0, 14, 21, 8, 36, 0);
  EXPECT_EQ(r.total_cycles, 22u);
  EXPECT_EQ(r.work.at("busy_cycles.setup"), 2u + 9u);
  cfg.boundary = BoundaryMode::Divide;
  r = run_model({right_triangle()}, cfg);
  expect_cycles(r.cycles[0], 0, 17, 24, 8, 36, 0);
}

TEST(ScCyclesHand, SingleTriangleStepMode) {
  RasterConfig cfg = fixed_divider();
  const EngineResult r = run_model({right_triangle()}, cfg);
  ASSERT_EQ(r.cycles.size(), 1u);
  // h = 3 + 31 = 34; row j processed in 35 + j, popped in 36 + j.
  expect_cycles(r.cycles[0], 0, 36, 43, 8, 36, 0);
  EXPECT_EQ(r.total_cycles, 44u);
  EXPECT_EQ(r.work.at("busy_cycles.walk"), 8u);
  EXPECT_EQ(r.work.at("busy_cycles.setup"), 2u + 31u);
}

TEST(ScCyclesHand, SingleTriangleDivideMode) {
  RasterConfig cfg = fixed_divider();
  cfg.boundary = BoundaryMode::Divide;
  const EngineResult r = run_model({right_triangle()}, cfg);
  // h = 3 + 45 = 48.
  expect_cycles(r.cycles[0], 0, 50, 57, 8, 36, 0);
}

TEST(ScCyclesHand, EndpointsTwoAndFour) {
  for (int n : {2, 4}) {
    RasterConfig cfg = fixed_divider();
    cfg.endpoints = n;
    const EngineResult r = run_model({right_triangle()}, cfg);
    // Groups of n rows from cycle 35; the sink still takes one span per cycle: pops 36..43.
    expect_cycles(r.cycles[0], 0, 36, 43, 8, 36, 0);
    EXPECT_EQ(r.work.at("busy_cycles.walk"), uint64_t(8 / n)) << "N=" << n;
  }
}

TEST(ScCyclesHand, FifoFullWithFourEndpoints) {
  RasterConfig cfg = fixed_divider();
  cfg.endpoints = 4;
  cfg.fifo_depth = 4;
  const EngineResult r = run_model({right_triangle()}, cfg);
  // Group 0 in 35 (4 pushes, popped 36..39); group 1 needs count <= 0: stalls 36..39, goes in 40;
  // its spans are popped 41..44.
  expect_cycles(r.cycles[0], 0, 36, 44, 8, 36, 4);
  EXPECT_EQ(r.work.at("stall_cycles.walk"), 4u);
}

TEST(ScCyclesHand, PeriodicSinkAndShallowFifo) {
  RasterConfig cfg = fixed_divider();
  cfg.fifo_depth = 2;
  cfg.sink_stall = "periodic:1:1";  // ready in even cycles
  const EngineResult r = run_model({right_triangle()}, cfg);
  // Span k is popped in 36 + 2k; rows go in 35, 36, 37, then every other cycle (39, 41, .., 47)
  // once two spans wait: stalls in 38, 40, 42, 44, 46.
  expect_cycles(r.cycles[0], 0, 36, 50, 8, 36, 5);
  EXPECT_EQ(r.work.at("stall_cycles.span_sink"), 7u);  // spans 1..7 each wait one cycle
}

TEST(ScCyclesHand, BackToBackSetupOverlapsWalk) {
  RasterConfig cfg = fixed_divider();
  const EngineResult r = run_model({right_triangle(), right_triangle(20)}, cfg);
  ASSERT_EQ(r.cycles.size(), 2u);
  expect_cycles(r.cycles[0], 0, 36, 43, 8, 36, 0);
  // Accepted in h0 + 1 = 35, lanes done in 35 + 3 + 31 = 69 (the walk is idle from 43): h1 = 69.
  expect_cycles(r.cycles[1], 35, 71, 78, 8, 36, 0);
  EXPECT_EQ(r.total_cycles, 79u);
  EXPECT_EQ(r.work.at("stall_cycles.setup"), 0u);
}

TEST(ScCyclesHand, WalkBoundPairHoldsTheSetup) {
  RasterConfig cfg = fixed_divider();
  cfg.fifo_depth = 1;
  cfg.sink_stall = "periodic:1:9";  // one ready cycle in ten: the walk crawls
  const EngineResult r = run_model({right_triangle(), right_triangle(20)}, cfg);
  // Ready when c mod 10 = 0; a row needs an empty FIFO at the start of its cycle. Triangle 0:
  // row 0 in 35, popped in 40; row k >= 1 in 41 + 10(k-1) (the FIFO empties at the end of the pop
  // cycle), popped in 50 + 10(k-1): last row in 101, last pop in 110; stalls 5 + 6 * 9 = 59.
  expect_cycles(r.cycles[0], 0, 40, 110, 8, 36, 59);
  // Triangle 1: accepted in 35, lanes done in 69, the walk is idle from 102: h1 = 102 (33 cycles
  // of StHold beyond the lanes). Row 0 waits for the pop in 110: goes in 111, popped in 120;
  // row k popped in 120 + 10k; stalls 8 + 7 * 9 = 71.
  expect_cycles(r.cycles[1], 35, 120, 190, 8, 36, 71);
  EXPECT_EQ(r.work.at("stall_cycles.setup"), 102u - 69u);
}

TEST(ScCyclesHand, EmptyBoxRetiresInSetup) {
  RasterConfig cfg = fixed_divider();
  // No pixel centre in the box: x and y centres 1.5 lie outside [1.1, 1.4].
  const EngineResult r = run_model({tri(1.1, 1.1, 1.4, 1.1, 1.1, 1.4), right_triangle()}, cfg);
  ASSERT_EQ(r.cycles.size(), 2u);
  expect_cycles(r.cycles[0], 0, 1, 1, 0, 0, 0);
  expect_cycles(r.cycles[1], 2, 38, 45, 8, 36, 0);
}

TEST(ScCyclesHand, TriangleWithoutSpansRetiresInItsLastRow) {
  RasterConfig cfg = fixed_divider();
  // One-pixel box (centre 1.5, 1.5) that the sliver misses.
  const InputTriangle sliver = tri(1, 1, 1.3, 2, 2, 2.4);
  const SetupResult setup = setup_scene({sliver}, cfg);
  ASSERT_EQ(setup.tris.size(), 1u);
  ImprovedUnit unit(cfg);
  SpanList spans;
  const UnitTriangleResult u = unit.run_triangle(setup.tris[0], spans);
  ASSERT_TRUE(spans.empty());
  ASSERT_FALSE(u.iface.empty);
  uint64_t L = 0;
  for (const EdgeWork& e : u.work.edge) L = std::max(L, e.boundary_steps + e.divider_iterations);
  const EngineResult r = run_model({sliver}, cfg);
  // h = 3 + L, the one row in h + 1, retired there.
  expect_cycles(r.cycles[0], 0, 3 + L + 1, 3 + L + 1, 0, 0, 0);
  EXPECT_EQ(r.total_cycles, 3 + L + 2);
}

TEST(ScCyclesHand, TradSmallTriangle) {
  RasterConfig cfg;
  // Integer pixels p0 = (0,0), p1 = (4,0), p2 = (0,2). Long edge p0->p2: steps 0, 1, 1 on rows
  // 0..2; short side: p0->p1 4 steps on row 0, p1->p2 (x-major, 4 steps) 1, 2, 1: rows cost
  // max(1, 0, 5) = 5, max(1, 1, 2) = 2, max(1, 1, 1) = 1. h = 3; row 0 in 4..8 (pop 9),
  // row 1 in 9..10 (pop 11), row 2 in 11 (pop 12).
  const EngineResult r = run(make_trad_sc_engine(), {tri(0.5, 0.5, 4.5, 0.5, 0.5, 2.5)}, cfg);
  ASSERT_EQ(r.cycles.size(), 1u);
  expect_cycles(r.cycles[0], 0, 9, 12, 3, 9, 0);
  EXPECT_EQ(r.total_cycles, 13u);
  EXPECT_EQ(r.work.at("busy_cycles.walk"), 8u);
}

TEST(ScCyclesHand, TradRowStepsSumToLineSteps) {
  RasterConfig cfg;
  test::TestRng rng(77);
  const auto tris = test::random_grid_triangles(rng, 500, -50, 300, -50, 300, 2, 200);
  const SetupResult setup = setup_scene(tris, cfg);
  TradVertexQuantizer q(cfg);
  for (const TriangleSetup& t : setup.tris) {
    const TradVertices v = q.run(t);
    if (v.empty) continue;
    const TradWalkTiming w(v);
    for (int e = 0; e < 3; ++e) {
      uint64_t sum = 0;
      for (int64_t y = w.first_row(); y <= w.last_row(); ++y) sum += w.steps_on_row(e, y);
      EXPECT_EQ(sum, uint64_t(w.line(e).steps())) << "triangle " << t.index << " edge " << e;
    }
  }
}

// ---- against the cycle-by-cycle reading of docs/timing.md ----

// One reference triangle per set-up triangle: `Unit` (the unit's C++ model) runs it, and
// `describe` fills in the reference's inputs from its result and spans.
template <typename Unit, typename Describe>
std::vector<test::RefTriangle> reference_input(const SetupResult& setup, const RasterConfig& cfg,
                                               Describe describe) {
  std::vector<test::RefTriangle> out;
  Unit unit(cfg);
  for (const TriangleSetup& t : setup.tris) {
    test::RefTriangle r;
    r.tri = t.index;
    SpanList spans;
    describe(unit.run_triangle(t, spans), spans, r);
    out.push_back(r);
  }
  return out;
}

std::vector<test::RefTriangle> improved_reference_input(const SetupResult& setup,
                                                        const RasterConfig& cfg) {
  return reference_input<ImprovedUnit>(setup, cfg, [](const UnitTriangleResult& u,
                                                      const SpanList& spans,
                                                      test::RefTriangle& r) {
    r.retire_in_setup = u.iface.empty;
    if (!u.iface.empty) {
      uint64_t L = 0;
      for (const EdgeWork& e : u.work.edge)
        L = std::max(L, e.boundary_steps + e.divider_iterations);
      r.setup_cycles = 3 + L;
      for (const EdgeWork& e : u.work.edge) {
        r.divider_iterations += e.divider_iterations;
        r.boundary_steps += e.boundary_steps;
      }
      r.box_width = uint64_t(u.iface.Xmax) + 1;
      r.box_height = uint64_t(u.iface.Ymax) + 1;
      r.row_cost.assign(size_t(u.iface.Ymax + 1), 1);
      r.row_pixels.assign(size_t(u.iface.Ymax + 1), 0);
      for (const Span& s : spans) r.row_pixels[size_t(s.y - u.iface.y0)] = uint64_t(s.pixels());
    }
  });
}

std::vector<test::RefTriangle> trad_reference_input(const SetupResult& setup,
                                                    const RasterConfig& cfg) {
  return reference_input<TradSpanFiller>(setup, cfg, [](const TradTriangleResult& f,
                                                        const SpanList& spans,
                                                        test::RefTriangle& r) {
    r.retire_in_setup = f.verts.empty;
    if (!f.verts.empty) {
      r.setup_cycles = 3;
      const Vec2i* p = f.verts.p;
      r.box_width = uint64_t(std::max({p[0].x, p[1].x, p[2].x}) - std::min({p[0].x, p[1].x, p[2].x})) + 1;
      r.box_height = uint64_t(p[2].y - p[0].y) + 1;
      const TradWalkTiming w(f.verts);
      for (int64_t y = w.first_row(); y <= w.last_row(); ++y) {
        r.row_cost.push_back(w.row_cycles(y));
        r.row_pixels.push_back(0);
      }
      for (const Span& s : spans) r.row_pixels[size_t(s.y - w.first_row())] = uint64_t(s.pixels());
    }
  });
}

void compare_with_reference(bool trad, const std::vector<InputTriangle>& tris, RasterConfig cfg,
                            const std::string& what) {
  const SetupResult setup = setup_scene(tris, cfg);
  EngineResult r;
  (trad ? make_trad_sc_engine() : make_improved_sc_engine())->run(setup, cfg, r);
  const auto input = trad ? trad_reference_input(setup, cfg) : improved_reference_input(setup, cfg);
  const auto ref =
      test::reference_cycles(input, trad ? 1 : uint64_t(cfg.endpoints), uint64_t(cfg.fifo_depth),
                             SinkPattern::parse(cfg.sink_stall));
  ASSERT_EQ(r.cycles.size(), ref.size()) << what;
  int reported = 0;
  uint64_t total = 0;
  for (size_t i = 0; i < ref.size(); ++i) {
    const TriangleCycles& a = r.cycles[i];
    const TriangleCycles& b = ref[i];
    total = std::max(total, b.done_cycle + 1);
    // Every column, the stage breakdown too (docs/timing.md, "Outputs").
    if (test::same_cycles(a, b)) continue;
    ADD_FAILURE() << what << ": triangle " << a.tri << " (" << test::kCyclesColumns << ") model ("
                  << test::cycles_row(a) << ") reference (" << test::cycles_row(b) << ")";
    if (++reported == 5) return;
  }
  EXPECT_EQ(r.total_cycles, total) << what;
}

std::vector<InputTriangle> small_scene(uint64_t seed, int count) {
  test::TestRng rng(seed);
  auto a = test::random_grid_triangles(rng, count / 2, -20, 140, -20, 100, 2, 12);
  auto b = test::random_grid_triangles(rng, count / 2, -20, 140, -20, 100, 8, 60);
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

const char* kSinks[] = {"none", "periodic:3:2", "periodic:1:7", "random:7:50", "random:1:90"};

TEST(ScCyclesReference, ImprovedAllConfigurations) {
  const auto tris = small_scene(11, 600);
  for (int n : {1, 2, 4})
    for (int depth : {n, 2 * n, 8})
      for (const char* sink : kSinks)
        for (BoundaryMode mode : {BoundaryMode::Step, BoundaryMode::Divide}) {
          RasterConfig cfg;
          cfg.width = 128;
          cfg.height = 96;
          cfg.endpoints = n;
          cfg.fifo_depth = depth;
          cfg.sink_stall = sink;
          cfg.boundary = mode;
          cfg.divider = depth == 8 ? DividerMode::Fixed : DividerMode::Adaptive;
          compare_with_reference(false, tris, cfg,
                                 "N=" + std::to_string(n) + " depth=" + std::to_string(depth) +
                                     " sink=" + sink + " " + boundary_mode_name(mode));
        }
}

TEST(ScCyclesReference, TradAllConfigurations) {
  const auto tris = small_scene(12, 600);
  for (int depth : {1, 2, 8})
    for (const char* sink : kSinks) {
      RasterConfig cfg;
      cfg.width = 128;
      cfg.height = 96;
      cfg.fifo_depth = depth;
      cfg.sink_stall = sink;
      compare_with_reference(true, tris, cfg,
                             "trad depth=" + std::to_string(depth) + " sink=" + sink);
    }
}

}  // namespace
}  // namespace trirast
