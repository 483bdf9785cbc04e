// The Verilated RTL of the second-generation improved unit (rtl/improved2/trirast_improved2.f, engine
// "improved2-rtl"): its spans equal the golden's, pixel for pixel, and every column of every
// triangle's cycles (accept, first span, done, stalls, the stage breakdown, the lanes' work, the
// box) and the run's statistics equal its SystemC model improved2-sc's (docs/improved2.md,
// "Verification"), in both corner forms, with the sink always ready and stalled, at several FIFO
// depths, at N = 1, 2 and 4 rows per walk cycle, on the hard cases, the cycles table's scenes,
// random triangles and meshes. Nothing here
// is a stored result: every expectation comes from running the golden and the model.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "common/setup.hpp"
#include "engines.hpp"
#include "golden/golden.hpp"
#include "common/cycle_columns.hpp"
#include "improved2/improved2_sc.hpp"
#include "scene/scene.hpp"
#include "improved2/improved2_rtl_engine.hpp"
#include "support/rtl_helpers.hpp"

namespace trirast {
namespace {

using test::scene;

EngineResult run_rtl(const SetupResult& setup, const RasterConfig& cfg, uint32_t seed = 1) {
  return test::run_verilated(rtl::run_rtl_improved2, setup, cfg, seed);
}

RasterConfig cfg_with(int form, const std::string& sink, int depth, int endpoints = 1) {
  RasterConfig cfg;
  cfg.improved2.corner_form = form;
  cfg.sink_stall = sink;
  cfg.fifo_depth = depth;
  cfg.endpoints = endpoints;
  cfg.validate();
  return cfg;
}

// The golden's spans and the model's cycles and statistics against one RTL run. Returns the
// number of triangles compared.
size_t expect_improved2(const SetupResult& setup, const RasterConfig& cfg,
                        const std::string& what) {
  EngineResult rtl = run_rtl(setup, cfg);
  EngineResult golden, sc;
  make_golden_engine()->run(setup, cfg, golden);
  make_improved2_sc_engine()->run(setup, cfg, sc);
  sort_spans(rtl.spans);
  sort_spans(golden.spans);
  EXPECT_EQ(test::first_span_difference(rtl.spans, "rtl", golden.spans, "golden"), "") << what;
  EXPECT_EQ(rtl.cycles.size(), setup.tris.size()) << what;
  EXPECT_EQ(sc.cycles.size(), setup.tris.size()) << what;
  std::string rows;
  EXPECT_EQ(test::cycle_rows_mismatch(rtl.cycles, "rtl", sc.cycles, "improved2-sc", what, rows), 0u)
      << rows;
  EXPECT_EQ(rtl.total_cycles, sc.total_cycles) << what;
  // Every statistic of the model: stage busy and stall cycles, lanes, walk stage, FIFO and sink,
  // empty / tiny / lane boxes, the lanes' divider iterations and steps, the rows.
  int stats = 0;
  EXPECT_EQ(test::statistics_mismatch(sc.work, rtl.work, {}, stats), "") << what;
  EXPECT_GE(stats, 20) << what;
  // The build that ran covers the run's N (cfg_endpoints_i sets it within the build's).
  EXPECT_GE(rtl.work["rtl_build_fifo_depth"], uint64_t(cfg.fifo_depth)) << what;
  return setup.tris.size();
}

const char* const kSinks[] = {"none", "periodic:2:1", "random:7:30"};

TEST(RtlImproved2, RegisteredExactAndTimed) {
  const EngineInfo* e = find_engine("improved2-rtl");
  ASSERT_NE(e, nullptr);
  EXPECT_TRUE(e->exact);
  EXPECT_TRUE(e->timed);
}

// The hard cases: both corner forms, three sinks.
TEST(RtlImproved2, HardCases) {
  for (int form : {0, 1})
    for (const char* sink : kSinks) {
      const RasterConfig cfg = cfg_with(form, sink, 8);
      expect_improved2(scene("builtin:hard-all", cfg), cfg,
                       "hard-all form " + std::to_string(form) + " sink " + sink);
    }
}

// The built-in scenes of docs/cycles-improved-vs-trad.md (Mileff, Nehez & Dudra's five and three
// meshes), radix-16 form, the sink always ready (the table's runs); two of them also stalled.
TEST(RtlImproved2, CyclesTableScenes) {
  for (const char* s : {"lowpoly-far", "lowpoly-near", "highpoly-far", "highpoly-near", "mixed",
                        "surface", "sphere", "torus"}) {
    const RasterConfig cfg = cfg_with(1, "none", 8);
    expect_improved2(scene(std::string("builtin:") + s, cfg), cfg, s);
  }
  for (const char* s : {"highpoly-far", "mixed"}) {
    const RasterConfig cfg = cfg_with(1, "random:3:40", 8);
    expect_improved2(scene(std::string("builtin:") + s, cfg), cfg, std::string(s) + " stalled");
  }
}

// A downstream that reacts to what it took (a pixel queue, --sink-stall queue:RATE:CAPACITY,
// common/span_downstream.hpp): the model and the RTL drive the same object, so their per-triangle
// cycles and statistics agree on three scenes, both corner forms; the queue really held the unit
// back (sink stall cycles, and cycles other than an always-ready downstream's).
TEST(RtlImproved2, ReactingDownstream) {
  for (const char* spec : {"builtin:mixed", "builtin:highpoly-near", TRIRAST_SOURCE_DIR "/tests/data/cube.obj"})
    for (int form : {0, 1})
      for (const char* sink : {"queue:2:16", "queue:1:4"}) {
        const RasterConfig cfg = cfg_with(form, sink, 8);
        const SetupResult setup = scene(spec, cfg);
        expect_improved2(setup, cfg, std::string(spec) + " form " + std::to_string(form) + " " + sink);
        EngineResult sc, ready;
        make_improved2_sc_engine()->run(setup, cfg, sc);
        make_improved2_sc_engine()->run(setup, cfg_with(form, "none", 8), ready);
        EXPECT_GT(sc.work["stall_cycles.span_sink"], 0u) << spec << " " << sink;
        EXPECT_GT(sc.total_cycles, ready.total_cycles) << spec << " " << sink;
      }
}

// FIFO depths 1 (every row waits for the span before to leave), 2, 4, 16 and 1024 (the
// Verilated maximum), random triangles of every size class, both forms.
TEST(RtlImproved2, FifoDepths) {
  size_t compared = 0;
  for (int form : {0, 1})
    for (int depth : {1, 2, 4, 16, 1024}) {
      const RasterConfig cfg = cfg_with(form, "random:11:50", depth);
      compared += expect_improved2(scene("builtin:random:count=1500,size=mixed,seed=21", cfg), cfg,
                                   "random form " + std::to_string(form) + " depth " +
                                       std::to_string(depth));
    }
  EXPECT_EQ(compared, 10u * 1500u);
}

// Tiny and small triangles: empty boxes, the 2x2 direct test, back-to-back hand-offs.
TEST(RtlImproved2, SmallAndTinyTriangles) {
  for (const char* size : {"tiny", "small"})
    for (int form : {0, 1}) {
      const RasterConfig cfg = cfg_with(form, "periodic:3:2", 2);
      expect_improved2(scene(std::string("builtin:random:count=4000,seed=5,size=") + size, cfg),
                       cfg, std::string("random size=") + size + " form " + std::to_string(form));
    }
}

TEST(RtlImproved2, MeshFile) {
  for (int form : {0, 1}) {
    const RasterConfig cfg = cfg_with(form, "random:5:20", 8);
    expect_improved2(scene(std::string(TRIRAST_SOURCE_DIR) + "/tests/data/cube.obj", cfg), cfg,
                     "cube.obj form " + std::to_string(form));
  }
}

// A small viewport: boxes clipped, many empty.
TEST(RtlImproved2, ClippedViewport) {
  RasterConfig cfg = cfg_with(1, "periodic:3:2", 8);
  cfg.width = 200;
  cfg.height = 120;
  cfg.validate();
  expect_improved2(scene("builtin:random:count=1500,size=large,seed=4,margin=100", cfg), cfg,
                   "clipped viewport");
}

// The other widths of docs/synth.md's configurations, both corner forms: small (S = 4,
// coordinates 12, box 10), wide (8, 20, 14), tiny (0, 8, 6: F = 1), hard cases and random
// triangles, two sinks; N = 1, and N = 4 with the stalling sink (those builds are at the
// maximums, N = 4 and FIFO 1024).
TEST(RtlImproved2, OtherWidths) {
  struct W { const char* name; int s, coord, box; };
  struct R { const char* sink; int n; int form; };
  for (const W& w : {W{"small", 4, 12, 10}, W{"wide", 8, 20, 14}, W{"tiny", 0, 8, 6}})
    for (const R& run : {R{"none", 1, 1}, R{"random:7:30", 1, 1}, R{"random:7:30", 4, 1},
                         R{"none", 1, 0}, R{"random:7:30", 4, 0}}) {
      const char* sink = run.sink;
      RasterConfig cfg = cfg_with(run.form, sink, 8, run.n);
      cfg.subpixel_bits = w.s;
      cfg.coord_int_bits = w.coord;
      cfg.box_bits = w.box;
      cfg.width = std::min(cfg.width, 1 << std::min(w.coord - 1, w.box));
      cfg.height = std::min(cfg.height, 1 << std::min(w.coord - 1, w.box));
      cfg.validate();
      // hard-all's coordinates reach past tiny's 8-bit range: its sub-pixel cases there.
      const std::string hard = w.coord >= 12 ? "builtin:hard-all" : "builtin:hard-tiny";
      const std::string n = " N " + std::to_string(run.n) + " form " + std::to_string(run.form);
      expect_improved2(scene(hard, cfg), cfg,
                       std::string(w.name) + " " + hard + " sink " + sink + n);
      expect_improved2(scene("builtin:random:count=1500,size=mixed,seed=8", cfg), cfg,
                       std::string(w.name) + " random sink " + sink + n);
    }
}

TEST(RtlImproved2, IndependentOfTheXSeed) {
  const RasterConfig cfg = cfg_with(1, "random:7:30", 8);
  const SetupResult setup = scene("builtin:random:count=300,seed=9", cfg);
  const EngineResult a = run_rtl(setup, cfg, 1), b = run_rtl(setup, cfg, 12345);
  EXPECT_EQ(a.spans, b.spans);
  ASSERT_EQ(a.cycles.size(), b.cycles.size());
  for (size_t p = 0; p < a.cycles.size(); ++p)
    EXPECT_TRUE(test::same_cycles(a.cycles[p], b.cycles[p])) << p;
}

// N = 2 and 4 (the maximal builds, cfg_endpoints_i): the hard cases in both corner forms under
// three sinks (FIFO 8, and the smallest FIFO an N allows, DEPTH = N).
TEST(RtlImproved2, HardCasesAtNTwoAndFour) {
  for (int n : {2, 4})
    for (int form : {0, 1})
      for (const char* sink : kSinks)
        for (int depth : {n, 8}) {
          const RasterConfig cfg = cfg_with(form, sink, depth, n);
          expect_improved2(scene("builtin:hard-all", cfg), cfg,
                           "hard-all N " + std::to_string(n) + " form " + std::to_string(form) +
                               " sink " + sink + " depth " + std::to_string(depth));
        }
}

// N = 2 and 4: random triangles of every size class (tiny jobs among them: their rows 0 and 1
// are one group) at FIFO depths N .. 1024, both forms, sinks ready, periodic and random.
TEST(RtlImproved2, RandomTrianglesAtNTwoAndFour) {
  size_t compared = 0;
  for (int n : {2, 4})
    for (int form : {0, 1})
      for (int depth : {n, 5, 16, 1024}) {
        const char* sink = depth == 16 ? "none" : depth == 5 ? "periodic:3:2" : "random:11:50";
        const RasterConfig cfg = cfg_with(form, sink, depth, n);
        compared += expect_improved2(scene("builtin:random:count=1500,size=mixed,seed=23", cfg),
                                     cfg, "random N " + std::to_string(n) + " form " +
                                              std::to_string(form) + " depth " +
                                              std::to_string(depth) + " sink " + sink);
      }
  for (int n : {2, 4}) {
    const RasterConfig cfg = cfg_with(1, "random:3:40", 4, n);
    compared += expect_improved2(scene("builtin:random:count=3000,seed=8,size=tiny", cfg), cfg,
                                 "random tiny N " + std::to_string(n));
    compared += expect_improved2(scene("builtin:mixed", cfg), cfg, "mixed N " + std::to_string(n));
  }
  EXPECT_EQ(compared, 16u * 1500u + 2u * 3000u + 2u * 10320u);
}

// What no build covers is refused by name: other widths; and an N that is not 1, 2 or 4.
TEST(RtlImproved2, RefusesWhatNoBuildCovers) {
  auto refuses = [](RasterConfig cfg, const std::string& option, bool valid = true) {
    if (valid) cfg.validate();
    EngineResult r;
    try {
      rtl::run_rtl_improved2(SetupResult{}, cfg, rtl::RtlRunOptions{}, r);
      ADD_FAILURE() << "accepted " << option;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
    }
  };
  RasterConfig n3;
  n3.endpoints = 3;
  refuses(n3, "--endpoints", false);
  RasterConfig s5;
  s5.subpixel_bits = 5;  // no build (docs/synth.md: S = 8, 4, 0)
  refuses(s5, "--subpixel-bits");
}

}  // namespace
}  // namespace trirast
