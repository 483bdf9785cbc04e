// The Verilated RTL (rtl/, engine "improved-rtl"): spans identical to the golden on the hard cases,
// 10,000 random triangles and the meshes; cycles equal to docs/timing.md, both in closed form and
// against an independent cycle-by-cycle reference written from that document (below), also with a
// queue downstream (--sink-stall queue:RATE:CAPACITY, which reacts to the spans it took); configuration
// errors; the FST trace of a window read back with fst2vcd.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/setup.hpp"
#include "common/span_downstream.hpp"
#include "golden/golden.hpp"
#include "improved/improved_sc.hpp"
#include "improved/improved_rtl_engine.hpp"
#include "scene/scene.hpp"
#include "common/cycle_columns.hpp"
#include "common/reference_raster.hpp"
#include "common/sc_engine.hpp"
#include "common/trirast_rtl_params.hpp"
#include "improved/improved_unit.hpp"
#include "common/unit_widths.hpp"
#include "support/scene_helpers.hpp"
#include "support/rtl_helpers.hpp"

namespace trirast {
namespace {

using test::tri;

RasterConfig default_cfg() {
  RasterConfig cfg;
  cfg.validate();
  return cfg;
}

EngineResult run_rtl(const SetupResult& setup, const RasterConfig& cfg, uint32_t seed = 1) {
  return test::run_verilated(rtl::run_rtl, setup, cfg, seed);
}

SpanList golden_spans(const SetupResult& setup, const RasterConfig& cfg) {
  EngineResult r;
  make_golden_engine()->run(setup, cfg, r);
  sort_spans(r.spans);
  return r.spans;
}

void expect_golden(const SetupResult& setup, const RasterConfig& cfg, const std::string& what) {
  EngineResult r = run_rtl(setup, cfg);
  sort_spans(r.spans);
  const SpanList g = golden_spans(setup, cfg);
  ASSERT_EQ(r.spans.size(), g.size()) << what;
  for (size_t i = 0; i < g.size(); ++i)
    ASSERT_EQ(r.spans[i], g[i]) << what << ": span " << i << " (triangle " << g[i].tri << ")";
  ASSERT_EQ(r.cycles.size(), setup.tris.size()) << what;
}

SetupResult builtin(const std::string& name, const RasterConfig& cfg) {
  return setup_scene(make_builtin(name, cfg, CameraOptions{}).tris, cfg);
}

// ---- an independent cycle reference, written from docs/timing.md ----

struct RefTriangle {
  bool empty;
  uint64_t L;             // max over the lanes of boundary_steps_k + divider_iterations_k
  int64_t rows;           // Ymax + 1
  std::vector<bool> has;  // has[j]: row j has a span
  std::vector<uint64_t> pixels;  // pixels[j]: its pixels
};

std::vector<RefTriangle> ref_triangles(const SetupResult& setup, const RasterConfig& cfg) {
  ImprovedUnit unit(cfg);
  std::vector<RefTriangle> out;
  for (const TriangleSetup& t : setup.tris) {
    SpanList spans;
    const UnitTriangleResult r = unit.run_triangle(t, spans);
    RefTriangle rt{r.iface.empty, 0, 0, {}, {}};
    if (!rt.empty) {
      for (int k = 0; k < 3; ++k)
        rt.L = std::max(rt.L, r.work.edge[k].boundary_steps + r.work.edge[k].divider_iterations);
      rt.rows = r.iface.Ymax + 1;
      rt.has.assign(size_t(rt.rows), false);
      rt.pixels.assign(size_t(rt.rows), 0);
      for (const Span& s : spans) {
        rt.has[size_t(s.y - r.iface.y0)] = true;
        rt.pixels[size_t(s.y - r.iface.y0)] = uint64_t(s.pixels());
      }
    }
    out.push_back(rt);
  }
  return out;
}

std::vector<TriangleCycles> reference_cycles(const SetupResult& setup, const RasterConfig& cfg) {
  const std::vector<RefTriangle> tris = ref_triangles(setup, cfg);
  // The run's downstream (a pattern or a queue), asked in the cycles a span is on offer and
  // handed each popped span (its triangle, its row in the walk, its pixels).
  const std::unique_ptr<SpanDownstream> sink = make_span_downstream(cfg);
  const size_t n = tris.size();
  const int64_t N = cfg.endpoints;
  const size_t depth = size_t(cfg.fifo_depth);
  std::vector<TriangleCycles> out(n);
  for (size_t p = 0; p < n; ++p) out[p] = TriangleCycles{setup.tris[p].index, 0, 0, 0, 0, 0, 0};
  enum { Idle, Box, Edge, Lanes, Hold } setup_st = Idle;
  size_t next = 0, cur = 0;  // next to accept; the one in setup
  uint64_t hold_from = 0;
  bool walking = false;
  size_t wtri = 0;
  int64_t wrow = 0;
  bool wany = false;
  std::deque<std::pair<size_t, int64_t>> fifo;  // triangle, row
  for (uint64_t c = 0; c < (uint64_t(1) << 32); ++c) {
    const size_t count0 = fifo.size();  // occupancy at the start of the cycle
    const bool walk_idle = !walking;
    // Sink: pop the oldest span.
    if (count0 > 0 && sink->ready(c)) {
      const auto [p, row] = fifo.front();
      sink->take(Span{setup.tris[p].index, int32_t(row), 0, int32_t(tris[p].pixels[size_t(row)])}, c);
      TriangleCycles& tc = out[p];
      if (tc.spans == 0) tc.first_span_cycle = c;
      tc.done_cycle = c;
      ++tc.spans;
      fifo.pop_front();
    }
    // Walk stage: a group when count <= DEPTH - N at the start of the cycle, else a stall.
    std::vector<std::pair<size_t, int64_t>> pushes;
    if (walking) {
      const RefTriangle& t = tris[wtri];
      if (count0 + size_t(N) <= depth) {
        for (int64_t r = 0; r < N && wrow <= t.rows - 1; ++r, ++wrow)
          if (t.has[size_t(wrow)]) pushes.push_back({wtri, wrow});
        wany = wany || !pushes.empty();
        if (wrow >= t.rows) {
          walking = false;  // idle from c + 1
          if (!wany) out[wtri].first_span_cycle = out[wtri].done_cycle = c;
        }
      } else {
        ++out[wtri].stall_cycles;
      }
    }
    for (const auto& e : pushes) fifo.push_back(e);
    // Setup stage.
    switch (setup_st) {
      case Idle:
        if (next < n) {
          cur = next++;
          out[cur].accept_cycle = c;
          setup_st = Box;
        }
        break;
      case Box:
        if (tris[cur].empty) {
          out[cur].first_span_cycle = out[cur].done_cycle = c;
          setup_st = Idle;
        } else {
          setup_st = Edge;
        }
        break;
      case Edge:
        hold_from = c + 1 + tris[cur].L;  // a + 3 + L
        setup_st = tris[cur].L > 0 ? Lanes : Hold;
        break;
      case Lanes:
        if (c + 1 >= hold_from) setup_st = Hold;
        break;
      case Hold:
        if (walk_idle) {  // hand-off at the end of c; the walk stage walks from c + 1
          walking = true;
          wtri = cur;
          wrow = 0;
          wany = false;
          setup_st = Idle;
        }
        break;
    }
    // Everything accepted, setup idle, walk idle, FIFO empty.
    if (next == n && setup_st == Idle && !walking && fifo.empty()) break;
  }
  return out;
}

// with_model: also every column against the SystemC model (which reads --sink-stall as a cycle
// pattern only, not yet a queue downstream). out: the RTL's run.
void expect_cycles(const SetupResult& setup, const RasterConfig& cfg, const std::string& what,
                   bool with_model = true, EngineResult* out = nullptr) {
  const std::vector<TriangleCycles> ref = reference_cycles(setup, cfg);
  EngineResult run = run_rtl(setup, cfg);
  const EngineResult& r = out ? (*out = std::move(run)) : run;
  ASSERT_EQ(r.cycles.size(), ref.size()) << what;
  for (size_t p = 0; p < ref.size(); ++p) {
    const TriangleCycles &a = r.cycles[p], &b = ref[p];
    ASSERT_EQ(a.tri, b.tri) << what;
    ASSERT_EQ(a.accept_cycle, b.accept_cycle) << what << ": triangle " << a.tri;
    ASSERT_EQ(a.first_span_cycle, b.first_span_cycle) << what << ": triangle " << a.tri;
    ASSERT_EQ(a.done_cycle, b.done_cycle) << what << ": triangle " << a.tri;
    ASSERT_EQ(a.spans, b.spans) << what << ": triangle " << a.tri;
    ASSERT_EQ(a.stall_cycles, b.stall_cycles) << what << ": triangle " << a.tri;
  }
  if (!with_model) return;
  // Every column, the stage breakdown too, equals the SystemC model's (docs/timing.md, "Outputs").
  EngineResult sc;
  make_improved_sc_engine()->run(setup, cfg, sc);
  ASSERT_EQ(sc.cycles.size(), r.cycles.size()) << what;
  std::string rows;
  EXPECT_EQ(test::cycle_rows_mismatch(r.cycles, "rtl", sc.cycles, "model", what, rows), 0u)
      << rows;
}

std::vector<InputTriangle> random_tris(uint64_t seed, int count, double max_size) {
  test::TestRng rng(seed);
  return test::random_grid_triangles(rng, count, -40.0, 1064.0, -40.0, 808.0, 8, max_size);
}

// ---- parameters ----

TEST(RtlParams, GeneratedWidthsEqualTheModels) {
  const UnitWidths w = unit_widths(default_cfg());
  EXPECT_EQ(rtl::kFracBits, w.frac);
  EXPECT_EQ(rtl::kVertexBits, w.vertex);
  EXPECT_EQ(rtl::kCoefBits, w.edge_coef);
  EXPECT_EQ(rtl::kStepBits, w.step);
  EXPECT_EQ(rtl::kEdgeBits, w.edge_value);
  EXPECT_EQ(rtl::kBoxBits, w.box);
  EXPECT_EQ(rtl::kQuotBits, w.quotient);
  EXPECT_EQ(rtl::kRemBits, w.remainder);
  EXPECT_EQ(rtl::kWalkerXBits, w.walker_x);
  EXPECT_EQ(rtl::kNumerBits, w.numerator);
  EXPECT_EQ(rtl::kSubpixelBits, default_cfg().subpixel_bits);
  EXPECT_EQ(rtl::kCoordIntBits, default_cfg().coord_int_bits);
}

TEST(RtlConfig, UnbuiltWidthsAreRejectedNamingTheOption) {
  const RasterConfig base = default_cfg();
  const SetupResult setup = setup_scene({tri(1, 1, 9, 2, 3, 8)}, base);
  auto message = [&](RasterConfig cfg) {
    try {
      run_rtl(setup, cfg);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // Built: 8:16:14, 4:12:10, 8:20:14, 0:8:6 (docs/synth.md); S = 5, coord 13, box 11 are not.
  RasterConfig c = base;
  c.subpixel_bits = 5;
  EXPECT_NE(message(c).find("--subpixel-bits"), std::string::npos) << message(c);
  c = base;
  c.coord_int_bits = 13;
  EXPECT_NE(message(c).find("--coord-bits"), std::string::npos) << message(c);
  c = base;
  c.box_bits = 11;
  EXPECT_NE(message(c).find("--box-bits"), std::string::npos) << message(c);
}

// Every width configuration docs/synth.md names has a Verilated build: the RTL's spans equal the
// golden's there (scripts/synth.sh CONFIGS; tb/CMakeLists.txt).
TEST(RtlConfig, EveryDocumentedWidthConfigurationRuns) {
  const int configs[][3] = {{8, 16, 14}, {4, 12, 10}, {8, 20, 14}, {0, 8, 6}};
  for (const auto& w : configs) {
    RasterConfig cfg = default_cfg();
    cfg.subpixel_bits = w[0];
    cfg.coord_int_bits = w[1];
    cfg.box_bits = w[2];
    cfg.width = 64;
    cfg.height = 48;
    const SetupResult setup =
        setup_scene({tri(1, 1, 40, 2, 3, 30), tri(10, 40, 60, 5, 50, 44)}, cfg);
    EngineResult r;
    ASSERT_NO_THROW(r = run_rtl(setup, cfg)) << w[0] << ":" << w[1] << ":" << w[2];
    EngineResult g;
    make_golden_engine()->run(setup, cfg, g);
    sort_spans(r.spans);
    sort_spans(g.spans);
    EXPECT_EQ(r.spans, g.spans) << w[0] << ":" << w[1] << ":" << w[2];
    EXPECT_GT(r.spans.size(), 0u);
  }
}

// The RTL's module table (every module's busy and stall cycles, the edge walkers' Bresenham steps
// included) and the datapath's work counters equal the SystemC model's, also with a stalling
// sink, N = 4 and both boundary and divider modes.
TEST(RtlStats, ModuleCyclesEqualTheModel) {
  for (const char* stall : {"none", "random:7:30"}) {
    for (int n : {1, 4}) {
      RasterConfig cfg = default_cfg();
      cfg.sink_stall = stall;
      cfg.endpoints = n;
      if (n == 4) {
        cfg.boundary = BoundaryMode::Divide;
        cfg.divider = DividerMode::Fixed;
      }
      const SetupResult setup = setup_scene(
          {tri(1, 1, 90, 2, 3, 80), tri(10, 40, 60, 5, 50, 44), tri(-5, -5, -1, -2, -3, -1)}, cfg);
      const EngineResult r = run_rtl(setup, cfg);
      EngineResult m;
      make_improved_sc_engine()->run(setup, cfg, m);
      int compared = 0;
      EXPECT_EQ(test::statistics_mismatch(m.work, r.work, {}, compared), "")
          << "sink " << stall << " N=" << n;
      EXPECT_GE(compared, 25);  // 15 modules' busy, 2 stalls, 5 work counters, spans, ...
    }
  }
}

TEST(RtlConfig, QuotientTruncationIsRejectedNamingTheOption) {
  const RasterConfig base = default_cfg();
  const SetupResult setup = setup_scene({tri(1, 1, 9, 2, 3, 8)}, base);
  RasterConfig c = base;
  c.divider_quotient_bits = 6;
  std::string msg = "no error";
  try {
    run_rtl(setup, c);
  } catch (const std::invalid_argument& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("divider_quotient_bits"), std::string::npos) << msg;
  EXPECT_NE(msg.find("6"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;  // one line
  // 0 (the exact divider) still runs.
  c.divider_quotient_bits = 0;
  EXPECT_NO_THROW(run_rtl(setup, c));
}

// ---- spans against the golden ----

TEST(RtlGolden, HardCases) { expect_golden(builtin("hard-all", default_cfg()), default_cfg(), "hard-all"); }

TEST(RtlGolden, TenThousandRandomTriangles) {
  const RasterConfig cfg = default_cfg();
  const SetupResult setup = setup_scene(random_tris(0x7269a5u, 10000, 120.0), cfg);
  expect_golden(setup, cfg, "random 10000");
}

TEST(RtlGolden, Meshes) {
  const RasterConfig cfg = default_cfg();
  for (const char* m : {"sphere", "torus", "mixed"}) expect_golden(builtin(m, cfg), cfg, m);
}

TEST(RtlGolden, DivideBoundaryFixedDividerFourEndpoints) {
  RasterConfig cfg = default_cfg();
  cfg.boundary = BoundaryMode::Divide;
  cfg.divider = DividerMode::Fixed;
  cfg.endpoints = 4;
  cfg.sink_stall = "random:3:40";
  expect_golden(builtin("hard-all", cfg), cfg, "hard-all divide/fixed/N=4");
}

TEST(RtlGolden, IndependentOfTheXSeed) {
  const RasterConfig cfg = default_cfg();
  const SetupResult setup = builtin("hard-tiny", cfg);
  const EngineResult a = run_rtl(setup, cfg, 1), b = run_rtl(setup, cfg, 12345);
  ASSERT_EQ(a.spans.size(), b.spans.size());
  for (size_t i = 0; i < a.spans.size(); ++i) EXPECT_EQ(a.spans[i], b.spans[i]);
  EXPECT_EQ(a.total_cycles, b.total_cycles);
}

// ---- cycles: closed form (docs/timing.md, "Closed form for one triangle") ----

TEST(RtlCycles, LoneTriangleClosedForm) {
  const RasterConfig cfg = default_cfg();
  for (const InputTriangle& t : {tri(10.2, 10.7, 30.5, 14.1, 17.3, 40.9), tri(100, 100, 160, 103, 90, 190),
                                 tri(5, 5, 6.5, 5, 5, 300), tri(0.1, 0.1, 900, 2, 300, 700)}) {
    const SetupResult setup = setup_scene({t}, cfg);
    ASSERT_EQ(setup.tris.size(), 1u);
    const RefTriangle rt = ref_triangles(setup, cfg)[0];
    ASSERT_FALSE(rt.empty);
    const uint64_t h = 3 + rt.L;
    int64_t jf = -1, jl = -1;
    for (int64_t j = 0; j < rt.rows; ++j)
      if (rt.has[size_t(j)]) {
        if (jf < 0) jf = j;
        jl = j;
      }
    ASSERT_GE(jf, 0);
    const EngineResult r = run_rtl(setup, cfg);
    ASSERT_EQ(r.cycles.size(), 1u);
    EXPECT_EQ(r.cycles[0].accept_cycle, 0u);
    EXPECT_EQ(r.cycles[0].first_span_cycle, h + 2 + uint64_t(jf));
    EXPECT_EQ(r.cycles[0].done_cycle, h + 2 + uint64_t(jl));
    EXPECT_EQ(r.cycles[0].stall_cycles, 0u);
    EXPECT_EQ(r.total_cycles, h + 3 + uint64_t(jl));
  }
}

TEST(RtlCycles, BackToBackPairAcceptsTheSecondAfterTheHandOff) {
  const RasterConfig cfg = default_cfg();
  const SetupResult setup =
      setup_scene({tri(10, 10, 40, 12, 20, 50), tri(100, 20, 130, 25, 110, 28)}, cfg);
  const RefTriangle t0 = ref_triangles(setup, cfg)[0];
  const EngineResult r = run_rtl(setup, cfg);
  EXPECT_EQ(r.cycles[1].accept_cycle, 3 + t0.L + 1);  // h0 + 1
  expect_cycles(setup, cfg, "pair");
}

TEST(RtlCycles, EmptyBoxRetiresInTheBoxCycle) {
  const RasterConfig cfg = default_cfg();
  // Off screen, then a sub-pixel triangle between centres, then a visible one.
  const SetupResult setup = setup_scene(
      {tri(-50, -50, -40, -45, -45, -30), tri(3.6, 3.6, 3.9, 3.6, 3.6, 3.9), tri(1, 1, 9, 2, 3, 8)},
      cfg);
  ASSERT_EQ(setup.tris.size(), 3u);
  const EngineResult r = run_rtl(setup, cfg);
  EXPECT_EQ(r.cycles[0].accept_cycle, 0u);
  EXPECT_EQ(r.cycles[0].done_cycle, 1u);
  EXPECT_EQ(r.cycles[0].first_span_cycle, 1u);
  EXPECT_EQ(r.cycles[1].accept_cycle, 2u);
  EXPECT_EQ(r.cycles[1].done_cycle, 3u);
  EXPECT_EQ(r.cycles[2].accept_cycle, 4u);
  expect_cycles(setup, cfg, "empty boxes");
}

// ---- cycles: against the reference, many configurations ----

TEST(RtlCycles, HardTinyEmptyBoxesAndTrianglesWithoutSpans) {
  RasterConfig cfg = default_cfg();
  expect_cycles(builtin("hard-tiny", cfg), cfg, "hard-tiny");
  cfg.sink_stall = "periodic:2:3";
  expect_cycles(builtin("hard-tiny", cfg), cfg, "hard-tiny periodic");
}

TEST(RtlCycles, RandomTrianglesAllSinksAndEndpoints) {
  const std::vector<InputTriangle> tris = random_tris(0xc1c1e5u, 1500, 60.0);
  for (int N : {1, 2, 4})
    for (const char* sink : {"none", "periodic:3:2", "random:11:35"})
      for (int depth : {N, 8}) {
        RasterConfig cfg = default_cfg();
        cfg.endpoints = N;
        cfg.fifo_depth = depth;
        cfg.sink_stall = sink;
        expect_cycles(setup_scene(tris, cfg), cfg,
                      "N=" + std::to_string(N) + " depth=" + std::to_string(depth) + " " + sink);
      }
}

TEST(RtlCycles, BoundaryAndDividerModes) {
  for (BoundaryMode b : {BoundaryMode::Step, BoundaryMode::Divide})
    for (DividerMode d : {DividerMode::Adaptive, DividerMode::Fixed}) {
      RasterConfig cfg = default_cfg();
      cfg.boundary = b;
      cfg.divider = d;
      cfg.sink_stall = "random:5:20";
      cfg.endpoints = 2;
      expect_cycles(builtin("hard-all", cfg), cfg,
                    std::string(boundary_mode_name(b)) + "/" + divider_mode_name(d));
    }
}

TEST(RtlCycles, BackPressureStalls) {
  RasterConfig cfg = default_cfg();
  cfg.sink_stall = "periodic:1:7";
  cfg.fifo_depth = 2;
  const SetupResult setup = setup_scene({tri(10, 10, 200, 14, 30, 120)}, cfg);
  const EngineResult r = run_rtl(setup, cfg);
  EXPECT_GT(r.cycles[0].stall_cycles, 50u);
  expect_cycles(setup, cfg, "back-pressure");
}

// A queue downstream (--sink-stall queue:RATE:CAPACITY, docs/timing.md "Sink patterns"): its
// ready reacts to the pixels of the spans it took; the RTL asks it every cycle, the reference only
// in the cycles a span is on offer, and they must give the same cycles.
TEST(RtlCycles, QueueDownstreamFollowsTheReference) {
  const std::vector<InputTriangle> tris = random_tris(0x9e0e5u, 800, 80.0);
  uint64_t stalls = 0;
  for (int N : {1, 4})
    for (const char* queue : {"queue:2:16", "queue:1:4", "queue:8:64", "queue:3:1"})
      for (int depth : {N, 8}) {
        RasterConfig cfg = default_cfg();
        cfg.endpoints = N;
        cfg.fifo_depth = depth;
        cfg.sink_stall = queue;
        EngineResult r;
        expect_cycles(setup_scene(tris, cfg), cfg,
                      "N=" + std::to_string(N) + " depth=" + std::to_string(depth) + " " + queue,
                      false, &r);
        if (HasFatalFailure()) return;
        EXPECT_GT(r.work["stall_cycles.span_sink"], 0u) << queue;
        stalls += r.work["walk_stall_cycles"];
      }
  EXPECT_GT(stalls, 1000u);  // the queues back-pressured the walk stage
}

// ---- the trace ----

std::string read_file(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

TEST(RtlTrace, FstWindowOfALargeSceneHasTheHandshakes) {
  RasterConfig cfg = default_cfg();
  const std::string dir = testing::TempDir();
  const std::string fst = dir + "/rtl_window.fst", vcd = dir + "/rtl_window_readback.vcd";
  cfg.trace_path = fst;
  cfg.trace_first = 1000;
  cfg.trace_last = 1010;
  const SetupResult setup = builtin("sphere", cfg);
  ASSERT_GT(setup.tris.size(), 1100u);
  const EngineResult r = run_rtl(setup, cfg);
  ASSERT_EQ(std::system(("fst2vcd -f '" + fst + "' -o '" + vcd + "'").c_str()), 0);
  const std::string text = read_file(vcd);
  for (const char* sig : {"tri_valid_i", "tri_ready_o", "span_valid_o", "span_ready_i", "clk_i"})
    EXPECT_NE(text.find(std::string(" ") + sig + " "), std::string::npos) << sig;
  // The model's time base: 1 ns per cycle, recorded in 100 ps; cycle c's values at c.5 ns.
  EXPECT_NE(text.find("$timescale\n\t100ps\n$end"), std::string::npos) << text.substr(0, 300);
  // Only the window: its first timestamp is the cycle triangle 1000 is on the port.
  size_t p1000 = 0;
  while (setup.tris[p1000].index < 1000) ++p1000;
  const uint64_t first = 10 * (r.cycles[p1000 - 1].accept_cycle + 1) + 5;
  const size_t t = text.find("\n#");
  ASSERT_NE(t, std::string::npos);
  EXPECT_EQ(std::stoull(text.substr(t + 2)), first);
  // ... and its last one the cycle after triangle 1010 is done.
  size_t p1010 = p1000;
  while (p1010 + 1 < setup.tris.size() && setup.tris[p1010 + 1].index <= 1010) ++p1010;
  const size_t last = text.rfind("\n#");
  const uint64_t last_t = std::stoull(text.substr(last + 2));
  EXPECT_GE(last_t, 10 * r.cycles[p1010].done_cycle + 10);
  EXPECT_LE(last_t, 10 * r.cycles[p1010].done_cycle + 25);
  // The save file beside it: the dump named relative to it, the zoom from the window's start,
  // the setup state through a filter file beside it.
  const std::string gtkw = read_file(dir + "/rtl_window.gtkw");
  EXPECT_NE(gtkw.find("[dumpfile] \"rtl_window.fst\"\n"), std::string::npos) << gtkw.substr(0, 300);
  EXPECT_NE(gtkw.find("[savefile] \"rtl_window.gtkw\"\n"), std::string::npos);
  EXPECT_NE(gtkw.find("[timestart] " + std::to_string(first * 100) + "\n"), std::string::npos);
  EXPECT_NE(gtkw.find("^1 rtl_window.setup_state.filter\n@2024\ntrirast_improved_top.setup_state_o[2:0]\n"),
            std::string::npos);
  EXPECT_NE(read_file(dir + "/rtl_window.setup_state.filter").find("4 StHold\n"), std::string::npos);
}

// The first timestamp after the header of a VCD (its first recorded instant).
uint64_t first_vcd_time(const std::string& text) {
  const size_t t = text.find("\n#", text.find("$enddefinitions"));
  if (t == std::string::npos) throw std::runtime_error("a VCD without a timestamp");
  return std::stoull(text.substr(t + 2));
}

// The SystemC model's trace and the RTL's of the same window start on the same cycle: the one the
// window's first triangle is on the port (the model records in 1 ns per cycle, the RTL in 100 ps
// with cycle c's values at c.5 ns). The RTL's trace has the triangle port split per vertex and
// edge, signed, in a group of its own in the save file.
TEST(RtlTrace, ModelAndRtlWindowsStartOnTheSameCycle) {
  RasterConfig cfg = default_cfg();
  const std::string dir = testing::TempDir();
  const SetupResult setup = builtin("mixed", cfg);
  // The window starts at a triangle that waits on the port (accepted later than offered), so a
  // trace that starts at the accept would start later.
  EngineResult untraced;
  make_improved_sc_engine()->run(setup, cfg, untraced);
  size_t p = 100;
  while (p < untraced.cycles.size() &&
         untraced.cycles[p].accept_cycle <= untraced.cycles[p - 1].accept_cycle + 1)
    ++p;
  ASSERT_LT(p, untraced.cycles.size());
  const uint64_t offered = untraced.cycles[p - 1].accept_cycle + 1;
  cfg.trace_first = setup.tris[p].index;
  cfg.trace_last = cfg.trace_first + 4;
  cfg.trace_path = dir + "/align_model.vcd";
  EngineResult model;
  make_improved_sc_engine()->run(setup, cfg, model);
  cfg.trace_path = dir + "/align_rtl.vcd";
  const EngineResult rtl = run_rtl(setup, cfg);
  ASSERT_EQ(rtl.cycles[p - 1].accept_cycle, untraced.cycles[p - 1].accept_cycle);
  const std::string model_vcd = read_file(dir + "/align_model.vcd");
  const std::string rtl_vcd = read_file(dir + "/align_rtl.vcd");
  EXPECT_EQ(first_vcd_time(model_vcd), offered);
  EXPECT_EQ(first_vcd_time(rtl_vcd), 10 * offered + 5);
  for (const char* view : {"tri_v0_x", "tri_v2_y", "tri_e1_a", "tri_e2_c"})
    EXPECT_NE(rtl_vcd.find(std::string(" ") + view + " "), std::string::npos) << view;
  const std::string gtkw = read_file(dir + "/align_rtl.gtkw");
  EXPECT_NE(gtkw.find("-triangle port, per vertex and edge (signed)\n@424\n"), std::string::npos)
      << gtkw;
}

TEST(RtlTrace, VcdOutputIsConverted) {
  RasterConfig cfg = default_cfg();
  cfg.trace_path = testing::TempDir() + "/rtl_small.vcd";
  const SetupResult setup = setup_scene({tri(1, 1, 9, 2, 3, 8)}, cfg);
  run_rtl(setup, cfg);
  const std::string text = read_file(cfg.trace_path);
  EXPECT_NE(text.find("$enddefinitions"), std::string::npos);
  EXPECT_NE(text.find(" span_valid_o "), std::string::npos);
}

}  // namespace
}  // namespace trirast
