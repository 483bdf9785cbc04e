// The half-space unit's SystemC model (halfspace-sc, docs/timing.md "The half-space unit"):
// hand-derived cycles for small triangles, the golden's spans under every sink pattern and FIFO
// depth at every stamp / tile / walk, and the contract's invariants (a FIFO of depth 1 with a
// stalling sink costs stall cycles; pops never precede pushes).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/setup.hpp"
#include "golden/golden.hpp"
#include "common/reference_raster.hpp"
#include "halfspace/halfspace_sc.hpp"
#include "support/scene_helpers.hpp"

namespace trirast {
namespace {

using test::tri;

EngineResult run_hs(const std::vector<InputTriangle>& tris, const RasterConfig& cfg) {
  const SetupResult setup = setup_scene(tris, cfg);
  EngineResult r;
  make_halfspace_sc_engine()->run(setup, cfg, r);
  return r;
}

// Box x, y = 1..8 (Xmax = Ymax = 7); row j covers box columns 0..7-j: 8 spans, 36 pixels.
InputTriangle right_triangle() { return tri(1, 1, 9.25, 1, 1, 9.25); }

// Each hand test in both corner forms (--hs-corner-form): dsp's StEdge is one cycle, StHold from
// a + 3. radix16's digit-serial corner unit: for this triangle the operands cx0 - vx, cy0 - vy of
// v0 and v1 (1/256 pixel) are 128 and 384 - 2368 = -1984, 12 signed bits, so 3 digits a run
// (docs/timing.md, "Setup stage"): StHold from a + 4 + 3 (one run, a box one unit wide), or from
// a + 5 + 3 + 3 (two runs); every later cycle moves by the difference, `late`.
TEST(ScHalfspaceHand, OneTileSixteenStamps) {
  // Stamp 2, tile 8: one band, one tile; its corner (7, 7) is outside the hypotenuse, the others
  // inside: partial, 1 test + 16 stamps = 17 walker cycles. dsp: h = 3, walker 4..20, hand-off at
  // the end of 20, spans pushed by the emitter in 21..28, through the span port's push register
  // into the FIFO at the end of 22..29, popped in 23..30. radix16: one run, 4 cycles later.
  for (int form : {0, 1}) {
    RasterConfig cfg;
    cfg.halfspace.stamp = 2;
    cfg.halfspace.tile = 8;
    cfg.halfspace.corner_form = form;
    const uint64_t late = form ? 4 : 0;
    const EngineResult r = run_hs({right_triangle()}, cfg);
    ASSERT_EQ(r.cycles.size(), 1u);
    const TriangleCycles& c = r.cycles[0];
    EXPECT_EQ(c.accept_cycle, 0u);
    EXPECT_EQ(c.setup_done_cycle, 3u + late) << "form " << form;
    EXPECT_EQ(c.first_span_cycle, 23u + late) << "form " << form;
    EXPECT_EQ(c.done_cycle, 30u + late) << "form " << form;
    EXPECT_EQ(c.spans, 8u);
    EXPECT_EQ(c.pixels, 36u);
    EXPECT_EQ(c.stall_cycles, 0u);
    EXPECT_EQ(r.total_cycles, 31u + late) << "form " << form;
  }
}

TEST(ScHalfspaceHand, StampsWithoutTilesZigzagAndForward) {
  // Stamp 4, no tiles, zig-zag: band 0 tests stamps 0, 1 in 4, 5 (hand-off end of 5, rows 0..3
  // pushed in 6..9, in the FIFO at the end of 7..10, popped in 8..11); band 1 runs right to left:
  // stamp (4, 4) is rejected (all four corners outside the hypotenuse), stamp (0, 4) is not:
  // cycles 6, 7; the emitter is busy until 9, so band 1 goes to it at the end of 9 and rows 4..7
  // are pushed in 10..13, in the FIFO at the end of 11..14, popped in 12..15.
  // radix16: two units a band, two runs (E_end at x0 + 4, 3 digits as well), 8 cycles later.
  // Forward: band 1 tests (0, 4) and (4, 4) in 6, 7, the same cycles; radix16 has no run 2 (no
  // band starts at E_end), so it is 4 cycles later, not 8.
  for (HalfspaceWalk walk : {HalfspaceWalk::Zigzag, HalfspaceWalk::Forward}) {
    for (int form : {0, 1}) {
      RasterConfig cfg;
      cfg.halfspace.stamp = 4;
      cfg.halfspace.tile = 0;
      cfg.halfspace.walk = walk;
      cfg.halfspace.corner_form = form;
      const uint64_t late = form ? (walk == HalfspaceWalk::Zigzag ? 8 : 4) : 0;
      const std::string what = std::string(halfspace_walk_name(walk)) + " form " + std::to_string(form);
      const EngineResult r = run_hs({right_triangle()}, cfg);
      ASSERT_EQ(r.cycles.size(), 1u);
      EXPECT_EQ(r.cycles[0].setup_done_cycle, 3u + late) << what;
      EXPECT_EQ(r.cycles[0].first_span_cycle, 8u + late) << what;
      EXPECT_EQ(r.cycles[0].done_cycle, 15u + late) << what;
      EXPECT_EQ(r.work.at("stall_cycles.tile_walker"), 2u) << what;
      EXPECT_EQ(r.total_cycles, 16u + late) << what;
    }
  }
}

TEST(ScHalfspaceHand, EmptyBoxRetiresInSetupAndNextIsAcceptedTwoLater) {
  RasterConfig cfg;
  // Between pixel centres: the box is empty.
  const EngineResult r = run_hs({tri(1.6, 1.6, 1.9, 1.6, 1.6, 1.9), right_triangle()}, cfg);
  ASSERT_EQ(r.cycles.size(), 2u);
  EXPECT_EQ(r.cycles[0].done_cycle, 1u);
  EXPECT_EQ(r.cycles[0].spans, 0u);
  EXPECT_EQ(r.cycles[1].accept_cycle, 2u);
}

TEST(ScHalfspace, GoldenSpansAndSaneCyclesEverywhere) {
  test::TestRng rng(15);
  auto tris = test::random_grid_triangles(rng, 150, -20, 140, -20, 100, 2, 12);
  auto big = test::random_grid_triangles(rng, 150, -20, 140, -20, 100, 8, 60);
  tris.insert(tris.end(), big.begin(), big.end());
  for (const test::HalfspaceShape& shape : test::every_halfspace_shape())
    for (const char* sink : {"none", "periodic:1:3", "random:3:60"})
      for (int depth : {1, 4}) {
        RasterConfig cfg = test::with_halfspace_shape(test::config_at(8, 128, 96), shape);
        cfg.sink_stall = sink;
        cfg.fifo_depth = depth;
        const std::string what = test::halfspace_shape_name(shape) + " " + sink + " depth " +
                                 std::to_string(depth);
        const SetupResult setup = setup_scene(tris, cfg);
        EngineResult r;
        make_halfspace_sc_engine()->run(setup, cfg, r);
        const SpanList g = test::golden_spans(setup, cfg);
        sort_spans(r.spans);
        EXPECT_TRUE(r.spans == g) << what;
        uint64_t prev_accept = 0;
        for (const TriangleCycles& c : r.cycles) {
          EXPECT_LE(c.accept_cycle, c.first_span_cycle) << what;
          EXPECT_LE(c.first_span_cycle, c.done_cycle) << what;
          if (&c != &r.cycles[0]) {
            EXPECT_GT(c.accept_cycle, prev_accept) << what;
          }
          prev_accept = c.accept_cycle;
        }
        if (std::string(sink) != "none" && depth == 1) {
          EXPECT_GT(r.work.at("stall_cycles.walk"), 0u) << what;
        }
      }
}

}  // namespace
}  // namespace trirast
