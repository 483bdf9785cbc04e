// The VCD of the SystemC models read back: the documented signals exist and change, the values
// agree with the cycles, the .gtkw beside it groups the signals by module, and --trace-tris keeps
// the trace of a 100,000-triangle scene small.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <string>
#include <vector>

#include "common/setup.hpp"
#include "improved/improved_sc.hpp"
#include "trad/trad_sc.hpp"
#include "scene/scene.hpp"
#include "support/run_command.hpp"
#include "support/vcd_reader.hpp"

namespace trirast {
namespace {

using test::read_vcd;
using test::slurp;
using test::value_at;
using test::Vcd;
using test::vcd_bin;

uint64_t file_size(const std::string& path) {
  struct stat st {};
  return stat(path.c_str(), &st) == 0 ? uint64_t(st.st_size) : 0;
}

const char* kDocumented[] = {"setup.tri",  "setup.state",    "setup.tri_accept", "walk.tri",
                             "walk.state", "walk.stall",     "walk.row",         "span.valid",
                             "span.ready", "span.tri",       "span.y",           "span.x_begin",
                             "span.x_end", "span_fifo.count"};

TEST(ScTrace, DocumentedSignalsExistAndChange) {
  for (bool trad : {false, true}) {
    RasterConfig cfg;
    cfg.trace_path = testing::TempDir() + (trad ? "sc_trace_trad.vcd" : "sc_trace_model.vcd");
    cfg.fifo_depth = 2;
    cfg.sink_stall = "periodic:2:3";  // stalls, so walk.stall and span.ready change
    const Scene scene = make_builtin("mixed:objects=2", cfg, CameraOptions{});
    const SetupResult setup = setup_scene(scene.tris, cfg);
    EngineResult r;
    (trad ? make_trad_sc_engine() : make_improved_sc_engine())->run(setup, cfg, r);
    Vcd v = read_vcd(cfg.trace_path);
    for (const char* sig : kDocumented) {
      ASSERT_TRUE(v.id_of.count(sig)) << sig << " missing (trad " << trad << ")";
      EXPECT_GT(v.changes[v.id_of.at(sig)], 0) << sig << " never changes (trad " << trad << ")";
    }
    if (!trad) {
      for (int k = 0; k < 3; ++k)
        EXPECT_TRUE(v.id_of.count("setup.lane" + std::to_string(k) + "_busy"));
    }
    // The whole run is traced: from cycle 0 to the last done cycle.
    EXPECT_EQ(v.first_time, 0u);
    EXPECT_GE(v.last_time, r.total_cycles - 1);
    // Values agree with the cycles: in a triangle's first-span cycle the output shows its span.
    for (size_t i = 0; i < r.cycles.size(); i += 97) {
      const TriangleCycles& c = r.cycles[i];
      if (!c.spans) continue;
      EXPECT_EQ(value_at(v, "span.valid", c.first_span_cycle), "1");
      EXPECT_EQ(value_at(v, "span.tri", c.first_span_cycle), vcd_bin(c.tri));
      EXPECT_EQ(value_at(v, "setup.tri_accept", c.accept_cycle), "1");
    }
    // The GTKWave save file beside it, one group per module.
    const std::string gtkw = slurp(cfg.trace_path.substr(0, cfg.trace_path.size() - 4) + ".gtkw");
    for (const char* group : {"-setup", "-walk", "-span", "-span_fifo"})
      EXPECT_NE(gtkw.find(std::string("\n") + group + "\n"), std::string::npos) << group;
    EXPECT_NE(gtkw.find("[dumpfile]"), std::string::npos);
    // The dump named relative to the save file (beside it), the view on the window, the setup
    // state by name through a filter file beside it.
    const std::string base = trad ? "sc_trace_trad" : "sc_trace_model";
    EXPECT_NE(gtkw.find("[dumpfile] \"" + base + ".vcd\"\n[savefile] \"" + base + ".gtkw\"\n"),
              std::string::npos)
        << gtkw.substr(0, 300);
    EXPECT_NE(gtkw.find("[timestart] 0\n"), std::string::npos);
    EXPECT_NE(gtkw.find("\n*-"), std::string::npos);  // a zoom out to the whole run
    EXPECT_NE(gtkw.find("^1 " + base + ".setup_state.filter\n@2024\n"), std::string::npos);
    const std::string filter = slurp(testing::TempDir() + base + ".setup_state.filter");
    EXPECT_NE(filter.find(trad ? "1 StSort\n" : "3 StLanes\n"), std::string::npos) << filter;
    // Every module of the statistics table (busy_cycles.* / stall_cycles.*) has its scope.
    for (const auto& [key, value] : r.work) {
      for (const char* prefix : {"busy_cycles.", "stall_cycles."}) {
        if (key.rfind(prefix, 0) != 0) continue;
        const std::string module = key.substr(std::string(prefix).size());
        if (trad && module != "setup" && module != "walk" && module != "span_fifo" &&
            module != "span_sink")
          continue;  // the traditional unit's own modules are not traced (docs/sc-model.md)
        EXPECT_NE(gtkw.find("\n-" + module + "\n"), std::string::npos) << module;
      }
    }
  }
}

TEST(ScTrace, WindowKeepsA100kSceneSmall) {
  RasterConfig cfg;
  const Scene scene = make_builtin("highpoly-far", cfg, CameraOptions{});
  const SetupResult setup = setup_scene(scene.tris, cfg);
  ASSERT_GE(scene.tris.size(), 100000u);
  cfg.trace_path = testing::TempDir() + "sc_trace_window.vcd";
  cfg.trace_first = 50000;
  cfg.trace_last = 50999;
  EngineResult r;
  make_improved_sc_engine()->run(setup, cfg, r);
  const uint64_t size = file_size(cfg.trace_path);
  EXPECT_GT(size, 0u);
  EXPECT_LT(size, 5u * 1000 * 1000);
  // The window: from the cycle the first windowed triangle is on the port (its predecessor's
  // accept + 1, as the RTL's trace) to the last one's done.
  uint64_t lo = ~uint64_t(0), hi = 0;
  for (size_t i = 1; i < r.cycles.size(); ++i) {
    const TriangleCycles& c = r.cycles[i];
    if (c.tri >= 50000 && c.tri <= 50999) {
      lo = std::min(lo, r.cycles[i - 1].accept_cycle + 1);
      hi = std::max(hi, c.done_cycle);
    }
  }
  Vcd v = read_vcd(cfg.trace_path);
  EXPECT_EQ(v.first_time, lo);
  EXPECT_LE(v.last_time, hi + 1);
  EXPECT_GT(v.changes[v.id_of.at("span.y")], 100);
  // The values at the window's start are the run's (a triangle is already in the unit).
  for (const TriangleCycles& c : r.cycles) {
    if (c.tri == 50000 && c.spans) {
      EXPECT_EQ(value_at(v, "span.tri", c.first_span_cycle), vcd_bin(c.tri));
    }
  }
}

}  // namespace
}  // namespace trirast
