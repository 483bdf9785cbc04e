// The --coverage option of raster and fuzz (docs/coverage.md): the report of the RTL's cover
// points, its summary line, and the refusal on engines without cover points.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <string>

#include "support/run_command.hpp"

namespace trirast {
namespace {

using test::CommandResult;
using test::kBin;
using test::run_command;
using test::slurp;
using test::TempDir;

// The count of `point` of `engine` in a report ("| engine | `point` | count |"); -1 if absent.
long long count_of(const std::string& report, const std::string& engine, const std::string& point) {
  const std::string row = "| " + engine + " | `" + point + "` | ";
  const size_t at = report.find(row);
  if (at == std::string::npos) return -1;
  return std::stoll(report.substr(at + row.size()));
}

// Rows of the report's table, and H, T of its summary line.
void summary(const std::string& text, long long& hit, long long& total, long long& rows) {
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, std::regex("coverage: (\\d+) of (\\d+) cover points hit")))
      << text;
  hit = std::stoll(m[1]);
  total = std::stoll(m[2]);
  rows = 0;
  for (size_t p = text.find("\n| "); p != std::string::npos; p = text.find("\n| ", p + 1)) ++rows;
  --rows;  // the header
}

// The half-space unit walks a band right to left only in its zigzag order: the point counts on
// a zigzag build and stays 0 on the row build, and both reports list every point with its count.
TEST(CliCoverage, RasterReportsEveryPointOfTheRun) {
  TempDir dir;
  const std::string scene = " --scene builtin:mixed:objects=2,tess=8 --width 320 --height 240";
  const CommandResult zig = run_command(kBin + " raster --engine halfspace-rtl" + scene +
                                        " --stamp 1 --tile none --hs-walk zigzag --coverage " +
                                        dir.file("zig.md"));
  ASSERT_EQ(zig.status, 0) << zig.err;
  const CommandResult row = run_command(kBin + " raster --engine halfspace-rtl" + scene +
                                        " --stamp 4 --tile 16 --hs-walk row --coverage " +
                                        dir.file("row.md"));
  ASSERT_EQ(row.status, 0) << row.err;
  const std::string z = slurp(dir.file("zig.md")), r = slurp(dir.file("row.md"));
  EXPECT_GT(count_of(z, "halfspace-rtl", "u_walker.WalkBandBackward_C"), 0) << z;
  EXPECT_EQ(count_of(r, "halfspace-rtl", "u_walker.WalkBandBackward_C"), 0) << r;
  EXPECT_GT(count_of(r, "halfspace-rtl", "u_walker.WalkUnitAccepted_C"), 0) << r;
  EXPECT_GT(count_of(r, "halfspace-rtl", "u_setup.TriAccept_C"), 0) << r;
  long long hit = 0, total = 0, rows = 0;
  summary(r, hit, total, rows);
  EXPECT_EQ(rows, total);
  EXPECT_GT(hit, 0);
  EXPECT_LT(hit, total);  // WalkBandBackward_C at least
  EXPECT_NE(r.find("- halfspace-rtl `u_walker.WalkBandBackward_C`"), std::string::npos) << r;
  EXPECT_NE(row.out.find("coverage: " + std::to_string(hit) + " of " + std::to_string(total)),
            std::string::npos)
      << row.out;
}

TEST(CliCoverage, RefusedOnAnEngineWithoutCoverPoints) {
  TempDir dir;
  for (const char* engine : {"improved2-sc", "golden", "improved-datapath"}) {
    const CommandResult r = run_command(kBin + " raster --engine " + engine +
                                        " --scene builtin:mixed:objects=1 --coverage " +
                                        dir.file("c.md"));
    EXPECT_EQ(r.status, 2) << engine;
    EXPECT_NE(r.err.find("--coverage: engine '" + std::string(engine) + "' has no cover points"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const CommandResult f = run_command(kBin + " fuzz --scenes 1 --engines golden,improved-sc --out " +
                                      dir.path() + " --coverage " + dir.file("c.md"));
  EXPECT_EQ(f.status, 2);
  EXPECT_NE(f.err.find("--coverage"), std::string::npos) << f.err;
  EXPECT_EQ(dir.entry_count(), 0);
}

// fuzz adds every scene's counts: the triangles the port accepted over the run.
TEST(CliCoverage, FuzzMergesTheRunsOfEveryRtlEngine) {
  TempDir dir;
  const CommandResult f = run_command(kBin + " fuzz --seed 3 --scenes 4 --max-triangles 20 " +
                                      "--engines golden,improved2-rtl,improved-rtl --out " + dir.path() +
                                      " --coverage " + dir.file("c.md"));
  ASSERT_EQ(f.status, 0) << f.err;
  const std::string c = slurp(dir.file("c.md"));
  long long hit = 0, total = 0, rows = 0;
  summary(c, hit, total, rows);
  EXPECT_EQ(rows, total);
  EXPECT_NE(f.out.find("coverage: " + std::to_string(hit) + " of " + std::to_string(total)),
            std::string::npos)
      << f.out;
  EXPECT_GT(count_of(c, "improved2-rtl", "TriAccept_C"), 0) << c;
  EXPECT_GT(count_of(c, "improved-rtl", "u_setup.TriAccept_C"), 0) << c;
}

}  // namespace
}  // namespace trirast
