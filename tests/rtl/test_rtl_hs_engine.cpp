// The Verilated RTL of the half-space tile unit (rtl/halfspace/trirast_halfspace.f, engine "halfspace-rtl"),
// in every Verilated configuration (StampSize / TileSize / walk order): its spans equal the
// golden's, span for span, and its cycles equal the SystemC model's (halfspace-sc,
// docs/timing.md "The half-space unit") for every triangle: accept, first span, done, spans,
// pixels and stall cycles, with the sink always ready and with stalling sinks and shallow FIFOs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/fixed_point.hpp"
#include "common/setup.hpp"
#include "golden/golden.hpp"
#include "common/cycle_columns.hpp"
#include "common/reference_raster.hpp"
#include "halfspace/halfspace_sc.hpp"
#include "scene/scene.hpp"
#include "support/run_command.hpp"
#include "halfspace/halfspace_unit.hpp"
#include "common/unit_widths.hpp"
#include "common/rtl_builds.hpp"
#include "halfspace/halfspace_rtl_engine.hpp"
#include "support/scene_helpers.hpp"

namespace trirast {
namespace {

using test::HalfspaceShape;
using test::tri;

// The stamp / tile / walk / corner form a Verilated build of the unit was made for.
HalfspaceShape shape_of(const rtl::RtlBuild& b) {
  return {b.stamp, b.tile, HalfspaceWalk(b.walk), b.corner_form};
}

// The shapes Verilated at the default widths (rtl_builds.hpp).
std::vector<HalfspaceShape> built_at_default_widths() {
  std::vector<HalfspaceShape> out;
  const RasterConfig d;
  for (const rtl::RtlBuild& b : rtl::halfspace_builds())
    if (b.subpixel_bits == d.subpixel_bits && b.coord_int_bits == d.coord_int_bits &&
        b.box_bits == d.box_bits)
      out.push_back(shape_of(b));
  return out;
}
const std::vector<HalfspaceShape> kBuilt = built_at_default_widths();

size_t expect_equal(const SetupResult& setup, const RasterConfig& cfg, const std::string& what) {
  EngineResult rtl, sc;
  make_halfspace_rtl_engine()->run(setup, cfg, rtl);
  make_halfspace_sc_engine()->run(setup, cfg, sc);
  const SpanList g = test::golden_spans(setup, cfg);
  sort_spans(rtl.spans);
  EXPECT_TRUE(rtl.spans == g) << what << ": " << rtl.spans.size() << " rtl spans, " << g.size()
                              << " golden";
  EXPECT_EQ(rtl.cycles.size(), sc.cycles.size()) << what;
  int reported = 0;
  for (size_t i = 0; i < std::min(rtl.cycles.size(), sc.cycles.size()); ++i) {
    const TriangleCycles& a = rtl.cycles[i];
    const TriangleCycles& b = sc.cycles[i];
    if (a.tri == b.tri && a.accept_cycle == b.accept_cycle &&
        a.first_span_cycle == b.first_span_cycle && a.done_cycle == b.done_cycle &&
        a.spans == b.spans && a.pixels == b.pixels && a.stall_cycles == b.stall_cycles)
      continue;
    ADD_FAILURE() << what << ": triangle " << a.tri << " rtl (" << a.accept_cycle << ","
                  << a.first_span_cycle << "," << a.done_cycle << "," << a.spans << "," << a.pixels
                  << "," << a.stall_cycles << ") sc (" << b.accept_cycle << ","
                  << b.first_span_cycle << "," << b.done_cycle << "," << b.spans << "," << b.pixels
                  << "," << b.stall_cycles << ")";
    if (++reported == 5) break;
  }
  EXPECT_EQ(rtl.total_cycles, sc.total_cycles) << what;
  // The statistics: every module's busy and stall cycles and the datapath's work counters are
  // the model's, counted from the RTL's own signals (halfspace_harness.hpp).
  int stats = 0;
  EXPECT_EQ(test::statistics_mismatch(sc.work, rtl.work, {}, stats), "") << what;
  EXPECT_GE(stats, 18) << what;  // six modules' busy, three stalls, six hs_*, spans, pixels, ...
  return rtl.cycles.size();
}

RasterConfig config(const HalfspaceShape& b) { return test::with_halfspace_shape({}, b); }

std::string name(const HalfspaceShape& b, const std::string& sink, int depth) {
  return test::halfspace_shape_name(b) + " sink " + sink + " depth " + std::to_string(depth);
}

TEST(RtlHalfspace, RandomTrianglesEveryConfigurationSinkAndDepth) {
  test::TestRng rng(1515);
  auto tris = test::random_grid_triangles(rng, 120, -20, 140, -20, 100, 2, 12);
  auto big = test::random_grid_triangles(rng, 120, -20, 140, -20, 100, 8, 60);
  tris.insert(tris.end(), big.begin(), big.end());
  ASSERT_GE(kBuilt.size(), 5u);
  ASSERT_TRUE(std::any_of(kBuilt.begin(), kBuilt.end(),
                          [](const HalfspaceShape& b) { return b.corner_form == 1; }));
  size_t n = 0;
  for (const HalfspaceShape& b : kBuilt)
    for (const char* sink : {"none", "periodic:1:3", "random:5:70"})
      for (int depth : {1, 2, 8}) {
        RasterConfig cfg = config(b);
        cfg.width = 128;
        cfg.height = 96;
        cfg.sink_stall = sink;
        cfg.fifo_depth = depth;
        n += expect_equal(setup_scene(tris, cfg), cfg, name(b, sink, depth));
      }
  EXPECT_GT(n, 5000u);
}

TEST(RtlHalfspace, HardCasesAndMeshes) {
  for (const HalfspaceShape& b : kBuilt)
    for (const char* spec : {"builtin:hard-all", "builtin:sphere"})
      for (const char* sink : {"none", "random:9:40"}) {
        if (std::string(spec) == "builtin:sphere" && std::string(sink) != "none") continue;
        RasterConfig cfg = config(b);
        cfg.sink_stall = sink;
        // Without tiles the unit tests every stamp of a box: hard-all's screen-sized triangles
        // take 113 M cycles at 1024x768 (41 s of Verilated RTL, ten times that under the
        // sanitizers). The tiled builds take the full viewport; this one a quarter of each side.
        if (b.tile == 0) {
          cfg.width = 320;
          cfg.height = 240;
        }
        const SetupResult setup = setup_scene(load_scene(spec, cfg, CameraOptions{}).tris, cfg);
        expect_equal(setup, cfg, std::string(spec) + " " + name(b, sink, cfg.fifo_depth));
      }
}

// A downstream that reacts to what it took (a pixel queue, --sink-stall queue:RATE:CAPACITY):
// the model and the RTL drive the same object, so their per-triangle cycles agree on three scenes
// with every built stamp size; the queue really held the unit back.
TEST(RtlHalfspace, ReactingDownstream) {
  for (const HalfspaceShape& b : kBuilt) {
    if (b.tile == 0) continue;  // untiled: every stamp of a box (HardCasesAndMeshes covers it)
    for (const char* spec : {"builtin:mixed", "builtin:lowpoly-near", TRIRAST_SOURCE_DIR "/tests/data/cube.obj"})
      for (const char* sink : {"queue:2:16", "queue:1:4"}) {
        RasterConfig cfg = config(b);
        cfg.sink_stall = sink;
        const SetupResult setup = setup_scene(load_scene(spec, cfg, CameraOptions{}).tris, cfg);
        expect_equal(setup, cfg, std::string(spec) + " " + name(b, sink, cfg.fifo_depth));
        RasterConfig ready_cfg = cfg;
        ready_cfg.sink_stall = "none";
        EngineResult sc, ready;
        make_halfspace_sc_engine()->run(setup, cfg, sc);
        make_halfspace_sc_engine()->run(setup, ready_cfg, ready);
        EXPECT_GT(sc.work["stall_cycles.span_sink"], 0u) << spec << " " << sink;
        EXPECT_GT(sc.total_cycles, ready.total_cycles) << spec << " " << sink;
      }
  }
}

// ---- the coordinate limits ----------------------------------------------------------------------

// Triangles with vertices on the corners and edges of the coordinate range [-L, L) and on the
// viewport's far edge (the box reaches the viewport's last pixel, its units past it), and random
// ones with every vertex at an extreme of the range or of the viewport.
std::vector<InputTriangle> limit_triangles(const RasterConfig& cfg, uint64_t seed) {
  const double L = double(cfg.coord_limit_px()), step = std::ldexp(1.0, -cfg.subpixel_bits);
  const double lo = -L, hi = L - step;
  // The viewport's far edge, inside the range (at S = 0, x.5 snaps to the even neighbour).
  const double w = std::min(double(cfg.width), hi), h = std::min(double(cfg.height), hi);
  std::vector<InputTriangle> t = {
      tri(lo, lo, hi, lo, lo, hi), tri(hi, hi, lo, hi, hi, lo), tri(lo, lo, hi, hi, lo, hi),
      tri(lo, lo, hi, hi, hi, lo), tri(lo, hi, hi, lo, hi, hi), tri(lo, hi, hi, lo, lo, lo),
      tri(lo, lo, std::min(w - 0.5, hi), lo, lo, std::min(h - 0.5, hi)),
      tri(lo, std::min(h - 0.5, hi), std::min(w - 0.5, hi), lo, hi, hi),
      tri(lo, hi, w - step, lo, w - step, hi), tri(hi, lo, lo, h - step, hi, h - step),
      tri(0.5, lo, 0.5, hi, w, h / 2), tri(lo, 0.5, hi, 0.5, w / 2, h),
  };
  const double xs[] = {lo, lo + step, hi, hi - step, 0, 0.5, std::min(w - 0.5, hi), w - step, w / 2};
  const double ys[] = {lo, lo + step, hi, hi - step, 0, 0.5, std::min(h - 0.5, hi), h - step, h / 2};
  test::TestRng rng(seed);
  for (int n = 0; n < 60; ++n) {
    InputTriangle r;
    for (int k = 0; k < 3; ++k) {
      r.x[k] = xs[rng.range(0, 8)];
      r.y[k] = ys[rng.range(0, 8)];
    }
    t.push_back(r);
  }
  return t;
}

// The largest |E| at a corner of any unit of the set-up scene (the values the tile walker tests).
int64_t largest_corner_value(const SetupResult& setup, const RasterConfig& cfg) {
  HalfspaceUnit unit(cfg);
  const int64_t U = HalfspaceParams::from(cfg).unit();
  int64_t most = 0;
  for (const TriangleSetup& t : setup.tris) {
    const HalfspaceSetupOut s = unit.set_up(t);
    if (s.empty) continue;
    for (int64_t j0 = 0; j0 <= s.Ymax; j0 += U)
      for (int64_t i0 = 0; i0 <= s.Xmax; i0 += U)
        for (const HalfspaceEdge& e : s.edge)
          for (int64_t di : {int64_t(0), U - 1})
            for (int64_t dj : {int64_t(0), U - 1}) {
              const int64_t v = e.E0 + (i0 + di) * e.a + (j0 + dj) * e.b;
              most = std::max(most, v < 0 ? -v : v);
            }
  }
  return most;
}

// Triangles at the coordinate limits, at every stamp and tile size and walk, in the widths where
// a unit's corners lie past the coordinate range (the narrow ones) and in wide ones: the
// datapath and the SystemC model give the golden's spans, and the corner values fit
// hs_edge_bits (the bound of model/common/unit_widths.cpp) and, where it exceeds 2p + 2, need the
// extra bits (so 2p + 2-bit corner values would fail this test).
TEST(HalfspaceLimits, CoordinateLimitsAtEveryStampTileAndWalk) {
  struct W {
    int S, coord, box, width, height;
  };
  // (the wide ones at small viewports: their corner values need 2p + 2 bits at any viewport)
  const W widths[] = {{8, 2, 1, 2, 2},     {4, 3, 4, 4, 4},      {8, 3, 2, 4, 4},
                      {0, 4, 4, 8, 8},     {1, 8, 7, 128, 100},  {4, 12, 11, 160, 120},
                      {8, 16, 14, 256, 192}, {0, 24, 14, 128, 128}, {8, 22, 14, 256, 192}};
  int needed_more = 0;
  for (const W& w : widths)
    for (const HalfspaceShape& shape : test::every_halfspace_shape()) {
      RasterConfig cfg = test::with_halfspace_shape(
          test::config_with_widths(w.S, w.coord, w.box, w.width, w.height), shape);
      cfg.validate();
      const std::string what = "S " + std::to_string(w.S) + " coord " +
                               std::to_string(w.coord) + " box " + std::to_string(w.box) +
                               " " + name(shape, "none", cfg.fifo_depth);
      const SetupResult setup = setup_scene(limit_triangles(cfg, 77), cfg);
      const SpanList g = test::golden_spans(setup, cfg);
      EngineResult dp, sc;
      ASSERT_NO_THROW(make_halfspace_datapath_engine()->run(setup, cfg, dp)) << what;
      ASSERT_NO_THROW(make_halfspace_sc_engine()->run(setup, cfg, sc)) << what;
      sort_spans(dp.spans);
      sort_spans(sc.spans);
      EXPECT_TRUE(dp.spans == g) << what << ": halfspace-datapath";
      EXPECT_TRUE(sc.spans == g) << what << ": halfspace-sc";
      const UnitWidths uw = unit_widths(cfg);
      const int64_t most = largest_corner_value(setup, cfg);
      EXPECT_TRUE(fits_signed(most, uw.hs_edge_value)) << what << ": " << most;
      if (!fits_signed(most, uw.edge_value)) ++needed_more;
      // The bound is 2p + 2 bits exactly when the units stay inside the largest viewport.
      EXPECT_EQ(uw.hs_edge_value > uw.edge_value,
                (shape.tile ? shape.tile : shape.stamp) > cfg.coord_limit_px())
          << what;
    }
  EXPECT_GT(needed_more, 10) << "no scene needs corner values wider than 2p + 2 bits";
}

// The same triangles through every Verilated build of halfspace-rtl (each at its widths and
// stamp / tile / walk, the narrow "hslimit" widths among them): spans equal the golden's and
// cycles the SystemC model's, with the sink always ready and stalling.
TEST(RtlHalfspace, CoordinateLimitsEveryBuild) {
  int narrow = 0;
  for (const rtl::RtlBuild& b : rtl::halfspace_builds())
    for (const char* sink : {"none", "random:3:50"}) {
      RasterConfig cfg = test::with_halfspace_shape({}, shape_of(b));
      cfg.subpixel_bits = b.subpixel_bits;
      cfg.coord_int_bits = b.coord_int_bits;
      cfg.box_bits = b.box_bits;
      cfg.width = cfg.height = int(std::min<int64_t>(cfg.coord_limit_px(), 128));
      cfg.sink_stall = sink;
      cfg.fifo_depth = 2;
      cfg.validate();
      const SetupResult setup = setup_scene(limit_triangles(cfg, 91), cfg);
      const UnitWidths uw = unit_widths(cfg);
      narrow += !fits_signed(largest_corner_value(setup, cfg), uw.edge_value);
      expect_equal(setup, cfg,
                   std::string(b.prefix) + " " +
                       name(shape_of(b), sink, cfg.fifo_depth));
    }
  EXPECT_GT(narrow, 0) << "no build sees corner values wider than 2p + 2 bits";
}

// The trace's save file names the half-space unit's own states: its setup stage has no StLanes,
// its walk stage is the tile walker (WIdle .. WDrain), in the register and the unit's nets.
TEST(RtlHalfspace, TraceShowsTheUnitsStateNames) {
  RasterConfig cfg;
  const std::string dir = testing::TempDir();
  cfg.trace_path = dir + "/hs_states.fst";
  const SetupResult setup = setup_scene({tri(1, 1, 90, 2, 3, 80), tri(10, 40, 60, 5, 50, 44)}, cfg);
  EngineResult r;
  make_halfspace_rtl_engine()->run(setup, cfg, r);
  const std::string walk = test::slurp(dir + "/hs_states.walk_state.filter");
  const std::string setup_names = test::slurp(dir + "/hs_states.setup_state.filter");
  EXPECT_EQ(walk, "0 WIdle\n1 WUnit\n2 WStamp\n3 WWait\n4 WDrain\n");
  EXPECT_EQ(setup_names, "0 StIdle\n1 StBox\n2 StEdge\n4 StHold\n");
  const std::string gtkw = test::slurp(dir + "/hs_states.gtkw");
  for (const char* sig : {"u_dut.u_walker.state_q[2:0]", "u_dut.walk_state[2:0]",
                          "u_dut.u_setup.state_q[2:0]", "u_dut.setup_state[2:0]"}) {
    const size_t at = gtkw.find(std::string("_sim.") + sig + "\n");
    ASSERT_NE(at, std::string::npos) << sig;
    const size_t filter = gtkw.rfind(".filter\n", at);
    ASSERT_NE(filter, std::string::npos) << sig;
    // The filter line is the one two lines above the signal ("^N file.filter", "@2024", signal).
    EXPECT_EQ(std::count(gtkw.begin() + long(filter), gtkw.begin() + long(at), '\n'), 2) << sig;
    const std::string which = std::string(sig).find("walk") != std::string::npos
                                  ? "walk_state"
                                  : "setup_state";
    EXPECT_EQ(gtkw.compare(filter - which.size(), which.size(), which), 0) << sig;
  }
}

TEST(RtlHalfspace, UnbuiltConfigurationIsNamed) {
  RasterConfig cfg;
  cfg.halfspace.stamp = 4;
  cfg.halfspace.tile = 8;
  const SetupResult setup = setup_scene({}, cfg);
  EngineResult r;
  try {
    make_halfspace_rtl_engine()->run(setup, cfg, r);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--stamp 4 --tile 8"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace trirast
