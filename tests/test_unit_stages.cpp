// Stage-by-stage tests of the improved-Bresenham unit (docs/unit.md): the adder divider against
// exact integer division, the edge normalizer's mirror/restore, the edge walker against the
// closed-form per-row bound floor((T + j*b) / D), and the width checks at their limits.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "common/fixed_point.hpp"
#include "common/setup.hpp"
#include "golden/golden.hpp"
#include "common/reference_raster.hpp"
#include "improved/improved_adder_divider.hpp"
#include "improved/improved_edge_normalizer.hpp"
#include "improved/improved_edge_walker.hpp"
#include "improved/improved_unit.hpp"
#include "common/box_stage.hpp"
#include "common/unit_widths.hpp"

namespace trirast {
namespace {

// The fixed-seed generator of the reference checks (splitmix64, identical on every platform).
using test::TestRng;

// floor(n / d), d > 0, in 128-bit arithmetic: the closed form the walker must match.
int64_t floor_div128(__int128 n, __int128 d) {
  __int128 q = n / d;
  if (n % d != 0 && n < 0) --q;
  return int64_t(q);
}

// ---------------------------------------------------------------- adder_divider

TEST(ImprovedAdderDivider, ExhaustiveSmallWidths) {
  // Every n < 2^10 and d < 2^6 for small quotient widths: exact q and r, exact saturation.
  uint64_t checked = 0;
  for (int Q : {1, 3, 4, 6}) {
    ImprovedAdderDivider div(Q, 10, 6);
    for (int64_t n = 0; n < 1024; ++n) {
      for (int64_t d = 1; d < 64; ++d) {
        const DivideResult r = div.divide(n, d, 0, "n");
        const bool saturates = n >= d * (int64_t(1) << Q);
        ASSERT_EQ(r.saturated, saturates) << "Q=" << Q << " n=" << n << " d=" << d;
        ASSERT_EQ(r.iterations, Q);
        if (!saturates) {
          ASSERT_EQ(r.quotient, n / d) << "Q=" << Q << " n=" << n << " d=" << d;
          ASSERT_EQ(r.remainder, n % d) << "Q=" << Q << " n=" << n << " d=" << d;
        }
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 4u * 1024u * 63u);
}

TEST(ImprovedAdderDivider, RandomFullWidth) {
  // The unit's divider (default config: Q = 15, numerator 2p+2 = 50 bits, divisor p+F = 32 bits).
  RasterConfig cfg;
  const UnitWidths w = unit_widths(cfg);
  ASSERT_EQ(w.quotient, 15);
  ASSERT_EQ(w.numerator, 50);
  ImprovedAdderDivider div(cfg);
  EXPECT_EQ(div.iterations_per_division(), 15);
  TestRng rng{12345};
  int saturated = 0, exact = 0;
  for (int it = 0; it < 200000; ++it) {
    const int64_t d = 1 + rng.bits(w.remainder - 1);
    int64_t n;
    switch (it % 4) {
      case 0:
        n = rng.bits(w.numerator);
        break;  // any numerator
      case 1:
        n = d * rng.range(0, (1 << 15) - 1) + rng.range(0, d - 1);
        break;  // q fits
      case 2:
        n = d * (int64_t(1) << 15) - rng.range(0, 1);
        break;  // at the saturation edge
      default:
        n = rng.bits(w.numerator) >> rng.range(0, 40);
        break;  // short numerators
    }
    if (n >= (int64_t(1) << w.numerator)) n >>= 1;
    const DivideResult r = div.divide(n, d, 0, "n");
    const bool saturates = (__int128)n >= (__int128)d << 15;
    ASSERT_EQ(r.saturated, saturates) << "n=" << n << " d=" << d;
    ASSERT_EQ(r.iterations, 15);
    if (saturates) {
      ++saturated;
      continue;
    }
    ++exact;
    ASSERT_EQ(r.quotient, n / d) << "n=" << n << " d=" << d;
    ASSERT_EQ(r.remainder, n % d) << "n=" << n << " d=" << d;
  }
  // Both outcomes were exercised.
  EXPECT_GT(saturated, 10000);
  EXPECT_GT(exact, 50000);
}

TEST(ImprovedAdderDivider, PortWidths) {
  RasterConfig cfg;
  const UnitWidths w = unit_widths(cfg);
  ImprovedAdderDivider div(cfg);
  const int64_t n_max = (int64_t(1) << w.numerator) - 1;
  const int64_t d_max = (int64_t(1) << w.remainder) - 1;
  // At the limit: accepted; 2^50 / 2^32 needs 18 quotient bits, so it saturates.
  EXPECT_TRUE(div.divide(n_max, d_max, 7, "n").saturated);
  // The largest quotient that fits: exact.
  const int64_t n_top = d_max * (int64_t(1) << 15) - 1;
  const DivideResult r = div.divide(n_top, d_max, 7, "n");
  EXPECT_FALSE(r.saturated);
  EXPECT_EQ(r.quotient, (1 << 15) - 1);
  EXPECT_EQ(r.remainder, d_max - 1);
  // One past: rejected, naming the triangle.
  try {
    div.divide(n_max + 1, 3, 7, "entry x N");
    FAIL() << "numerator one past the width was accepted";
  } catch (const WidthError& e) {
    EXPECT_NE(std::string(e.what()).find("triangle 7: entry x N"), std::string::npos) << e.what();
  }
  EXPECT_THROW(div.divide(5, d_max + 1, 7, "d"), WidthError);
  EXPECT_THROW(div.divide(-1, 3, 7, "n"), WidthError);
}

// ---------------------------------------------------------------- edge_normalizer

// A random box-relative edge whose values fit the default widths.
BoxStageEdge random_edge(TestRng& rng, int64_t Xmax, int step_bits) {
  BoxStageEdge e;
  const int64_t u = 256;
  // Steps of random bit length; a quarter of them small, so exact carries are common.
  const int bits = rng.next() % 4 == 0 ? 4 : step_bits - 8;
  e.a = rng.bits(bits) * u * (rng.next() & 1 ? 1 : -1);
  e.b = rng.bits(step_bits - 8) * u * (rng.next() & 1 ? 1 : -1);
  if (rng.next() % 4 == 0) e.b = rng.bits(4) * u * (rng.next() & 1 ? 1 : -1);
  if (rng.next() % 16 == 0) e.a = 0;
  if (rng.next() % 16 == 0) e.b = 0;
  if (e.a == 0 && e.b == 0) e.b = u;
  // Make the edge cross the box's neighbourhood most of the time: pass near (it, jt).
  const int64_t it = rng.range(-Xmax - 2, 2 * Xmax + 2);
  const int64_t jt = rng.range(-(1 << 14), 1 << 15);
  e.E_L = -it * e.a - jt * e.b + rng.range(-3 * u, 3 * u);
  // Often on the pixel lattice: exact divisions (remainder 0, carry exactly at D) happen.
  if (rng.next() % 2 == 0) e.E_L = e.E_L / u * u;
  if (rng.next() % 8 == 0) e.E_L = rng.range(-(int64_t(1) << 48), int64_t(1) << 48);
  e.E_R = e.E_L + Xmax * e.a;
  return e;
}

TEST(ImprovedEdgeNormalizer, MirrorRestoreRoundTrip) {
  RasterConfig cfg;
  ImprovedEdgeNormalizer norm(cfg);
  TestRng rng{777};
  int mirrored = 0, plain = 0;
  for (int it = 0; it < 100000; ++it) {
    const int64_t Xmax = rng.range(0, (1 << 14) - 1);
    const BoxStageEdge e = random_edge(rng, Xmax, 32);
    if (e.a == 0) continue;
    const NormalizedEdge n = norm.run(e, Xmax, 0);
    // The normalized form: D > 0, s = |b|, T1 at the far column, signs into flags.
    ASSERT_GT(n.D, 0);
    ASSERT_EQ(n.s, e.b < 0 ? -e.b : e.b);
    ASSERT_EQ(n.T1, n.T - Xmax * n.D);
    ASSERT_EQ(n.mirror, e.a > 0);
    ASSERT_EQ(n.dir_down, e.b >= 0);
    // A row, the normalized bound X' there, and the bound restored to real columns.
    const int64_t j = rng.range(0, (1 << 14) - 1);
    const int64_t Xp = floor_div128((__int128)n.T + (__int128)j * e.b, n.D);
    const int64_t x = ImprovedEdgeNormalizer::restore(n, Xp, Xmax);
    // The original edge, evaluated at the restored bound and its neighbour, confirms it.
    auto E = [&](int64_t i) { return (__int128)e.E_L + (__int128)i * e.a + (__int128)j * e.b; };
    if (n.mirror) {
      ++mirrored;  // x is the first covered column
      ASSERT_TRUE(E(x) >= 0 && E(x - 1) < 0) << "begin " << x << " a=" << e.a << " j=" << j;
    } else {
      ++plain;  // x is one past the last covered column
      ASSERT_TRUE(E(x - 1) >= 0 && E(x) < 0) << "end " << x << " a=" << e.a << " j=" << j;
    }
  }
  EXPECT_GT(mirrored, 30000);
  EXPECT_GT(plain, 30000);
}

// ---------------------------------------------------------------- edge_walker

// Expected state of a normalized edge on row j, straight from the closed form.
WalkerRow closed_form(const NormalizedEdge& n, const BoxStageEdge& e, int64_t Xmax, int64_t j) {
  const __int128 f0 = (__int128)n.T + (__int128)j * e.b;  // f at column i' = 0
  if (n.horizontal) return WalkerRow{f0 >= 0 ? EdgeRowState::Clear : EdgeRowState::Out, 0};
  const int64_t X = floor_div128(f0, n.D);
  if (X < 0) return WalkerRow{EdgeRowState::Out, 0};
  if (X >= Xmax) return WalkerRow{EdgeRowState::Clear, 0};
  return WalkerRow{EdgeRowState::Bound, X};
}

const char* state_name(EdgeRowState s) {
  return s == EdgeRowState::Out ? "out" : s == EdgeRowState::Bound ? "bound" : "clear";
}

void walk_random_edges(BoundaryMode mode, DividerMode divider, uint64_t seed) {
  RasterConfig cfg;
  cfg.boundary = mode;
  cfg.divider = divider;
  const UnitWidths w = unit_widths(cfg);
  ImprovedEdgeNormalizer norm(cfg);
  ImprovedAdderDivider div(cfg);
  ImprovedEdgeWalker walker(cfg, div);
  TestRng rng{seed};
  uint64_t rows = 0, bound_rows = 0, steps_total = 0, dir_up = 0;
  for (int it = 0; it < 6000; ++it) {
    // Mostly small boxes, some at the full 2^box_bits.
    const int64_t lim = it % 10 == 0 ? (1 << 14) - 1 : 300;
    const int64_t Xmax = rng.range(0, lim), Ymax = rng.range(0, lim);
    const BoxStageEdge e = random_edge(rng, Xmax, it % 3 == 0 ? 16 : 32);
    if (!fits_signed(e.E_L, w.edge_value) || !fits_signed(e.E_R, w.edge_value)) continue;
    const NormalizedEdge n = norm.run(e, Xmax, uint32_t(it));
    if (!n.dir_down) ++dir_up;
    walker.start(n, Xmax, Ymax, uint32_t(it));
    // Row by row against the closed form; count the Bresenham steps and the entry row.
    uint64_t expect_stepped = 0;
    int64_t entry = Ymax + 1;
    const EdgeRowState before = n.dir_down ? EdgeRowState::Out : EdgeRowState::Clear;
    for (int64_t j = 0; j <= Ymax; ++j) {
      if (j > 0) walker.advance();
      const WalkerRow want = closed_form(n, e, Xmax, j);
      const WalkerRow got = walker.row();
      ASSERT_EQ(int(got.state), int(want.state))
          << "edge " << it << " row " << j << ": got " << state_name(got.state) << ", want "
          << state_name(want.state) << " (T=" << n.T << " D=" << n.D << " b=" << e.b
          << " Xmax=" << Xmax << ")";
      if (want.state == EdgeRowState::Bound) {
        ASSERT_EQ(got.X, want.X) << "edge " << it << " row " << j;
        ++bound_rows;
        if (j < Ymax) ++expect_stepped;  // the walker steps from this row to the next
      }
      if (entry > Ymax && want.state != before) entry = j;
      ++rows;
    }
    // The entry row (first row whose state differs from the pre-entry one) and the counters.
    const EdgeWork& wk = walker.work();
    ASSERT_EQ(walker.state().enters, entry <= Ymax) << "edge " << it;
    if (entry <= Ymax) {
      ASSERT_EQ(walker.state().j_entry, entry) << "edge " << it;
    }
    if (mode == BoundaryMode::Step) {
      EXPECT_EQ(int64_t(wk.boundary_steps), entry) << "edge " << it;  // capped at Ymax + 1
    } else {
      EXPECT_EQ(wk.boundary_steps, 0u);
    }
    steps_total += wk.boundary_steps;
    EXPECT_EQ(wk.rows_stepped, expect_stepped) << "edge " << it;
    if (divider == DividerMode::Fixed) {
      EXPECT_EQ(wk.divider_iterations, wk.divisions * uint64_t(w.quotient));
    } else {
      // Each division runs bits(extent) + 1 iterations: the box's width (slope, entry x) or
      // height (entry row, divide mode only).
      const uint64_t bx = uint64_t(unsigned_bits(uint64_t(Xmax)) + 1);
      const uint64_t by = uint64_t(unsigned_bits(uint64_t(Ymax)) + 1);
      if (mode == BoundaryMode::Step) {
        EXPECT_EQ(wk.divider_iterations, wk.divisions * bx);
      } else {
        EXPECT_GE(wk.divider_iterations, wk.divisions * std::min(bx, by));
        EXPECT_LE(wk.divider_iterations, wk.divisions * std::max(bx, by));
      }
    }
  }
  // The random edges exercised bound rows in both directions.
  EXPECT_GT(bound_rows, rows / 20);
  EXPECT_GT(dir_up, 1000u);
  if (mode == BoundaryMode::Step) {
    EXPECT_GT(steps_total, 0u);
  }
}

TEST(ImprovedEdgeWalker, ClosedFormStepMode) {
  walk_random_edges(BoundaryMode::Step, DividerMode::Adaptive, 99);
  walk_random_edges(BoundaryMode::Step, DividerMode::Fixed, 98);
}
TEST(ImprovedEdgeWalker, ClosedFormDivideMode) {
  walk_random_edges(BoundaryMode::Divide, DividerMode::Adaptive, 99);
  walk_random_edges(BoundaryMode::Divide, DividerMode::Fixed, 98);
}

TEST(ImprovedEdgeWalker, BothModesFindTheSameEntry) {
  // The step traversal and the division agree on the entry row, edge by edge.
  RasterConfig step_cfg, div_cfg;
  div_cfg.boundary = BoundaryMode::Divide;
  ImprovedEdgeNormalizer norm(step_cfg);
  ImprovedAdderDivider div(step_cfg);
  ImprovedEdgeWalker ws(step_cfg, div), wd(div_cfg, div);
  TestRng rng{4242};
  int entered = 0;
  for (int it = 0; it < 20000; ++it) {
    const int64_t Xmax = rng.range(0, 500), Ymax = rng.range(0, 2000);
    const BoxStageEdge e = random_edge(rng, Xmax, 24);
    const NormalizedEdge n = norm.run(e, Xmax, 0);
    ws.start(n, Xmax, Ymax, 0);
    wd.start(n, Xmax, Ymax, 0);
    ASSERT_EQ(ws.state().enters, wd.state().enters) << it;
    if (!ws.state().enters) continue;
    ++entered;
    ASSERT_EQ(ws.state().j_entry, wd.state().j_entry) << it;
    ASSERT_EQ(int(ws.state().entry_state), int(wd.state().entry_state)) << it;
    ASSERT_EQ(ws.state().entry_X, wd.state().entry_X) << it;
    ASSERT_EQ(ws.state().entry_e, wd.state().entry_e) << it;
  }
  EXPECT_GT(entered, 5000);
}

TEST(ImprovedEdgeWalker, SaturatedSlopeLeavesInOneStep) {
  // s >= D * 2^Q: the edge is bound on its entry row only, then clear (dir +) or out (dir -).
  for (BoundaryMode mode : {BoundaryMode::Step, BoundaryMode::Divide}) {
    RasterConfig cfg;
    cfg.boundary = mode;
    ImprovedEdgeNormalizer norm(cfg);
    ImprovedAdderDivider div(cfg);
    ImprovedEdgeWalker walker(cfg, div);
    const int64_t u = 256, Xmax = 100, Ymax = 10, s = u * (int64_t(1) << 15) * 3;
    for (bool mirror : {false, true}) {
      for (bool down : {true, false}) {
        // Enter at row 3 with X' = 50: f(0, 3) = T + 3*b = 50*D + 7.
        const int64_t D = u, b = down ? s : -s;
        const int64_t T = 50 * D + 7 - 3 * b;
        BoxStageEdge e;
        e.a = mirror ? D : -D;
        e.b = b;
        e.E_L = mirror ? T - Xmax * e.a : T;
        e.E_R = e.E_L + Xmax * e.a;
        const NormalizedEdge n = norm.run(e, Xmax, 0);
        ASSERT_EQ(n.T, T);
        walker.start(n, Xmax, Ymax, 0);
        EXPECT_EQ(walker.state().j_entry, 3);
        EXPECT_TRUE(walker.state().slope_saturated);
        for (int64_t j = 0; j <= Ymax; ++j) {
          if (j > 0) walker.advance();
          const WalkerRow want = closed_form(n, e, Xmax, j);
          ASSERT_EQ(int(walker.row().state), int(want.state)) << "row " << j;
          if (want.state == EdgeRowState::Bound) {
            ASSERT_EQ(walker.row().X, want.X) << "row " << j;
          }
          ASSERT_EQ(want.state == EdgeRowState::Bound, j == 3) << "row " << j;
        }
        EXPECT_EQ(walker.work().rows_stepped, 1u);
      }
    }
  }
}

// ---------------------------------------------------------------- width checks

// The unit's spans for one triangle, compared with the golden rasterizer's.
void expect_unit_matches_golden(const InputTriangle& in, const RasterConfig& cfg) {
  const SetupResult s = setup_scene({in}, cfg);
  ASSERT_EQ(s.tris.size(), 1u);
  SpanList golden, unit_spans;
  golden_triangle(s.tris[0], cfg, golden);
  ImprovedUnit unit(cfg);
  unit.run_triangle(s.tris[0], unit_spans);
  EXPECT_EQ(golden, unit_spans);
  EXPECT_FALSE(golden.empty());
}

void expect_width_error(const InputTriangle& in, const RasterConfig& cfg, const char* name) {
  const SetupResult s = setup_scene({in}, cfg);
  ASSERT_EQ(s.tris.size(), 1u);
  ImprovedUnit unit(cfg);
  SpanList spans;
  try {
    unit.run_triangle(s.tris[0], spans);
    FAIL() << "expected a WidthError naming " << name;
  } catch (const WidthError& e) {
    EXPECT_NE(std::string(e.what()).find(std::string("triangle 0: ") + name), std::string::npos)
        << e.what();
  }
}

TEST(UnitWidths, BoxExactlyAtTheLimit) {
  RasterConfig cfg;
  cfg.box_bits = 6;  // boxes up to 64 pixels
  // Centres 10.5 .. 73.5: 64 pixels wide (accepted), 65 (rejected); likewise tall.
  expect_unit_matches_golden(InputTriangle{{10.5, 73.5, 10.5}, {10.5, 10.5, 20.5}}, cfg);
  expect_width_error(InputTriangle{{10.5, 74.5, 10.5}, {10.5, 10.5, 20.5}}, cfg, "Xmax");
  expect_unit_matches_golden(InputTriangle{{10.5, 20.5, 10.5}, {10.5, 10.5, 73.5}}, cfg);
  expect_width_error(InputTriangle{{10.5, 20.5, 10.5}, {10.5, 10.5, 74.5}}, cfg, "Ymax");
}

TEST(UnitWidths, DefaultBoxHoldsTheLargestViewport) {
  // box_bits = 14 and a 16384-pixel viewport: the biggest box fits exactly.
  RasterConfig cfg;
  cfg.width = cfg.height = 16384;
  const SetupResult s = setup_scene({InputTriangle{{-100, 20000, -100}, {-100, -100, 20000}}}, cfg);
  ASSERT_EQ(s.tris.size(), 1u);
  ASSERT_EQ(s.tris[0].box.width(), 16384);
  ImprovedUnit unit(cfg);
  SpanList spans;
  const UnitTriangleResult r = unit.run_triangle(s.tris[0], spans);
  EXPECT_EQ(r.iface.Xmax, 16383);
  EXPECT_EQ(spans.size(), 16384u);
}

TEST(UnitWidths, VertexCoordinates) {
  RasterConfig cfg;
  const UnitWidths w = unit_widths(cfg);
  // The most negative and most positive representable coordinates pass.
  const double lo = -32768.0, hi = 32768.0 - 1.0 / 256;
  expect_unit_matches_golden(InputTriangle{{lo, hi, hi}, {lo, lo, hi}}, cfg);
  // One past the signed p-bit range (a setup the scene reader would refuse) is rejected.
  TriangleSetup t = setup_scene({InputTriangle{{lo, hi, lo}, {lo, lo, hi}}}, cfg).tris[0];
  t.v[1].x = int64_t(1) << (w.vertex - 1);
  BoxStage iface(cfg);
  try {
    iface.run(t);
    FAIL() << "a coordinate one past the range was accepted";
  } catch (const WidthError& e) {
    EXPECT_NE(std::string(e.what()).find("triangle 0: vertex x = 8388608 does not fit 24-bit"),
              std::string::npos)
        << e.what();
  }
}

TEST(UnitWidths, WidthTable) {
  // The doc's table for the default 16.8 configuration.
  RasterConfig cfg;
  const UnitWidths w = unit_widths(cfg);
  EXPECT_EQ(w.vertex, 24);
  EXPECT_EQ(w.edge_coef, 25);
  EXPECT_EQ(w.step, 32);
  EXPECT_EQ(w.edge_value, 50);
  EXPECT_EQ(w.box, 14);
  EXPECT_EQ(w.quotient, 15);
  EXPECT_EQ(w.remainder, 32);
  EXPECT_EQ(w.walker_x, 17);
  // S = 0 computes with one fractional bit.
  cfg.subpixel_bits = 0;
  EXPECT_EQ(unit_widths(cfg).vertex, 17);
  // A configuration whose edge values exceed the 64-bit model is refused, not wrapped.
  cfg.subpixel_bits = 8;
  cfg.coord_int_bits = 24;
  EXPECT_THROW(ImprovedUnit{cfg}, WidthError);
  // The half-space corner-value width of that configuration is computed, not wrapped (it exceeds
  // 63 bits, so the half-space unit refuses it too).
  EXPECT_GT(unit_widths(cfg).hs_edge_value, 63);
  EXPECT_LT(unit_widths(cfg).hs_edge_value, 80);
}

}  // namespace
}  // namespace trirast
