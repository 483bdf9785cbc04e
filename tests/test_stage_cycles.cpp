// Finding why a triangle is slow: the stage breakdown of the --cycles CSV read back
// against the engine run in process, compare's --explain / --slowest lines checked against the
// cycles they describe, --export-tris reproducing the same set-up triangles and spans, and the
// --heatmap PNG. Every expectation is computed here from an in-process run, not stored.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/slowest.hpp"
#include "common/setup.hpp"
#include "engines.hpp"
#include "io/cycles_file.hpp"
#include "common/cycle_columns.hpp"
#include "scene/scene.hpp"
#include "support/run_command.hpp"

namespace trirast {
namespace {

using test::CommandResult;
using test::run_command;
using test::TempDir;

const std::string kBin = TRIRAST_BIN;

// A scene whose triangles wait for the walk stage (many small triangles behind large ones).
const char* const kScene = "builtin:mixed";
const char* const kView = " --width 320 --height 240";

RasterConfig view_cfg() {
  RasterConfig cfg;
  cfg.width = 320;
  cfg.height = 240;
  return cfg;
}

EngineResult run_in_process(const std::string& engine, const SetupResult& setup, const RasterConfig& cfg) {
  EngineResult r;
  find_engine(engine)->make()->run(setup, cfg, r);
  return r;
}

SetupResult setup_of(const std::string& scene, const RasterConfig& cfg) {
  return setup_scene(load_scene(scene, cfg, CameraOptions{}).tris, cfg);
}

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

TEST(CliStageCycles, CsvKeepsItsColumnsAndAppendsTheBreakdown) {
  TempDir dir;
  for (const char* engine : {"improved-sc", "trad-sc"}) {
    const std::string csv = dir.file(std::string(engine) + ".csv");
    CommandResult r = run_command(kBin + " raster --scene " + kScene + kView + " --engine " + engine +
                                  " --cycles " + csv);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string text = slurp(csv);
    EXPECT_EQ(text.substr(0, text.find('\n')),
              "tri,accept_cycle,first_span_cycle,done_cycle,spans,pixels,stall_cycles,"
              "setup_start_cycle,setup_done_cycle,handoff_cycle,walk_start_cycle,walk_end_cycle,"
              "divider_iterations,boundary_steps,box_width,box_height");
    const std::vector<TriangleCycles> rows = read_cycles_file(csv);
    const RasterConfig cfg = view_cfg();
    const EngineResult in = run_in_process(engine, setup_of(kScene, cfg), cfg);
    ASSERT_EQ(rows.size(), in.cycles.size());
    size_t held = 0, walked = 0;
    for (size_t p = 0; p < rows.size(); ++p) {
      const TriangleCycles& c = rows[p];
      ASSERT_TRUE(test::same_cycles(c, in.cycles[p])) << test::cycles_row(c);
      // The contract's order of events (docs/timing.md, "Outputs").
      EXPECT_EQ(c.setup_start_cycle, c.accept_cycle + 1) << c.tri;
      EXPECT_LE(c.setup_done_cycle, c.handoff_cycle) << c.tri;
      if (c.walk_start_cycle == c.handoff_cycle + 1) {
        ++walked;
        EXPECT_GE(c.walk_end_cycle, c.walk_start_cycle) << c.tri;
        // Its first span is pushed in a walk cycle and popped later (rows after its last span
        // may keep the walk stage busy past done_cycle).
        if (c.spans > 0) {
          EXPECT_GT(c.first_span_cycle, c.walk_start_cycle) << c.tri;
        }
        EXPECT_GE(c.walk_end_cycle + 1 - c.walk_start_cycle, c.stall_cycles) << c.tri;
        EXPECT_GT(c.box_width * c.box_height, 0u) << c.tri;
        if (std::string(engine) == "improved-sc") {
          EXPECT_GT(c.divider_iterations, 0u) << c.tri;
        }
        held += c.handoff_cycle > c.setup_done_cycle;
      } else {
        EXPECT_EQ(c.walk_end_cycle, c.accept_cycle + 1) << c.tri;
        EXPECT_EQ(c.box_width, 0u) << c.tri;
      }
    }
    EXPECT_GT(walked, 100u) << engine;
    EXPECT_GT(held, 10u) << engine << ": the scene must hold triangles waiting for the walk stage";
  }
}

// The line --explain prints for a triangle that waited for the walk stage names the triangle
// the walk stage held and the cycle it held it until, and both are right: that triangle's walk
// ended in that cycle, and the explained one was handed off the cycle after.
TEST(CliStageCycles, ExplainNamesWhatATriangleWaitedFor) {
  const RasterConfig cfg = view_cfg();
  const EngineResult in = run_in_process("improved-sc", setup_of(kScene, cfg), cfg);
  // The triangle that waited longest in StHold.
  size_t worst = 0;
  uint64_t worst_hold = 0;
  for (size_t p = 0; p < in.cycles.size(); ++p) {
    const TriangleCycles& c = in.cycles[p];
    if (c.walk_start_cycle == c.handoff_cycle + 1 && c.handoff_cycle - c.setup_done_cycle > worst_hold) {
      worst_hold = c.handoff_cycle - c.setup_done_cycle;
      worst = p;
    }
  }
  ASSERT_GT(worst_hold, 0u);
  const TriangleCycles& c = in.cycles[worst];
  size_t prev = worst;
  while (prev-- > 0)
    if (in.cycles[prev].walk_start_cycle == in.cycles[prev].handoff_cycle + 1) break;
  ASSERT_LT(prev, worst);
  EXPECT_EQ(in.cycles[prev].walk_end_cycle, c.handoff_cycle - 1);  // what the line must say

  CommandResult r = run_command(kBin + " compare --scene " + kScene + kView +
                                " --engines improved-sc,improved-rtl --explain " + std::to_string(c.tri));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string want = std::to_string(worst_hold) + " cycles in StHold: walk stage busy with triangle " +
                           std::to_string(in.cycles[prev].tri) + " until cycle " +
                           std::to_string(c.handoff_cycle - 1);
  const std::string head = "triangle " + std::to_string(c.tri) + ": " +
                           std::to_string(c.done_cycle - c.accept_cycle) + " cycles (accept " +
                           std::to_string(c.accept_cycle) + ", done " + std::to_string(c.done_cycle);
  size_t lines = 0;
  std::istringstream out(r.out);
  for (std::string line; std::getline(out, line);)
    if (line.find(head) != std::string::npos) {
      ++lines;
      EXPECT_NE(line.find(want), std::string::npos) << line << "\nwanted: " << want;
      EXPECT_NE(line.find("divider: " + std::to_string(c.divider_iterations) + " iterations"),
                std::string::npos)
          << line;
      EXPECT_NE(line.find("hand-off " + std::to_string(c.handoff_cycle)), std::string::npos) << line;
    }
  EXPECT_EQ(lines, 2u) << "one line for improved-sc, one for improved-rtl:\n" << r.out;
  EXPECT_NE(r.out.find("per-triangle cycles: improved-sc = improved-rtl agree on all 16 columns"), std::string::npos)
      << r.out;
}

TEST(CliStageCycles, SlowestNamesTheTrianglesWithTheMostCycles) {
  const RasterConfig cfg = view_cfg();
  const EngineResult in = run_in_process("trad-sc", setup_of(kScene, cfg), cfg);
  const std::vector<size_t> slow = slowest_triangles(in.cycles, 3);
  ASSERT_EQ(slow.size(), 3u);
  for (const TriangleCycles& c : in.cycles) EXPECT_LE(latency(c), latency(in.cycles[slow[0]]));
  TempDir dir;
  CommandResult r = run_command(kBin + " compare --scene " + kScene + kView +
                                " --engines trad-sc,trad-rtl --slowest 3 --cycles " + dir.file("j.csv"));
  ASSERT_EQ(r.status, 0) << r.err;
  size_t at = r.out.find("slowest 3 triangles of trad-sc");
  ASSERT_NE(at, std::string::npos) << r.out;
  for (size_t p : slow) {
    const std::string head = "triangle " + std::to_string(in.cycles[p].tri) + ": " +
                             std::to_string(latency(in.cycles[p])) + " cycles";
    const size_t next = r.out.find(head, at);
    ASSERT_NE(next, std::string::npos) << head << "\n" << r.out;
    at = next;  // in order, slowest first
  }
  // The joined file: both engines' columns, no mismatch.
  const std::string joined = slurp(dir.file("j.csv"));
  EXPECT_EQ(joined.rfind("tri,trad-sc.accept_cycle,", 0), 0u);
  EXPECT_NE(joined.find("trad-rtl.box_height,mismatch\n"), std::string::npos);
  EXPECT_EQ(std::count(joined.begin(), joined.end(), '\n'), std::ptrdiff_t(in.cycles.size() + 1));
  EXPECT_EQ(joined.find("!="), std::string::npos);
}

// A flagged mismatch: two runs of one unit whose rows differ.
TEST(CliStageCycles, JoinedCyclesFlagAMismatch) {
  std::vector<TriangleCycles> a(2), b(2);
  a[0].tri = b[0].tri = 4;
  a[1].tri = b[1].tri = 9;
  b[1].handoff_cycle = 7;
  std::string first;
  const std::vector<TimedCycles> runs = {{"improved-sc", &a}, {"improved-rtl", &b}};
  EXPECT_EQ(count_cycle_mismatches(runs, first), 1u);
  EXPECT_EQ(first, "triangle 9 handoff_cycle: improved-rtl 7, improved-sc 0");
  const std::string csv = joined_cycles_csv(runs);
  EXPECT_NE(csv.find(",improved-rtl!=improved-sc\n"), std::string::npos) << csv;
  // Different units are not compared.
  const std::vector<TimedCycles> units = {{"improved-sc", &a}, {"trad-sc", &b}};
  EXPECT_EQ(count_cycle_mismatches(units, first), 0u);
  // The half-space unit's model and RTL are one unit.
  const std::vector<TimedCycles> hs = {{"halfspace-sc", &a}, {"halfspace-rtl", &b}};
  EXPECT_EQ(count_cycle_mismatches(hs, first), 1u);
  EXPECT_EQ(timing_unit("halfspace-rtl"), timing_unit("halfspace-sc"));
  // And the second-generation unit's; a datapath view has no cycles to hold against them.
  const std::vector<TimedCycles> g2 = {{"improved2-sc", &a}, {"improved2-rtl", &b}};
  EXPECT_EQ(count_cycle_mismatches(g2, first), 1u);
  EXPECT_EQ(timing_unit("improved2-rtl"), "improved2");
  EXPECT_EQ(timing_unit("improved2-datapath"), "improved2-datapath");
}

TEST(CliStageCycles, ExportedWindowSetsUpTheSameTrianglesAndSpans) {
  TempDir dir;
  const RasterConfig cfg = view_cfg();
  const SetupResult full = setup_of(kScene, cfg);
  ASSERT_GT(full.tris.size(), 400u);
  const uint32_t a = full.tris[100].index, b = full.tris[300].index;
  const std::string tri = dir.file("w.tri");
  CommandResult r = run_command(kBin + " raster --scene " + kScene + kView + " --spans " +
                                dir.file("all.spans") + " --export-tris " + std::to_string(a) + ":" +
                                std::to_string(b) + ":" + tri);
  ASSERT_EQ(r.status, 0) << r.err;
  const SetupResult part = setup_of(tri, cfg);
  std::vector<const TriangleSetup*> window;
  for (const TriangleSetup& t : full.tris)
    if (t.index >= a && t.index <= b) window.push_back(&t);
  ASSERT_EQ(part.tris.size(), window.size());
  for (size_t i = 0; i < window.size(); ++i) {
    const TriangleSetup &x = part.tris[i], &y = *window[i];
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(x.v[k].x, y.v[k].x) << y.index;
      EXPECT_EQ(x.v[k].y, y.v[k].y) << y.index;
      EXPECT_EQ(x.edge[k].A, y.edge[k].A) << y.index;
      EXPECT_EQ(x.edge[k].B, y.edge[k].B) << y.index;
      EXPECT_EQ(x.edge[k].C, y.edge[k].C) << y.index;
      EXPECT_EQ(x.edge[k].bias, y.edge[k].bias) << y.index;
    }
    EXPECT_EQ(x.swapped, y.swapped) << y.index;
  }
  // Rasterizing the file gives the window's spans, triangle k of the file being window[k].
  r = run_command(kBin + " raster --scene " + tri + kView + " --engine improved-sc --spans " + dir.file("w.spans"));
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<std::string> want, got;
  {
    std::ifstream f(dir.file("all.spans"));
    for (std::string line; std::getline(f, line);) {
      std::istringstream ls(line);
      uint32_t t;
      ls >> t;
      if (t >= a && t <= b) want.push_back(line);
    }
    std::ifstream g(dir.file("w.spans"));
    for (std::string line; std::getline(g, line);) {
      std::istringstream ls(line);
      size_t k;
      ls >> k;
      std::string rest;
      std::getline(ls, rest);
      ASSERT_LT(k, window.size());
      got.push_back(std::to_string(window[k]->index) + rest);
    }
  }
  std::sort(want.begin(), want.end());
  std::sort(got.begin(), got.end());
  EXPECT_GT(want.size(), 100u);
  EXPECT_EQ(got, want);
}

TEST(CliStageCycles, HeatmapIsAPngWithALegendBelowTheViewport) {
  TempDir dir;
  for (const char* metric : {"cycles", "stalls", "setup"}) {
    const std::string png = dir.file(std::string(metric) + ".png");
    CommandResult r = run_command(kBin + " raster --scene " + kScene + kView +
                                  " --engine improved-sc --sink-stall periodic:1:1 --heatmap " + metric + ":" + png);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string data = slurp(png);
    ASSERT_GT(data.size(), 24u);
    EXPECT_EQ(data.substr(1, 3), "PNG");
    auto be32 = [&](size_t at) {
      return (uint32_t(uint8_t(data[at])) << 24) | (uint32_t(uint8_t(data[at + 1])) << 16) |
             (uint32_t(uint8_t(data[at + 2])) << 8) | uint32_t(uint8_t(data[at + 3]));
    };
    EXPECT_GE(be32(16), 320u);  // the viewport, or the legend when it is wider
    EXPECT_GT(be32(20), 240u);  // the viewport, then the legend
  }
  CommandResult bad = run_command(kBin + " raster --scene " + kScene + kView +
                                  " --engine golden --heatmap cycles:" + dir.file("g.png"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--heatmap: engine 'golden' is not timed"), std::string::npos) << bad.err;
  CommandResult worse = run_command(kBin + " raster --scene " + kScene + kView +
                                    " --engine improved-sc --heatmap pixels:" + dir.file("g.png"));
  EXPECT_EQ(worse.status, 2);
  EXPECT_NE(worse.err.find("--heatmap: expected cycles:FILE.png"), std::string::npos) << worse.err;
}

}  // namespace
}  // namespace trirast
