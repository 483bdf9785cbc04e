// The speed builds (docs/rtl.md, "Speed and checked builds"; cmake/trirast_rtl_builds.cmake): the
// builds a default run picks also exist without assertions, cover points and trace support. A
// run takes them unless RasterConfig::rtl_checked or a trace asks for the checked one; either way
// the spans, the per-triangle cycles and the work counters are the same.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <string>

#include "common/cycle_columns.hpp"
#include "common/gtkw_save.hpp"
#include "common/rtl_builds.hpp"
#include "halfspace/halfspace_rtl_engine.hpp"
#include "improved2/improved2_rtl_engine.hpp"
#include "trad/trad_rtl_engine.hpp"
#include "support/rtl_helpers.hpp"

namespace trirast {
namespace {

using Run = void (*)(const SetupResult&, const RasterConfig&, uint32_t, EngineResult&);

void run_improved(const SetupResult& s, const RasterConfig& c, uint32_t seed, EngineResult& o) {
  rtl::run_rtl(s, c, {seed}, o);
}
void run_trad(const SetupResult& s, const RasterConfig& c, uint32_t seed, EngineResult& o) {
  rtl::run_rtl_trad(s, c, {seed}, o);
}
void run_improved2(const SetupResult& s, const RasterConfig& c, uint32_t seed, EngineResult& o) {
  rtl::run_rtl_improved2(s, c, {seed}, o);
}

struct Unit {
  const char* name;
  Run run;
  const std::vector<rtl::RtlBuild>& (*builds)();
};
const Unit kUnits[] = {{"improved", run_improved, rtl::improved_builds},
                       {"trad", run_trad, rtl::trad_builds},
                       {"improved2", run_improved2, rtl::improved2_builds},
                       {"halfspace", rtl::run_rtl_halfspace, rtl::halfspace_builds}};

// The run's work without the counters that differ by build or by time.
std::map<std::string, uint64_t> comparable_work(std::map<std::string, uint64_t> w) {
  for (const char* k : {"rtl_build_checked", "sim_wall_microseconds", "sim_cpu_microseconds",
                        "sim_cycles_per_second", "sim_cycles_per_cpu_second"})
    w.erase(k);
  return w;
}

// Every unit has one speed build, of the default widths and N = 1; improved2 and the half-space
// unit one per corner form (1 radix 16, 0 products).
TEST(RtlSpeedBuild, DefaultBuildsHaveOne) {
  for (const Unit& u : kUnits) {
    SCOPED_TRACE(u.name);
    std::map<int, int> per_corner_form;
    for (const rtl::RtlBuild& b : u.builds())
      if (b.run_speed) {
        ++per_corner_form[b.corner_form];
        EXPECT_EQ(b.subpixel_bits, 8);
        EXPECT_EQ(b.endpoints, 1);
      }
    const std::map<int, int> expected =
        std::string(u.name) == "improved2" || std::string(u.name) == "halfspace"
            ? std::map<int, int>{{0, 1}, {1, 1}}
            : std::map<int, int>{{0, 1}};
    EXPECT_EQ(per_corner_form, expected);
  }
}

// The speed build and the checked build agree on every span, every column of every triangle's
// cycles and every work counter; rtl_build_checked says which ran.
void expect_builds_agree(const Unit& u, const SetupResult& setup, const RasterConfig& cfg) {
  EngineResult speed, checked;
  u.run(setup, cfg, 1, speed);
  RasterConfig c2 = cfg;
  c2.rtl_checked = true;
  u.run(setup, c2, 1, checked);
  EXPECT_EQ(speed.work.at("rtl_build_checked"), 0u);
  EXPECT_EQ(checked.work.at("rtl_build_checked"), 1u);
  ASSERT_GT(speed.spans.size(), 1000u);
  EXPECT_TRUE(speed.spans == checked.spans)
      << test::first_span_difference(speed.spans, "speed", checked.spans, "checked");
  ASSERT_EQ(speed.cycles.size(), checked.cycles.size());
  std::string report;
  EXPECT_EQ(test::cycle_rows_mismatch(speed.cycles, "speed", checked.cycles, "checked",
                                      u.name, report),
            0u)
      << report;
  EXPECT_EQ(speed.total_cycles, checked.total_cycles);
  EXPECT_EQ(comparable_work(speed.work), comparable_work(checked.work));
}

// mixed at the default configuration, every unit.
TEST(RtlSpeedBuild, SpeedAndCheckedBuildsAgree) {
  RasterConfig cfg;
  cfg.validate();
  const SetupResult setup = test::scene("builtin:mixed", cfg);
  for (const Unit& u : kUnits) {
    SCOPED_TRACE(u.name);
    expect_builds_agree(u, setup, cfg);
  }
}

// The other corner form of improved2 (products) and of the half-space unit (radix 16) has a
// speed build of its own.
TEST(RtlSpeedBuild, OtherCornerFormBuildsAgree) {
  RasterConfig cfg;
  cfg.improved2.corner_form = 0;
  cfg.halfspace.corner_form = 1;
  cfg.validate();
  const SetupResult setup = test::scene("builtin:mixed", cfg);
  expect_builds_agree(kUnits[2], setup, cfg);
  expect_builds_agree(kUnits[3], setup, cfg);
}

// A traced run takes the checked build (the speed build has no trace support); a configuration
// no speed build covers (FIFO depth 16) takes a checked build too.
TEST(RtlSpeedBuild, TraceAndOtherConfigurationsTakeTheCheckedBuild) {
  RasterConfig cfg;
  cfg.validate();
  const SetupResult setup = test::scene("builtin:lowpoly-far", cfg);
  const std::string trace = (std::filesystem::temp_directory_path() /
                             ("rtl_speed_build_" + std::to_string(::getpid()) + ".fst"))
                                .string();
  RasterConfig traced = cfg;
  traced.trace_path = trace;
  traced.trace_last = 1;
  EngineResult r;
  run_improved(setup, traced, 1, r);
  EXPECT_EQ(r.work.at("rtl_build_checked"), 1u);
  EXPECT_TRUE(std::filesystem::exists(trace));
  std::filesystem::remove(trace);
  std::filesystem::remove(gtkw_path_of(trace));
  RasterConfig deep = cfg;
  deep.fifo_depth = 16;
  EngineResult d;
  run_improved(setup, deep, 1, d);
  EXPECT_EQ(d.work.at("rtl_build_checked"), 1u);
}

}  // namespace
}  // namespace trirast
