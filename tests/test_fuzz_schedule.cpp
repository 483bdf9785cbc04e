// The schedule of trirast fuzz (app/cli/fuzz_schedule.hpp): on a fixed seed's scenes every engine
// runs at least one scene in ten, every class of the generator reaches every engine, no engine's
// estimated spend per scene is far above its share, the cuts keep the estimate under the cap,
// and the assignment depends on the seed and the scene alone; and `trirast fuzz --seconds 5`
// prints the per-engine table and ends on time.
#include <gtest/gtest.h>

#include <chrono>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "cli/fuzz_schedule.hpp"
#include "fuzz/fuzz_scene.hpp"
#include "support/run_command.hpp"

namespace trirast {
namespace {

using test::CommandResult;
using test::kBin;
using test::run_command;
using test::TempDir;

const std::vector<std::string> kEngines = {
    "golden",          "improved-datapath", "improved-sc",        "improved-rtl",
    "improved2-datapath", "improved2-sc",   "improved2-rtl",      "halfspace-datapath",
    "halfspace-sc",    "halfspace-rtl"};

struct Drawn {
  RasterConfig cfg;
  std::vector<InputTriangle> tris;
  std::vector<FuzzClass> classes;
  SetupResult setup;
};

Drawn draw(uint64_t seed) {
  Drawn d;
  RngDraws draws(seed);
  d.cfg = draw_fuzz_config(draws);
  d.tris = draw_fuzz_scene(draws, d.cfg, 400, &d.classes);
  draw_fuzz_hs_config(draws, d.cfg, {});
  d.setup = setup_scene(d.tris, d.cfg);
  return d;
}

TEST(FuzzSchedule, EveryEngineATenthEveryClassBalancedAndDeterministic) {
  const int kScenes = 3000;
  const FuzzSchedulePolicy policy;
  const double cap = policy.share_ns * policy.slot_period;
  std::vector<int> runs(kEngines.size(), 0), cut(kEngines.size(), 0);
  std::vector<std::set<int>> classes(kEngines.size());
  std::vector<double> spend(kEngines.size(), 0.0);
  for (int scene = 0; scene < kScenes; ++scene) {
    const Drawn d = draw(0xabc00000 + scene);
    ASSERT_EQ(d.classes.size(), d.tris.size());
    const auto plan = fuzz_schedule_scene(77, scene, d.setup, uint32_t(d.tris.size()), d.cfg, kEngines);
    ASSERT_EQ(plan.size(), kEngines.size());
    // The same seed and scene give the same plan.
    const auto again = fuzz_schedule_scene(77, scene, d.setup, uint32_t(d.tris.size()), d.cfg, kEngines);
    for (size_t e = 0; e < kEngines.size(); ++e) {
      const FuzzAssignment& a = plan[e];
      SCOPED_TRACE(kEngines[e] + " scene " + std::to_string(scene));
      EXPECT_EQ(a.runs, again[e].runs);
      EXPECT_EQ(a.tri_begin, again[e].tri_begin);
      EXPECT_EQ(a.tri_end, again[e].tri_end);
      EXPECT_EQ(a.width, again[e].width);
      // A part of the scene: a crop at the origin and a window of its triangles.
      ASSERT_LE(a.width, d.cfg.width);
      ASSERT_LE(a.height, d.cfg.height);
      ASSERT_GE(std::min(a.width, a.height), std::min({16, d.cfg.width, d.cfg.height}));
      ASSERT_LT(a.tri_begin, a.tri_end);
      ASSERT_LE(a.tri_end, d.tris.size());
      EXPECT_EQ(a.cut, a.width != d.cfg.width || a.height != d.cfg.height || a.tri_begin != 0 ||
                           a.tri_end != d.tris.size());
      // The estimate is of the part, and under the cap unless nothing is left to cut.
      EXPECT_DOUBLE_EQ(a.estimate_ns,
                       fuzz_estimate_ns(fuzz_engine_cost(kEngines[e]),
                                        fuzz_cost_features(d.setup, d.cfg, a.width, a.height,
                                                           a.tri_begin, a.tri_end)));
      if (kEngines[e] == "golden") {
        EXPECT_TRUE(a.runs);
        EXPECT_FALSE(a.cut);
      } else if (a.tri_end - a.tri_begin > 1) {
        EXPECT_LE(a.estimate_ns, cap);
      }
      if (!a.runs) continue;
      ++runs[e];
      cut[e] += a.cut;
      spend[e] += a.estimate_ns;
      for (uint32_t i = a.tri_begin; i < a.tri_end; ++i)
        if (d.classes[i] != FuzzClass::kCount) classes[e].insert(int(d.classes[i]));
    }
  }
  for (size_t e = 0; e < kEngines.size(); ++e) {
    SCOPED_TRACE(kEngines[e]);
    EXPECT_GE(runs[e] * 10, kScenes) << runs[e];
    EXPECT_EQ(int(classes[e].size()), int(FuzzClass::kCount)) << classes[e].size();
    if (kEngines[e] == "golden") continue;
    // Balanced: no engine spends (by the estimate) much more than its share per scene.
    EXPECT_LE(spend[e] / kScenes, 1.5 * policy.share_ns) << spend[e] / kScenes;
  }
  // The slow engines get cut scenes, the cheap ones (the datapaths) almost none.
  EXPECT_GT(cut[9], kScenes / 100);  // halfspace-rtl
  EXPECT_LT(cut[1], cut[9]);         // improved-datapath
}

TEST(FuzzSchedule, CostsGrowWithTheBoxAndTheStamp) {
  RasterConfig cfg;
  cfg.width = cfg.height = 512;
  const std::vector<InputTriangle> tris = {InputTriangle{{1, 101, 1}, {1, 1, 201}},
                                           InputTriangle{{1, 401, 1}, {1, 1, 401}}};
  const SetupResult setup = setup_scene(tris, cfg);
  const FuzzCostFeatures all = fuzz_cost_features(setup, cfg, 512, 512, 0, 2);
  EXPECT_EQ(all.tris, 2);
  EXPECT_EQ(all.rows, 200 + 400);
  EXPECT_EQ(all.cols, 100 + 400);
  const FuzzCostFeatures second = fuzz_cost_features(setup, cfg, 512, 512, 1, 2);
  EXPECT_EQ(second.tris, 1);
  EXPECT_EQ(second.rows, 400);
  const FuzzCostFeatures cropped = fuzz_cost_features(setup, cfg, 64, 32, 0, 2);
  EXPECT_EQ(cropped.rows, 31 + 31);  // the boxes start at pixel 1
  EXPECT_EQ(cropped.cols, 63 + 63);
  // Stamps without tiles: the 31 x 31 box of the 32 x 32 crop in stamps of 2, then of 4.
  cfg.halfspace.stamp = 2;
  cfg.halfspace.tile = 0;
  EXPECT_EQ(fuzz_cost_features(setup, cfg, 32, 32, 0, 1).stamps, 16 * 16);
  cfg.halfspace.stamp = 4;
  EXPECT_EQ(fuzz_cost_features(setup, cfg, 32, 32, 0, 1).stamps, 8 * 8);
  // Every engine of the table costs more for more of the scene.
  for (const FuzzEngineCost& c : fuzz_cost_table()) {
    SCOPED_TRACE(c.engine);
    EXPECT_LT(fuzz_estimate_ns(c, cropped), fuzz_estimate_ns(c, all));
    EXPECT_GT(fuzz_estimate_ns(c, FuzzCostFeatures{}), 0.0);
  }
}

TEST(FuzzScheduleCli, FiveSecondsPrintsTheEngineTableAndEndsOnTime) {
  TempDir dir;
  const auto t0 = std::chrono::steady_clock::now();
  const CommandResult r = run_command(kBin + " fuzz --seconds 5 --seed 3031 --out " + dir.path());
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  // Within 3 s of the deadline (the program's start-up included).
  EXPECT_LT(wall, 5.0 + 3.0) << r.out;
  EXPECT_GE(wall, 5.0 - 3.0) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("\n  deadline   5 s, ended [0-9.]+ s (after|before) it")))
      << r.out;
  // The table: every engine, its scenes, share, cut scenes, triangles, pixels, classes, CPU time.
  EXPECT_NE(r.out.find("  engine                scenes  share     cut  triangles         pixels  "
                       "classes     CPU s    est. s\n"),
            std::string::npos)
      << r.out;
  const std::regex row("\n  ([a-z0-9-]+) +([0-9]+) +([0-9.]+)% +[0-9]+ +([0-9]+) +[0-9]+ +"
                       "([0-9]+)/14 +[0-9.]+ +[0-9.]+(?=\n)");
  std::set<std::string> seen;
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), row); it != std::sregex_iterator();
       ++it) {
    const std::smatch& m = *it;
    seen.insert(m[1]);
    EXPECT_GT(std::stoi(m[2]), 0) << m[0];
    EXPECT_GE(std::stod(m[3]), 10.0) << m[0];
  }
  for (const std::string& e : kEngines) EXPECT_EQ(seen.count(e), 1u) << e << "\n" << r.out;
  EXPECT_NE(r.out.find("0 disagreements"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace trirast
