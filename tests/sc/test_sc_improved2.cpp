// The second-generation unit's SystemC model (improved2-sc, docs/improved2.md, "Views and
// files"): its spans equal the golden's in both corner forms, whatever the
// sink and N (1, 2, 4 rows per walk cycle); an empty box retires in the box stage; a walk takes
// one cycle per group of N rows; N = 3 is refused; its trace (--trace) is a VCD
// whose signals agree with the cycles, with the .gtkw grouped by module, and tracing changes no
// cycle. Its cycles against
// the unit's RTL (rtl/improved2/trirast_improved2.f, engine improved2-rtl) are
// tests/rtl/test_rtl_improved2_engine.cpp's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/fixed_point.hpp"
#include "common/setup.hpp"
#include "golden/golden.hpp"
#include "common/cycle_columns.hpp"
#include "improved2/improved2_cycle_reference.hpp"
#include "improved2/improved2_sc.hpp"
#include "scene/scene.hpp"
#include "support/run_command.hpp"
#include "support/vcd_reader.hpp"
#include "improved2/improved2_unit.hpp"

namespace trirast {
namespace {

using test::read_vcd;
using test::rises;
using test::slurp;
using test::value_at;
using test::Vcd;
using test::vcd_bin;

EngineResult run_model(const SetupResult& setup, const RasterConfig& cfg) {
  EngineResult r;
  make_improved2_sc_engine()->run(setup, cfg, r);
  return r;
}

SetupResult builtin_setup(const std::string& name, const RasterConfig& cfg) {
  return setup_scene(make_builtin(name, cfg, CameraOptions{}).tris, cfg);
}

// The spans are the golden's at N = 1, 2, 4 in both corner forms, whatever the sink; per triangle
// the cycles are ordered (accept <= first span <= done, accepts in order) and the spans counted.
TEST(ScImproved2, SpansEqualGoldenInBothFormsSinksAndN) {
  for (const char* scene : {"hard-all", "mixed", "sphere", "highpoly-far"}) {
    RasterConfig cfg;
    const SetupResult setup = builtin_setup(scene, cfg);
    EngineResult g;
    make_golden_engine()->run(setup, cfg, g);
    sort_spans(g.spans);
    for (int n : {1, 2, 4})
      for (int form : {0, 1})
        for (const char* sink : {"none", "periodic:2:1", "random:5:40"}) {
          SCOPED_TRACE(std::string(scene) + " N " + std::to_string(n) + " form " +
                       std::to_string(form) + " sink " + sink);
          cfg.endpoints = n;
          cfg.improved2.corner_form = form;
          cfg.sink_stall = sink;
          cfg.fifo_depth = 4;
          EngineResult r = run_model(setup, cfg);
          sort_spans(r.spans);
          EXPECT_TRUE(r.spans == g.spans);
          ASSERT_EQ(r.cycles.size(), setup.tris.size());
          uint64_t spans = 0;
          for (size_t i = 0; i < r.cycles.size(); ++i) {
            const TriangleCycles& c = r.cycles[i];
            EXPECT_EQ(c.tri, setup.tris[i].index);
            EXPECT_LE(c.accept_cycle, c.first_span_cycle);
            EXPECT_LE(c.first_span_cycle, c.done_cycle);
            if (i > 0) {
              EXPECT_LT(r.cycles[i - 1].accept_cycle, c.accept_cycle);
            }
            spans += c.spans;
          }
          EXPECT_EQ(spans, g.spans.size());
        }
  }
}

// An empty box retires in a + 1 and the port takes the next triangle in that same cycle.
TEST(ScImproved2, EmptyBoxRetiresInTheBoxStage) {
  RasterConfig cfg;
  std::vector<InputTriangle> tris(3);
  for (auto& t : tris) t = InputTriangle{{10.6, 11.4, 10.6}, {10.6, 10.6, 11.4}, 0};
  const EngineResult r = run_model(setup_scene(tris, cfg), cfg);
  ASSERT_EQ(r.cycles.size(), 3u);
  for (uint64_t i = 0; i < 3; ++i) {
    EXPECT_EQ(r.cycles[i].accept_cycle, i);
    EXPECT_EQ(r.cycles[i].done_cycle, i + 1);
    EXPECT_EQ(r.cycles[i].spans, 0u);
  }
  EXPECT_EQ(r.total_cycles, 4u);
}

// TRIRAST_IMPROVED2_CHECK=1 turns on the unit's cross-check of the gen2 parts against gen1's
// (Improved2Unit's cross_check; improved2-datapath always runs it): the run must not throw and
// must give the same spans, per-triangle cycles, total and work counters as the normal run, at
// N = 1 and 4 (with a stalling sink and a 4-entry FIFO) in both corner forms.
TEST(ScImproved2, CrossCheckOnRequestChangesNothing) {
  for (int form : {0, 1})
    for (int n : {1, 4}) {
      RasterConfig cfg;
      cfg.improved2.corner_form = form;
      cfg.endpoints = n;
      if (n == 4) {
        cfg.sink_stall = "random:7:30";
        cfg.fifo_depth = 4;
      }
      const SetupResult setup = builtin_setup("mixed", cfg);
      const EngineResult plain = run_model(setup, cfg);
      ASSERT_EQ(setenv("TRIRAST_IMPROVED2_CHECK", "1", 1), 0);
      EngineResult checked;
      EXPECT_NO_THROW(checked = run_model(setup, cfg)) << "form " << form << " N " << n;
      unsetenv("TRIRAST_IMPROVED2_CHECK");
      EXPECT_TRUE(plain.spans == checked.spans);
      EXPECT_EQ(plain.total_cycles, checked.total_cycles);
      // Every counter but the run's own speed (sim_wall_microseconds, sim_cycles_per_second).
      auto counters = [](std::map<std::string, uint64_t> w) {
        w.erase("sim_wall_microseconds");
        w.erase("sim_cycles_per_second");
        return w;
      };
      EXPECT_EQ(counters(plain.work), counters(checked.work));
      EXPECT_GT(plain.work.at("lane_boxes"), 1000u);
      ASSERT_EQ(plain.cycles.size(), checked.cycles.size());
      EXPECT_GT(plain.cycles.size(), 10000u);
      for (size_t i = 0; i < plain.cycles.size(); ++i) {
        EXPECT_EQ(plain.cycles[i].done_cycle, checked.cycles[i].done_cycle) << i;
        EXPECT_EQ(plain.cycles[i].setup_done_cycle, checked.cycles[i].setup_done_cycle) << i;
        EXPECT_EQ(plain.cycles[i].divider_iterations, checked.cycles[i].divider_iterations) << i;
      }
    }
}

// The walk stage's N rule: a job walks one cycle per group of N rows besides its stall cycles,
// ceil(rows / N) groups for a lane job's Ymax + 1 rows; a tiny job (a box of at most 2 x 2
// centres) one group when N >= 2; the rows visited do not depend on N, the walk stage's busy
// cycles are the groups.
TEST(ScImproved2, WalkTakesOneCyclePerGroupOfNRows) {
  RasterConfig cfg;
  cfg.fifo_depth = 8;
  cfg.sink_stall = "periodic:2:1";
  const SetupResult setup = builtin_setup("mixed", cfg);
  uint64_t rows_n1 = 0;
  for (int n : {1, 2, 4}) {
    SCOPED_TRACE("N " + std::to_string(n));
    cfg.endpoints = n;
    const EngineResult r = run_model(setup, cfg);
    uint64_t groups = 0, checked = 0, tiny = 0;
    for (const TriangleCycles& c : r.cycles) {
      if (c.box_height == 0) continue;  // an empty box
      const uint64_t walk = c.walk_end_cycle - c.walk_start_cycle + 1 - c.stall_cycles;
      const bool is_tiny = c.box_width <= 2 && c.box_height <= 2;
      if (is_tiny) {
        ++tiny;
        if (n >= 2) {
          EXPECT_EQ(walk, 1u) << c.tri;
        }
      } else {
        EXPECT_EQ(walk, (c.box_height + uint64_t(n) - 1) / uint64_t(n)) << c.tri;
        ++checked;
      }
      groups += walk;
    }
    EXPECT_GT(checked, 1000u);
    EXPECT_GT(tiny, 100u);
    EXPECT_GT(r.work.at("stall_cycles.walk"), 0u);
    EXPECT_EQ(r.work.at("busy_cycles.walk"), groups);
    if (n == 1) rows_n1 = r.work.at("rows_visited");
    EXPECT_EQ(r.work.at("rows_visited"), rows_n1);
  }
}

// docs/timing.md's d, read independently of Improved2CornerUnit: the fewest digits of 4 bits (at least 1)
// in which each of cx - vx, cy - vy of the vertices v0 and v1 at the run's corner fits as a two's
// complement number, -2^(4d - 1) <= value < 2^(4d - 1).
static uint64_t contract_digits(const TriangleSetup& t, int64_t x0, int64_t y0,
                                const RasterConfig& cfg) {
  uint64_t d = 1;
  for (int v = 0; v < 2; ++v) {
    for (const int64_t value :
         {pixel_centre(x0, cfg) - t.v[v].x, pixel_centre(y0, cfg) - t.v[v].y}) {
      while (value < -(int64_t(1) << (4 * d - 1)) || value >= (int64_t(1) << (4 * d - 1))) ++d;
    }
  }
  return d;
}

// The model against an independent cycle-by-cycle reading of docs/timing.md "The
// second-generation improved unit" (tb/improved2/improved2_cycle_reference.hpp), which takes from
// the datapath only what the contract's cycles depend on (the corner unit's digit counts it reads
// from the contract itself, contract_digits, and checks the datapath's against them): all sixteen
// columns of every triangle, both corner forms, N = 1, 2, 4, FIFO depths 1 .. 8 (N at least),
// three sinks.
TEST(ScImproved2, CyclesFollowTheContractStepByStep) {
  size_t compared = 0;
  for (const char* scene : {"hard-all", "mixed:objects=3", "random:count=3000,size=mixed,seed=4",
                            "random:count=3000,size=tiny,seed=6"}) {
    RasterConfig cfg;
    const SetupResult setup = builtin_setup(scene, cfg);
    std::vector<test::Ref2Triangle> ref;
    Improved2Unit unit(cfg);
    Improved2Triangle x;
    for (const TriangleSetup& t : setup.tris) {
      unit.run_triangle(t, x);
      test::Ref2Triangle r;
      r.tri = t.index;
      r.empty = x.box.empty;
      r.tiny = x.tiny;
      // C's runs: E_L for every box that reaches C, E_R at x0 + Xmax for a lane job.
      if (!x.box.empty) {
        r.digits_l = contract_digits(t, x.box.x0, x.box.y0, cfg);
        ASSERT_EQ(uint64_t(x.corner_digits_l), r.digits_l) << scene << " triangle " << t.index;
        if (!x.tiny) {
          r.digits_r = contract_digits(t, x.box.x0 + x.box.Xmax, x.box.y0, cfg);
          ASSERT_EQ(uint64_t(x.corner_digits_r), r.digits_r) << scene << " triangle " << t.index;
        }
      }
      r.lane_cycles = x.lane_cycles;
      for (const Improved2Row& row : x.rows)
        r.row_pixels.push_back(row.valid ? uint64_t(row.span.pixels()) : 0);
      if (!x.box.empty) {
        for (const Improved2LaneWork& w : x.lane) {
          r.divider_iterations += w.iterations;
          r.boundary_steps += uint64_t(w.steps);
        }
        r.box_width = uint64_t(x.box.Xmax) + 1;
        r.box_height = uint64_t(x.box.Ymax) + 1;
      }
      ref.push_back(r);
    }
    for (int form : {0, 1})
      for (int n : {1, 2, 4})
        for (int depth : {1, 2, 8})
          for (const char* sink : {"none", "periodic:2:1", "random:3:45"}) {
            if (depth < n) continue;
            const std::string what = std::string(scene) + " form " + std::to_string(form) +
                                     " N " + std::to_string(n) + " FIFO " + std::to_string(depth) +
                                     " sink " + sink;
            cfg.improved2.corner_form = form;
            cfg.endpoints = n;
            cfg.fifo_depth = depth;
            cfg.sink_stall = sink;
            const EngineResult r = run_model(setup, cfg);
            const std::vector<TriangleCycles> want = test::reference2_cycles(
                ref, form == 1, uint64_t(n), uint64_t(depth), SinkPattern::parse(sink));
            ASSERT_EQ(r.cycles.size(), want.size()) << what;
            std::string rows;
            EXPECT_EQ(test::cycle_rows_mismatch(r.cycles, "improved2-sc", want, "reference", what,
                                                rows),
                      0u)
                << rows;
            compared += want.size();
          }
  }
  EXPECT_GT(compared, 500000u);
}

TEST(ScImproved2, RefusesOtherEndpoints) {
  RasterConfig cfg;
  const SetupResult setup = builtin_setup("hard-all", cfg);
  cfg.endpoints = 3;
  cfg.fifo_depth = 8;
  try {
    run_model(setup, cfg);
    ADD_FAILURE() << "N = 3 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--endpoints: 3 is not 1, 2 or 4"), std::string::npos)
        << e.what();
  }
}

// ---- the trace ---------------------------------------------------------------------------------

const char* kImproved2Signals[] = {"box_stage.tri_accept",
                                   "box_stage.busy",
                                   "box_stage.tri",
                                   "box_stage.stall",
                                   "box_stage.retire",
                                   "corner_stage.busy",
                                   "corner_stage.tri",
                                   "corner_stage.stall",
                                   "corner_unit.run",
                                   "corner_unit.digits",
                                   "job_stage.busy",
                                   "job_stage.tri",
                                   "job_stage.tiny",
                                   "job_stage.stall",
                                   "lane0.busy",
                                   "lane1.busy",
                                   "lane2.busy",
                                   "lane0.steps",
                                   "lane1.phase",
                                   "lane0.iterations",
                                   "walk_stage.state",
                                   "walk_stage.tri",
                                   "walk_stage.row",
                                   "walk_stage.stall",
                                   "walk_stage.push",
                                   "span.valid",
                                   "span.ready",
                                   "span.tri",
                                   "span.y",
                                   "span.x_begin",
                                   "span.x_end",
                                   "span_fifo.count",
                                   "span_sink.take"};

// The whole run of mixed (2 objects) traced, both corner forms, a 2-deep FIFO and a stalling
// sink: every signal exists and changes; the span port's accepts (span_sink.take) rise in each
// triangle's first-span cycle with its tag on span.tri; tri_accept in each accept cycle; the
// stages hold each triangle's tag at the cycles the CSV names; the .gtkw groups by module.
TEST(ScImproved2, TraceAgreesWithTheCycles) {
  for (int form : {0, 1}) {
    SCOPED_TRACE("corner form " + std::to_string(form));
    RasterConfig cfg;
    cfg.improved2.corner_form = form;
    cfg.fifo_depth = 2;
    cfg.sink_stall = "periodic:2:3";
    const SetupResult setup = builtin_setup("mixed:objects=2", cfg);
    ASSERT_GT(setup.tris.size(), 100u);
    const EngineResult plain = run_model(setup, cfg);
    const std::string base = "sc_improved2_trace" + std::to_string(form);
    cfg.trace_path = testing::TempDir() + base + ".vcd";
    std::remove(cfg.trace_path.c_str());
    const EngineResult r = run_model(setup, cfg);
    // Tracing changes no cycle and no span.
    ASSERT_EQ(r.cycles.size(), plain.cycles.size());
    for (size_t i = 0; i < r.cycles.size(); ++i) {
      const TriangleCycles &a = r.cycles[i], &b = plain.cycles[i];
      EXPECT_TRUE(a.accept_cycle == b.accept_cycle && a.first_span_cycle == b.first_span_cycle &&
                  a.done_cycle == b.done_cycle && a.handoff_cycle == b.handoff_cycle &&
                  a.walk_end_cycle == b.walk_end_cycle && a.spans == b.spans)
          << "triangle " << i;
    }
    EXPECT_EQ(r.total_cycles, plain.total_cycles);
    EXPECT_TRUE(r.spans == plain.spans);

    const Vcd v = read_vcd(cfg.trace_path);
    EXPECT_EQ(v.top, "improved2");
    EXPECT_TRUE(v.timescale_1ns);
    for (const char* sig : kImproved2Signals) {
      ASSERT_TRUE(v.id_of.count(sig)) << sig << " missing";
      if (form == 0 && std::string(sig) == "corner_unit.digits") continue;  // radix 16 only
      EXPECT_GT(v.values.at(v.id_of.at(sig)).size(), 1u) << sig << " never changes";
    }
    EXPECT_EQ(v.first_time, 0u);
    EXPECT_GE(v.last_time, r.total_cycles - 1);

    // Every span accept of the port is a pop of the CSV, and each triangle's first pop is one.
    const std::vector<uint64_t> takes = rises(v, "span_sink.take");
    const std::vector<uint64_t> accepts = rises(v, "box_stage.tri_accept");
    uint64_t spans = 0;
    size_t checked = 0;
    for (const TriangleCycles& c : r.cycles) {
      spans += c.spans;
      // tri_accept is high in every accept cycle (rises can merge back-to-back accepts).
      EXPECT_EQ(value_at(v, "box_stage.tri_accept", c.accept_cycle), "1") << c.tri;
      if (!c.spans) continue;
      EXPECT_EQ(value_at(v, "span_sink.take", c.first_span_cycle), "1") << c.tri;
      EXPECT_EQ(value_at(v, "span.valid", c.first_span_cycle), "1") << c.tri;
      EXPECT_EQ(value_at(v, "span.tri", c.first_span_cycle), vcd_bin(c.tri)) << c.tri;
      EXPECT_EQ(value_at(v, "span.tri", c.done_cycle), vcd_bin(c.tri)) << c.tri;
      // The walk stage holds it from the hand-off's next cycle to its last row; the job stage
      // in the hand-off cycle; the box stage in the cycle after the accept.
      EXPECT_EQ(value_at(v, "walk_stage.tri", c.walk_start_cycle), vcd_bin(c.tri)) << c.tri;
      EXPECT_EQ(value_at(v, "walk_stage.tri", c.walk_end_cycle), vcd_bin(c.tri)) << c.tri;
      EXPECT_NE(value_at(v, "walk_stage.state", c.walk_end_cycle), "0") << c.tri;
      EXPECT_EQ(value_at(v, "job_stage.tri", c.handoff_cycle), vcd_bin(c.tri)) << c.tri;
      EXPECT_EQ(value_at(v, "box_stage.tri", c.accept_cycle + 1), vcd_bin(c.tri)) << c.tri;
      ++checked;
    }
    EXPECT_GT(checked, 50u);
    EXPECT_LE(takes.size(), spans);
    EXPECT_GT(takes.size(), checked / 2);
    EXPECT_GT(accepts.size(), 0u);
    // The number of cycles with span_sink.take high is the number of spans: sum the high runs.
    {
      uint64_t high = 0, since = 0;
      std::string prev = "0";
      for (const auto& tv : v.values.at(v.id_of.at("span_sink.take"))) {
        if (tv.second == "1" && prev != "1") since = tv.first;
        if (tv.second != "1" && prev == "1") high += tv.first - since;
        prev = tv.second;
      }
      if (prev == "1") high += v.last_time - since;
      EXPECT_EQ(high, spans);
    }

    // The .gtkw beside it: one group per module, in pipeline order; the states by name.
    const std::string gtkw = slurp(testing::TempDir() + base + ".gtkw");
    size_t at = 0;
    for (const char* group : {"box_stage", "corner_stage", "corner_unit", "job_stage", "lane0",
                              "lane1", "lane2", "walk_stage", "span", "span_fifo", "span_sink"}) {
      const size_t p = gtkw.find(std::string("\n-") + group + "\n", at);
      EXPECT_NE(p, std::string::npos) << group;
      if (p != std::string::npos) at = p + 1;
    }
    EXPECT_NE(gtkw.find("[dumpfile] \"" + base + ".vcd\"\n"), std::string::npos);
    EXPECT_NE(gtkw.find("improved2.walk_stage.state[1:0]"), std::string::npos);
    EXPECT_NE(slurp(testing::TempDir() + base + ".walk_state.filter").find("2 StWalkTiny\n"),
              std::string::npos);
    EXPECT_NE(slurp(testing::TempDir() + base + ".corner_run.filter").find("1 RunL\n"),
              std::string::npos);
    // Every module of the statistics has its group (the counters' "walk" is walk_stage).
    for (const auto& [key, value] : r.work)
      for (const char* prefix : {"busy_cycles.", "stall_cycles."}) {
        if (key.rfind(prefix, 0) != 0) continue;
        std::string module = key.substr(std::string(prefix).size());
        if (module == "walk") module = "walk_stage";
        EXPECT_NE(gtkw.find("\n-" + module + "\n"), std::string::npos) << module;
      }
  }
}

// The radix-16 corner unit's runs in the trace: E_L from the cycle the triangle enters C for
// d_L + 1 cycles, E_R (lane boxes) until the values are ready; digits shows the run's count.
TEST(ScImproved2, TraceShowsTheCornerRuns) {
  RasterConfig cfg;
  cfg.improved2.corner_form = 1;
  std::vector<InputTriangle> tris = {InputTriangle{{10.2, 40.7, 12.3}, {10.1, 14.6, 35.2}, 0}};
  const SetupResult setup = setup_scene(tris, cfg);
  cfg.trace_path = testing::TempDir() + "sc_improved2_corner.vcd";
  const EngineResult r = run_model(setup, cfg);
  ASSERT_EQ(r.cycles.size(), 1u);
  const Vcd v = read_vcd(cfg.trace_path);
  // Accepted in 0, in B in 1, moves to C in 1 (C free): RunL from 1, then RunR, Idle when the
  // values are ready; the job stage holds it from the cycle after.
  EXPECT_EQ(value_at(v, "corner_unit.run", 0), "0");
  EXPECT_EQ(value_at(v, "corner_unit.run", 1), "1");
  const auto& run = v.values.at(v.id_of.at("corner_unit.run"));
  ASSERT_GE(run.size(), 4u);  // 0 at $dumpvars, RunL, RunR, Idle
  EXPECT_EQ(run[1], std::make_pair(uint64_t(1), std::string("1")));
  EXPECT_EQ(run[2].second, "10");  // RunR
  EXPECT_EQ(run[3].second, "0");
  const uint64_t dl = std::stoull(value_at(v, "corner_unit.digits", 1), nullptr, 2);
  const uint64_t dr = std::stoull(value_at(v, "corner_unit.digits", run[2].first), nullptr, 2);
  EXPECT_EQ(run[2].first, 1 + 1 + dl);       // k + 1 + d_L
  EXPECT_EQ(run[3].first, 1 + 3 + dl + dr);  // r_C = k + 3 + d_L + d_R
  // C holds the triangle from k + 1 = 2 until it moves to L (L free: in r_C).
  EXPECT_EQ(value_at(v, "corner_stage.busy", 2), "1");
  EXPECT_EQ(value_at(v, "corner_stage.busy", run[3].first), "1");
  EXPECT_EQ(value_at(v, "corner_stage.busy", run[3].first + 1), "0");
  EXPECT_EQ(value_at(v, "job_stage.busy", run[3].first + 1), "1");
  EXPECT_EQ(value_at(v, "job_stage.busy", r.cycles[0].handoff_cycle), "1");
  EXPECT_EQ(value_at(v, "job_stage.busy", r.cycles[0].handoff_cycle + 1), "0");
  // The job is ready when its slowest lane is done: lane e is busy L_e cycles from r_C + 1.
  uint64_t L = 0;
  for (int e = 0; e < 3; ++e) {
    const std::string busy = "lane" + std::to_string(e) + ".busy";
    const std::vector<uint64_t> up = rises(v, busy);
    if (up.empty()) continue;
    EXPECT_EQ(up.front(), run[3].first + 1) << busy;
    const uint64_t Le = v.values.at(v.id_of.at(busy)).back().first - up.front();
    L = std::max(L, Le);
    // Its phases: Slope (or a horizontal edge's Traverse) from r_C + 1, then (an entering edge)
    // Entry for m_e = 2 (saturated) .. Q iterations, Idle when it is done.
    const std::string phase = "lane" + std::to_string(e) + ".phase";
    const auto& ph = v.values.at(v.id_of.at(phase));
    ASSERT_GE(ph.size(), 3u) << phase;
    EXPECT_EQ(ph[1].first, up.front()) << phase;
    EXPECT_TRUE(ph[1].second == "1" || ph[1].second == "11") << phase;
    EXPECT_EQ(ph.back(), std::make_pair(up.front() + Le, std::string("0"))) << phase;
    if (ph.size() == 4) {
      EXPECT_EQ(ph[2].second, "10") << phase;  // Entry
      EXPECT_GE(ph[3].first - ph[2].first, 2u) << phase;
    }
  }
  EXPECT_GT(L, 0u);
  EXPECT_EQ(r.cycles[0].setup_done_cycle, run[3].first + 1 + L);
}

// --trace-tris: the trace starts in the cycle the window's first triangle is on the port (the
// cycle after its predecessor's accept, as the RTL's trace does), holds the values the run has
// there (a triangle already in the unit), and ends by the window's last done.
TEST(ScImproved2, TraceWindow) {
  RasterConfig cfg;
  const SetupResult setup = builtin_setup("mixed", cfg);
  const EngineResult plain = run_model(setup, cfg);
  cfg.trace_path = testing::TempDir() + "sc_improved2_window.vcd";
  cfg.trace_first = 3000;
  cfg.trace_last = 3099;
  const EngineResult r = run_model(setup, cfg);
  EXPECT_EQ(r.total_cycles, plain.total_cycles);
  uint64_t lo = ~uint64_t(0), acc = ~uint64_t(0), hi = 0;
  size_t pos = r.cycles.size();  // the window's first triangle (setup order)
  for (size_t i = 0; i < r.cycles.size(); ++i) {
    const TriangleCycles& c = r.cycles[i];
    if (c.tri >= 3000 && c.tri <= 3099) {
      if (pos == r.cycles.size()) pos = i;
      hi = std::max(hi, c.done_cycle);
    }
  }
  ASSERT_GT(pos, 0u);
  ASSERT_LT(pos, r.cycles.size());
  lo = r.cycles[pos - 1].accept_cycle + 1;  // on the port from here
  acc = r.cycles[pos].accept_cycle;
  ASSERT_LT(lo, hi);
  const Vcd v = read_vcd(cfg.trace_path);
  EXPECT_EQ(v.first_time, lo);
  EXPECT_LE(v.last_time, hi + 1);
  // The values in the window's first accept are the run's: the triangle accepted there is the
  // port's, and the box stage still holds the one before it (it leaves B in that cycle).
  EXPECT_EQ(value_at(v, "box_stage.tri_accept", acc), "1");
  EXPECT_EQ(value_at(v, "box_stage.tri", acc), vcd_bin(r.cycles[pos - 1].tri));
  EXPECT_EQ(value_at(v, "box_stage.busy", acc), "1");
  size_t checked = 0;
  for (const TriangleCycles& c : r.cycles)
    if (c.tri >= 3000 && c.tri <= 3099 && c.spans) {
      EXPECT_EQ(value_at(v, "span.tri", c.first_span_cycle), vcd_bin(c.tri)) << c.tri;
      EXPECT_EQ(value_at(v, "span_sink.take", c.first_span_cycle), "1") << c.tri;
      ++checked;
    }
  EXPECT_GT(checked, 10u);
  // Nothing after the window: no change stamped past hi + 1.
  for (const auto& [id, ch] : v.values)
    for (const auto& tv : ch) EXPECT_LE(tv.first, hi + 1) << id;
}

// A .fst trace is a real FST (gtkwave's vcd2fst converts the VCD), read back by fst2vcd with the
// unit's scopes, with its .gtkw beside it.
TEST(ScImproved2, TraceAsFst) {
  if (std::system("command -v vcd2fst >/dev/null 2>&1 && command -v fst2vcd >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "gtkwave's vcd2fst / fst2vcd not installed";
  RasterConfig cfg;
  const SetupResult setup = builtin_setup("lowpoly-far", cfg);
  const std::string base = testing::TempDir() + "sc_improved2_fst";
  cfg.trace_path = base + ".fst";
  std::remove(cfg.trace_path.c_str());
  run_model(setup, cfg);
  const std::string fst = slurp(cfg.trace_path);
  ASSERT_FALSE(fst.empty());
  EXPECT_NE(fst[0], '$') << "the .fst holds VCD text";
  ASSERT_EQ(
      std::system(
          ("fst2vcd -f " + cfg.trace_path + " -o " + base + ".back.vcd >/dev/null 2>&1").c_str()),
      0);
  const Vcd v = read_vcd(base + ".back.vcd");
  EXPECT_EQ(v.top, "improved2");
  EXPECT_TRUE(v.id_of.count("corner_unit.run"));
  EXPECT_TRUE(v.id_of.count("walk_stage.row"));
  EXPECT_NE(slurp(base + ".gtkw").find("[dumpfile] \"sc_improved2_fst.fst\""), std::string::npos);
}

}  // namespace
}  // namespace trirast
