// What the unit descriptors (app/units.hpp) decide, as a user meets it through the trirast
// program: compare checks every unit's timed pair against each other, --explain and --slowest
// speak each unit's own stages, an option the engine does not read is refused (raster) or noted
// (compare), the JSON report records the parameters the run used, and --trace takes .vcd or .fst
// and every timed engine writes that format. TRIRAST_TEST_BIN runs the command lines against
// another build (e.g. the tree before the descriptors).
#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "common/setup.hpp"
#include "engines.hpp"
#include "scene/scene.hpp"
#include "support/run_command.hpp"
#include "units.hpp"

namespace trirast {
namespace {

using test::CommandResult;
using test::count_lines;
using test::file_exists;
using test::run_command;
using test::slurp;
using test::TempDir;

const std::string kBin =
    std::getenv("TRIRAST_TEST_BIN") ? std::getenv("TRIRAST_TEST_BIN") : TRIRAST_BIN;
const std::string kSrc = TRIRAST_SOURCE_DIR;

// A scene whose triangles queue behind each other in the pipelines.
const char* const kScene = " --scene builtin:mixed --width 320 --height 240";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The "config" object of a report, as text.
std::string config_of(const std::string& json) {
  const size_t b = json.find("\"config\": {");
  if (b == std::string::npos) return "";
  return json.substr(b, json.find('}', b) - b + 1);
}

// ---- compare checks each unit's timed pair -------------------------------------------------

TEST(UnitDescriptor, CompareChecksEveryTimedPair) {
  for (const UnitDescriptor& u : units()) {
    ASSERT_EQ(u.timed_pair.size(), 2u) << u.name;
    TempDir dir;
    const std::string a = u.timed_pair[0], b = u.timed_pair[1];
    const CommandResult r = run_command(kBin + " compare" + kScene + " --engines " + a + "," + b +
                                        " --cycles " + dir.file("j.csv"));
    ASSERT_LE(r.status, 1) << r.err;
    EXPECT_NE(r.out.find("per-triangle cycles: " + a + " = " + b + " agree on all 16 columns of "),
              std::string::npos)
        << u.name << "\n"
        << r.out;
    // The joined file's mismatch column compares them: a row of equal cycles has it empty.
    const std::string joined = slurp(dir.file("j.csv"));
    EXPECT_EQ(joined.find("!="), std::string::npos) << u.name;
  }
}

TEST(UnitDescriptor, TimedPairsAreTimedEnginesOfTheirUnit) {
  for (const UnitDescriptor& u : units())
    for (const std::string& e : u.timed_pair) {
      const EngineInfo* info = find_engine(e);
      ASSERT_NE(info, nullptr) << e;
      EXPECT_TRUE(info->timed) << e;
      EXPECT_EQ(unit_of(e), &u) << e;
    }
}

TEST(UnitDescriptor, EnginesUnitsListsEachUnitsDescriptor) {
  const CommandResult r = run_command(kBin + " engines --units");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const UnitDescriptor& u : units()) {
    EXPECT_NE(r.out.find(u.name + ": " + u.title), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("cycles agree " + u.timed_pair[0] + " = " + u.timed_pair[1] + "\n"),
              std::string::npos)
        << r.out;
  }
  EXPECT_NE(r.out.find("stage        setup stage: StIdle, StBox, StEdge, StLanes, StHold\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("golden: reference engine (exact); reads --traversal, --threads\n"),
            std::string::npos)
      << r.out;
  // The plain list is unchanged: one engine a line.
  EXPECT_EQ(count_lines(run_command(kBin + " engines").out), int(engine_registry().size()));
}

// ---- --explain and --slowest in the unit's own stages ----------------------------------------

// improved2 has no StHold: a ready job waits in its job stage (L), and the cycles from accept to
// its job ready hold its waits for a free corner or job stage, so they are not called "set-up".
TEST(UnitDescriptor, ExplainNamesImproved2sOwnStages) {
  RasterConfig cfg;
  cfg.width = 320;
  cfg.height = 240;
  const SetupResult setup =
      setup_scene(load_scene("builtin:mixed", cfg, CameraOptions{}).tris, cfg);
  EngineResult in;
  find_engine("improved2-sc")->make()->run(setup, cfg, in);
  // The triangle whose ready job waited longest for the walk stage, and the one walked before it.
  size_t worst = 0, prev = 0;
  uint64_t worst_wait = 0;
  for (size_t p = 0, last = SIZE_MAX; p < in.cycles.size(); ++p) {
    const TriangleCycles& c = in.cycles[p];
    if (c.walk_start_cycle != c.handoff_cycle + 1) continue;
    if (last != SIZE_MAX && c.handoff_cycle - c.setup_done_cycle > worst_wait) {
      worst_wait = c.handoff_cycle - c.setup_done_cycle;
      worst = p;
      prev = last;
    }
    last = p;
  }
  ASSERT_GT(worst_wait, 0u) << "the scene must hold jobs waiting for the walk stage";
  const TriangleCycles& c = in.cycles[worst];
  const CommandResult r = run_command(
      kBin + " compare" + kScene + " --engines improved2-sc,improved2-rtl --slowest 5 --explain " +
      std::to_string(c.tri));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("StHold"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("; set-up "), std::string::npos) << r.out;
  const std::string head = "triangle " + std::to_string(c.tri) + ": ";
  const std::string wait = std::to_string(worst_wait) +
                           " cycles in the job stage (L) with its job ready: walk stage busy with "
                           "triangle " +
                           std::to_string(in.cycles[prev].tri) + " until cycle " +
                           std::to_string(c.handoff_cycle - 1);
  const std::string span = "; box, corner and job stages (B, C, L) " +
                           std::to_string(c.setup_done_cycle - c.setup_start_cycle) + " cycles (" +
                           std::to_string(c.setup_start_cycle) + ".." +
                           std::to_string(c.setup_done_cycle - 1) +
                           ", waits for a free corner or job stage included";
  int explained = 0;
  for (const std::string& line : lines_of(r.out)) {
    if (line.find("    " + head) != 0) continue;
    ++explained;
    EXPECT_NE(line.find(wait), std::string::npos) << line << "\nwanted: " << wait;
    EXPECT_NE(line.find(span), std::string::npos) << line << "\nwanted: " << span;
    EXPECT_NE(line.find("hand-off " + std::to_string(c.handoff_cycle)), std::string::npos) << line;
  }
  EXPECT_GE(explained, 2) << "one --explain line per engine:\n" << r.out;

  // The box stage hands a triangle to the corner stage in the cycle the next one is accepted:
  // the triangle with the longest such wait has it named.
  size_t held = 0, before = 0;
  uint64_t held_wait = 0;
  for (size_t p = 0, last = SIZE_MAX; p + 1 < in.cycles.size(); ++p) {
    const TriangleCycles& t = in.cycles[p];
    if (t.walk_start_cycle != t.handoff_cycle + 1) continue;
    const uint64_t wait = in.cycles[p + 1].accept_cycle - (t.accept_cycle + 1);
    if (last != SIZE_MAX && wait > held_wait) {
      held_wait = wait;
      held = p;
      before = last;
    }
    last = p;
  }
  ASSERT_GT(held_wait, 0u);
  const std::string tri = std::to_string(in.cycles[held].tri);
  const CommandResult b = run_command(kBin + " compare" + kScene +
                                      " --engines improved2-sc --explain " + tri);
  ASSERT_EQ(b.status, 0) << b.err;
  const std::string in_box = std::to_string(held_wait) +
                             " cycles in the box stage (B): corner stage busy with triangle " +
                             std::to_string(in.cycles[before].tri) + " until cycle " +
                             std::to_string(in.cycles[held + 1].accept_cycle - 1);
  EXPECT_NE(b.out.find("    triangle " + tri + ": "), std::string::npos) << b.out;
  EXPECT_NE(b.out.find(in_box), std::string::npos) << b.out << "\nwanted: " << in_box;
}

// The half-space unit's per-triangle stall cycles are its span emitter's pushes that found the
// FIFO full (its tile walker waits apart, in stall_cycles.tile_walker).
TEST(UnitDescriptor, ExplainNamesTheHalfspaceUnitsSpanEmitter) {
  const CommandResult r =
      run_command(kBin + " compare" + kScene +
                  " --engines halfspace-sc --sink-stall periodic:1:3 --fifo-depth 1 --slowest 3");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("stall cycles of its span emitter: FIFO full (sink stalled, --sink-stall "
                       "periodic:1:3)"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("in its walk: FIFO full"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" in StHold: walk stage busy with"), std::string::npos) << r.out;
}

// ---- options an engine does not read -------------------------------------------------------

TEST(UnitDescriptor, RasterRefusesAnOptionTheEngineDoesNotRead) {
  struct Case {
    std::string option, engine, applies;
  };
  const std::vector<Case> cases = {
      {"--boundary divide", "improved2-sc", "improved-datapath, improved-sc, improved-rtl"},
      {"--divider fixed", "improved2-sc", "improved-datapath, improved-sc, improved-rtl"},
      {"--stamp 4", "improved2-sc", "halfspace-datapath, halfspace-sc, halfspace-rtl"},
      {"--traversal simple", "improved2-sc", "golden"},
      {"--threads 2", "improved2-sc", "golden"},
      {"--corner-form dsp", "improved-sc", "improved2-sc, improved2-rtl"},
      {"--endpoints 2", "trad-sc", "improved-sc"},
      {"--endpoints 2", "halfspace-rtl", "improved2-rtl"},
      {"--fifo-depth 4", "improved-datapath", "trad-rtl"},
      {"--box-bits 12", "golden", "halfspace-datapath"},
      {"--sink-stall periodic:1:1", "float-scanline", "improved-sc"},
  };
  for (const Case& c : cases) {
    TempDir dir;
    const CommandResult r =
        run_command(kBin + " raster" + kScene + " --engine " + c.engine + " " + c.option +
                    " --spans " + dir.file("s") + " --report " + dir.file("r.json"));
    const std::string option = c.option.substr(0, c.option.find(' '));
    EXPECT_EQ(r.status, 2) << c.option << " " << c.engine << "\n" << r.out;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("trirast raster: " + option + ": does not apply to engine '" + c.engine +
                         "' (it applies to: "),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find(c.applies), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(dir.entry_count(), 0);
  }
  // Given with its default value, it is still given.
  const CommandResult d =
      run_command(kBin + " raster" + kScene + " --engine improved2-sc --boundary step");
  EXPECT_EQ(d.status, 2) << d.out;
  // Not given: the defaults shape no engine that does not read them.
  EXPECT_EQ(run_command(kBin + " raster" + kScene + " --engine improved2-sc").status, 0);
}

TEST(UnitDescriptor, CompareNotesWhichEnginesIgnoreAnOption) {
  const CommandResult r = run_command(
      kBin + " compare" + kScene + " --engines golden,improved-sc,improved2-sc --boundary divide");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err,
            "trirast compare: note: --boundary: ignored by 'golden', 'improved2-sc' (it applies "
            "to: improved-datapath, improved-sc, improved-rtl)\n");
  // No engine of the run reads it: an error.
  const CommandResult none = run_command(kBin + " compare" + kScene +
                                         " --engines improved2-sc,improved2-rtl --divider fixed");
  EXPECT_EQ(none.status, 2) << none.out;
  EXPECT_EQ(count_lines(none.err), 1) << none.err;
  EXPECT_NE(none.err.find("--divider: applies to none of the engines run"), std::string::npos)
      << none.err;
  EXPECT_EQ(none.out, "");
  // The golden runs in every compare: its options apply.
  const CommandResult golden =
      run_command(kBin + " compare" + kScene + " --engines improved-sc --traversal scanline");
  EXPECT_EQ(golden.status, 0) << golden.err;
  EXPECT_NE(golden.err.find("--traversal: ignored by 'improved-sc'"), std::string::npos)
      << golden.err;
}

// ---- the report records the parameters the run used ----------------------------------------

struct ReportCase {
  std::string engine, options;
  std::vector<std::string> present, absent;  // "key": value texts of its "config"
};

void expect_config(const std::vector<ReportCase>& cases) {
  TempDir dir;
  for (const ReportCase& c : cases) {
    const std::string path = dir.file(c.engine + ".json");
    const CommandResult r = run_command(kBin + " raster" + kScene + " --engine " + c.engine + " " +
                                        c.options + " --report " + path);
    ASSERT_EQ(r.status, 0) << c.engine << ": " << r.err;
    const std::string config = config_of(slurp(path));
    ASSERT_FALSE(config.empty()) << path;
    for (const std::string& key : c.present)
      EXPECT_NE(config.find(key), std::string::npos) << c.engine << ": " << key << "\n" << config;
    for (const std::string& key : c.absent)
      EXPECT_EQ(config.find(key), std::string::npos) << c.engine << ": " << key << "\n" << config;
    const CommandResult check = run_command("/usr/bin/python3 " + kSrc +
                                            "/tests/support/check_report_descriptions.py " + path);
    EXPECT_EQ(check.status, 0) << check.out << check.err;
  }
}

// The boundary traversal and the divider are the improved unit's: a run of another engine does
// not record the defaults it never used.
TEST(UnitDescriptor, ReportRecordsBoundaryAndDividerOnlyWhereUsed) {
  expect_config({
      {"improved-sc",
       "--boundary divide",
       {"\"box_bits\": 14", "\"boundary\": \"divide\"", "\"divider\": \"adaptive\"",
        "\"endpoints\": 1", "\"fifo_depth\": 8", "\"sink_stall\": \"none\""},
       {"\"corner_form\"", "\"stamp\"", "\"threads\""}},
      {"improved2-sc", "", {"\"box_bits\": 14"}, {"\"boundary\"", "\"divider\""}},
      {"golden", "", {"\"traversal\": \"auto\""}, {"\"boundary\"", "\"divider\"", "\"box_bits\""}},
  });
}

// Every other parameter that shaped a run is recorded as it ran: the corner form (it changes
// improved2's cycles), the half-space unit's stamp, tile and walk, the golden's traversal.
TEST(UnitDescriptor, ReportRecordsCornerFormAndEachEnginesParameters) {
  expect_config({
      {"improved2-sc",
       "--corner-form dsp --endpoints 2",
       {"\"corner_form\": \"dsp\"", "\"endpoints\": 2", "\"box_bits\": 14", "\"fifo_depth\": 8"},
       {"\"stamp\"", "\"traversal\""}},
      {"improved2-rtl", "", {"\"corner_form\": \"radix16\""}, {}},
      {"halfspace-sc",
       "--stamp 4 --tile 16 --hs-walk row",
       {"\"stamp\": 4", "\"tile\": 16", "\"hs_walk\": \"row\"", "\"fifo_depth\": 8"},
       {"\"endpoints\"", "\"corner_form\""}},
      {"golden",
       "--traversal scanline --threads 2",
       {"\"traversal\": \"scanline\"", "\"threads\": 2"},
       {"\"endpoints\"", "\"sink_stall\""}},
  });
  // compare: the parameters of every engine it ran, the golden's included.
  TempDir dir;
  const std::string path = dir.file("compare.json");
  const CommandResult r = run_command(kBin + " compare" + kScene +
                                      " --engines improved2-sc,halfspace-sc --corner-form dsp "
                                      "--report " +
                                      path);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string config = config_of(slurp(path));
  for (const char* key : {"\"corner_form\": \"dsp\"", "\"stamp\": 2", "\"traversal\": \"auto\""})
    EXPECT_NE(config.find(key), std::string::npos) << key << "\n" << config;
  EXPECT_EQ(config.find("\"boundary\""), std::string::npos) << config;
}

// ---- traces: .vcd or .fst, and that format from every timed engine --------------------------

TEST(UnitDescriptor, TracePathMustNameVcdOrFst) {
  for (const char* engine : {"improved-sc", "improved-rtl", "improved2-sc", "halfspace-rtl"})
    for (const char* name : {"t.txt", "t", "t.vcd.gz", "t.FST"}) {
      TempDir dir;
      const CommandResult r = run_command(kBin + " raster --scene builtin:lowpoly-far --engine " +
                                          engine + " --trace " + dir.file(name));
      EXPECT_EQ(r.status, 2) << engine << " " << name << "\n" << r.out;
      EXPECT_EQ(count_lines(r.err), 1) << r.err;
      EXPECT_NE(r.err.find("--trace"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(".vcd or .fst"), std::string::npos) << r.err;
      EXPECT_EQ(dir.entry_count(), 0) << engine << " " << name;
    }
}

TEST(UnitDescriptor, EveryTimedEngineWritesTheFormatItsExtensionNames) {
  for (const EngineInfo& e : engine_registry()) {
    if (!e.timed) continue;
    for (const char* ext : {"vcd", "fst"}) {
      SCOPED_TRACE(e.name + " ." + ext);
      TempDir dir;
      const std::string path = dir.file(std::string("t.") + ext);
      const CommandResult r = run_command(kBin + " raster --scene builtin:lowpoly-far --engine " +
                                          e.name + " --trace-tris 0:3 --trace " + path);
      ASSERT_EQ(r.status, 0) << r.err;
      const std::string bytes = slurp(path);
      ASSERT_FALSE(bytes.empty());
      if (std::string(ext) == "vcd") {
        EXPECT_EQ(bytes[0], '$') << "not VCD text";
        EXPECT_NE(bytes.find("$enddefinitions"), std::string::npos);
      } else {
        EXPECT_NE(bytes[0], '$') << "VCD text in a .fst";
        const CommandResult back = run_command("fst2vcd -f " + path);
        EXPECT_EQ(back.status, 0) << back.err;
        EXPECT_NE(back.out.find("$enddefinitions"), std::string::npos);
      }
      // The save file beside it names the trace.
      const std::string gtkw = slurp(dir.file("t.gtkw"));
      EXPECT_NE(gtkw.find(std::string("t.") + ext), std::string::npos) << gtkw;
      // No temporary file is left.
      EXPECT_EQ(run_command("ls -A " + dir.path() + " | grep -c tmp").out, "0\n");
    }
  }
}

}  // namespace
}  // namespace trirast
