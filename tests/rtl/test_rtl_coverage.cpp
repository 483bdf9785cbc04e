// The RTL's cover points (docs/coverage.md; rtl/common/trirast_assert.svh `COVER): the counts the
// cycle loop reads from the Verilated model's coverage database after each run
// (tb/common/rtl_coverage.hpp). The count semantics (one per rising edge at which the property
// held, per instance, summed over runs), points a scene cannot reach at 0, and every point of
// every unit's RTL present in its engine's counts.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/rtl_coverage.hpp"
#include "halfspace/halfspace_rtl_engine.hpp"
#include "improved/improved_rtl_engine.hpp"
#include "improved2/improved2_rtl_engine.hpp"
#include "trad/trad_rtl_engine.hpp"
#include "support/rtl_helpers.hpp"
#include "support/scene_helpers.hpp"

namespace trirast {
namespace {

using test::tri;
using Counts = std::map<std::string, uint64_t>;

// The checked builds: the speed builds have no cover points.
RasterConfig default_cfg() {
  RasterConfig cfg;
  cfg.rtl_checked = true;
  cfg.validate();
  return cfg;
}

// Five small triangles inside the default viewport: every box is non-empty, the largest box is
// 13 pixels wide (adaptive divisions: m = bits(Xmax) + 1 <= 5).
std::vector<InputTriangle> small_scene() {
  return {tri(10.2, 10.1, 20.7, 12.3, 14.4, 19.8), tri(40.5, 40.5, 52.25, 44.0, 45.0, 50.5),
          tri(100.1, 5.3, 103.9, 6.2, 101.0, 9.7), tri(60.0, 80.0, 70.0, 80.5, 61.0, 92.0),
          tri(30.3, 60.6, 31.9, 61.1, 30.8, 62.4)};
}

Counts run_improved(const std::vector<InputTriangle>& tris, const RasterConfig& cfg,
                    size_t* accepted = nullptr) {
  rtl::reset_rtl_coverage();
  const SetupResult setup = setup_scene(tris, cfg);
  if (accepted) *accepted = setup.tris.size();
  test::run_verilated(rtl::run_rtl, setup, cfg, 1);
  return rtl::rtl_coverage_counts()["improved-rtl"];
}

uint64_t at(const Counts& c, const std::string& name) {
  auto it = c.find(name);
  if (it == c.end()) throw std::runtime_error("no cover point " + name);
  return it->second;
}

TEST(RtlCoverage, BuiltWithCoverPoints) { EXPECT_TRUE(rtl::rtl_coverage_built()); }

// A cover point counts the rising edges at which its property held: the setup FSM spends exactly
// one cycle in StBox and one in StEdge per triangle (docs/timing.md), and the port accepts each
// triangle once.
TEST(RtlCoverage, CountsAreCyclesThePropertyHeld) {
  size_t n = 0;
  const Counts c = run_improved(small_scene(), default_cfg(), &n);
  ASSERT_EQ(n, 5u);
  EXPECT_EQ(at(c, "u_setup.TriAccept_C"), n);
  EXPECT_EQ(at(c, "u_setup.SetupStBox_C"), n);
  EXPECT_EQ(at(c, "u_setup.SetupStEdge_C"), n);
  EXPECT_GT(at(c, "u_setup.SetupStLanes_C"), 0u);
  // No box is empty: nothing retires in StBox.
  EXPECT_EQ(at(c, "u_setup.SetupEmptyBoxRetired_C"), 0u);
  // Counts add up over runs (the report merges them).
  const SetupResult setup = setup_scene(small_scene(), default_cfg());
  test::run_verilated(rtl::run_rtl, setup, default_cfg(), 2);
  EXPECT_EQ(at(rtl::rtl_coverage_counts()["improved-rtl"], "u_setup.TriAccept_C"), 2 * n);
}

// One triangle between pixel centres (its box holds none) retires in StBox: the point that was
// 0 above counts it.
TEST(RtlCoverage, EmptyBoxRetiredCountsTheRetirement) {
  std::vector<InputTriangle> tris = small_scene();
  tris.push_back(tri(70.6, 10.6, 70.9, 10.6, 70.6, 10.9));
  const RasterConfig cfg = default_cfg();
  const SetupResult setup = setup_scene(tris, cfg);
  ASSERT_EQ(setup.tris.size(), 6u) << "the set-up dropped the triangle without a pixel centre";
  const Counts c = run_improved(tris, cfg);
  EXPECT_EQ(at(c, "u_setup.SetupEmptyBoxRetired_C"), 1u);
  EXPECT_EQ(at(c, "u_setup.SetupStEdge_C"), 5u);
}

// The divider's iteration count: fixed mode runs m = Q every division, adaptive mode on these
// small boxes m <= 5.
TEST(RtlCoverage, DividerLengthsFollowTheDividerMode) {
  RasterConfig fixed = default_cfg();
  fixed.divider = DividerMode::Fixed;
  RasterConfig adaptive = default_cfg();
  adaptive.divider = DividerMode::Adaptive;
  const Counts f = run_improved(small_scene(), fixed);
  const Counts a = run_improved(small_scene(), adaptive);
  {
    // The three lanes' instances are one point (Verilator's database merges a generate loop's
    // instances: g_edge[*]).
    const std::string lane = "u_setup.g_edge[*].u_lane.u_divider.";
    EXPECT_GT(at(f, lane + "DivLenQ_C"), 0u);
    EXPECT_EQ(at(f, lane + "DivLen2to4_C") + at(f, lane + "DivLen5to8_C") +
                  at(f, lane + "DivLen9toQm1_C"), 0u);
    EXPECT_EQ(at(a, lane + "DivLenQ_C") + at(a, lane + "DivLen9toQm1_C"), 0u);
    EXPECT_GT(at(a, lane + "DivLen2to4_C") + at(a, lane + "DivLen5to8_C"), 0u);
  }
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The labels of the `COVER points in a unit's RTL (its file list, rtl/UNIT/trirast_UNIT.f), with
// those of the check macros of rtl/common/trirast_assert.svh it uses (`TRIRAST_SPAN_PORT_CHECKS).
std::set<std::string> cover_labels(const std::string& unit) {
  const std::string common = std::string(TRIRAST_SOURCE_DIR) + "/rtl/common/";
  const std::string dir = std::string(TRIRAST_SOURCE_DIR) + "/rtl/" + unit + "/";
  const std::regex cover(R"(`COVER\((\w+),)");
  auto labels_in = [&](const std::string& s, std::set<std::string>& labels) {
    for (std::sregex_iterator it(s.begin(), s.end(), cover), end; it != end; ++it)
      labels.insert((*it)[1]);
  };
  // A macro's points: the `COVER lines of its definition (up to the line without a backslash).
  std::map<std::string, std::set<std::string>> macro_labels;
  {
    const std::string header = read_text(common + "trirast_assert.svh");
    const std::regex define(R"(`define (TRIRAST_\w+)\()");
    for (std::sregex_iterator it(header.begin(), header.end(), define), end; it != end; ++it) {
      size_t stop = size_t(it->position());
      while ((stop = header.find('\n', stop)) != std::string::npos && header[stop - 1] == '\\') ++stop;
      labels_in(header.substr(size_t(it->position()), stop - size_t(it->position())),
                macro_labels[(*it)[1]]);
    }
  }
  std::ifstream list(dir + "trirast_" + unit + ".f");
  std::set<std::string> labels;
  std::string file;
  while (std::getline(list, file)) {
    if (file.empty() || file.compare(0, 2, "//") == 0) continue;
    const std::string s = read_text(dir + file);
    labels_in(s, labels);
    for (const auto& [name, points] : macro_labels)
      if (s.find("`" + name + "(") != std::string::npos) labels.insert(points.begin(), points.end());
  }
  return labels;
}

// Every point written in a unit's RTL appears in its engine's counts (the report lists them all),
// after one run of each build variant that has its own points (improved2: both corner forms).
TEST(RtlCoverage, EveryCoverPointOfEveryUnitIsCounted) {
  rtl::reset_rtl_coverage();
  const RasterConfig cfg = default_cfg();
  const SetupResult setup = setup_scene(small_scene(), cfg);
  test::run_verilated(rtl::run_rtl, setup, cfg, 1);
  test::run_verilated(rtl::run_rtl_trad, setup, cfg, 1);
  for (int form : {0, 1}) {
    RasterConfig c2 = cfg;
    c2.improved2.corner_form = form;
    test::run_verilated(rtl::run_rtl_improved2, setup, c2, 1);
  }
  EngineResult hs;
  rtl::run_rtl_halfspace(setup, cfg, 1, hs);
  const auto counts = rtl::rtl_coverage_counts();
  for (const std::string unit : {"improved", "trad", "improved2", "halfspace"}) {
    SCOPED_TRACE(unit);
    const std::set<std::string> labels = cover_labels(unit);
    EXPECT_GE(labels.size(), 10u);
    auto it = counts.find(unit + "-rtl");
    ASSERT_NE(it, counts.end());
    std::set<std::string> counted;
    for (const auto& [name, count] : it->second)
      counted.insert(name.substr(name.rfind('.') + 1));
    for (const std::string& label : labels) EXPECT_TRUE(counted.count(label)) << label;
    for (const std::string& label : counted) EXPECT_TRUE(labels.count(label)) << label;
  }
  uint64_t hit = 0, total = 0;
  const std::string report =
      rtl::rtl_coverage_report({"improved-rtl", "trad-rtl", "improved2-rtl", "halfspace-rtl"},
                               "test", hit, total);
  uint64_t points = 0;
  for (const auto& [engine, c] : counts) points += c.size();
  EXPECT_EQ(total, points);
  EXPECT_GT(hit, 0u);
  EXPECT_LT(hit, total);  // a scene of five small triangles leaves points unhit
  EXPECT_NE(report.find("| improved-rtl | `u_setup.TriAccept_C` | 5 |"), std::string::npos);
  EXPECT_NE(report.find("coverage: " + std::to_string(hit) + " of " + std::to_string(total) +
                        " cover points hit"),
            std::string::npos);
}

TEST(RtlCoverage, ParseNamesPointsBelowTheUnitTop) {
  // Verilator's form: 'h' ends in the label; other pages (line, toggle coverage) are left out.
  const auto p = rtl::parse_coverage_dat(
      "C '\001t\002user\001page\002v_user/m\001h\002t.top_sim.u_dut.u_a.Q_C\001o\002Q_C' 3\n"
      "C '\001page\002v_line/m\001h\002t.top_sim.u_dut.u_a\001o\002L' 9\n"
      "C '\001page\002v_user/m\001h\002t.top_sim.u_dut.g__BRA__*__KET__.R_C\001o\002R_C' 4\n",
      "t");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p.at("u_a.Q_C"), 3u);
  EXPECT_EQ(p.at("g[*].R_C"), 4u);
}

TEST(RtlCoverage, ParseRejectsAMalformedLineNamingIt) {
  EXPECT_EQ(rtl::parse_coverage_dat("# comment\nC '\001page\002v_user/x\001h\002TOP.u_dut.u_a"
                                    "\001o\002P_C' 7\n",
                                    "t")
                .at("u_a.P_C"),
            7u);
  try {
    rtl::parse_coverage_dat("# ok\nX nothing\n", "f.dat");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("f.dat:2: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace trirast
