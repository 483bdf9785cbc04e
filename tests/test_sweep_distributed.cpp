// The distributed sweep (issue 16): task shards, result files, the merge, and the two runners
// (scripts/sweep_slurm.sh on a local single-node Slurm, scripts/sweep_parallel.sh through GNU
// parallel); each merged CSV is compared with a single-process run's on every column but the wall
// times (scripts/sweep_compare.py).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "sweep/sweep_area.hpp"
#include "sweep/sweep_shard.hpp"
#include "support/run_command.hpp"

namespace trirast {
namespace {

using test::CommandResult;
using test::file_exists;
using test::run_command;
using test::TempDir;

const std::string kBin = TRIRAST_BIN;
const std::string kSource = TRIRAST_SOURCE_DIR;
// Synthesis results of this tree, as the scripts pass them.
const std::string kArea =
    " --synth-csv " + kSource + "/docs/synth.csv --synth-script " + kSource + "/scripts/synth.sh";

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A usage or data error: exit status 2, one line on stderr that names `what`.
void expect_one_line_error(const CommandResult& r, const std::string& what) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
}

std::string task_file(const std::string& dir, int i) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "/tasks/sim-%06d.res", i);
  return dir + buf;
}

// Every "ran I" line of DIR/run.log, counted per task.
std::map<int, int> ran_counts(const std::string& dir) {
  std::map<int, int> n;
  std::istringstream in(slurp(dir + "/run.log"));
  std::string word;
  int i;
  while (in >> word >> i) {
    if (word == "ran") ++n[i];
    std::string rest;
    std::getline(in, rest);
  }
  return n;
}

CommandResult compare(const std::string& a, const std::string& b) {
  return run_command("/usr/bin/python3 " + kSource + "/scripts/sweep_compare.py " + a + " " + b);
}

// A single-process run of the same task list, the reference of every merge.
void single_run(const std::string& out, const std::string& options) {
  const CommandResult r =
      run_command(kBin + " sweep --quick --no-progress" + kArea + options + " --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
}

// The synthesis jobs' rows replace the estimate for their unit, widths and N only.
TEST(SweepDistributed, SynthesisJobRowsReplaceTheEstimateOfTheirConfiguration) {
  TempDir d;
  AreaModel area(kSource + "/docs/synth.csv", kSource + "/scripts/synth.sh");
  RasterConfig c13;
  c13.coord_int_bits = 13;
  RasterConfig c13n4 = c13;
  c13n4.endpoints = 4;
  ASSERT_TRUE(area.area(UnitKind::Improved, c13).estimate());
  mkdir(d.file("synth").c_str(), 0777);
  test::write_file(d.file("synth/a.synth"),
                   "# trirast-synth-result 1\n"
                   "unit,config,target,luts,ffs,carry,bram,dsp,fmax_mhz,subpixel_bits,coord_bits,"
                   "box_bits,endpoints,seconds\n"
                   "improved,x,xilinx7,1234,567,0,0,9,,8,13,14,1,60\n"
                   "trad,y,ice40-pnr,100,50,0,0,0,42.5,8,13,14,1,60\n# end\n");
  const std::vector<SynthRow> rows = read_synth_results(d.path());
  ASSERT_EQ(rows.size(), 2u);
  area.add_rows(rows);
  const Area a = area.area(UnitKind::Improved, c13);
  EXPECT_EQ(a.luts, 1234);
  EXPECT_EQ(a.ffs, 567);
  EXPECT_EQ(a.source, "synth:xilinx7");
  EXPECT_TRUE(area.area(UnitKind::Improved, c13n4).estimate());  // another N
  RasterConfig k6 = c13;
  k6.divider_quotient_bits = 6;
  EXPECT_TRUE(area.area(UnitKind::Improved, k6).estimate());  // quotient truncation: no RTL
  EXPECT_EQ(area.fmax_mhz(UnitKind::Trad, c13), 42.5);
  EXPECT_TRUE(area.area(UnitKind::Trad, c13).estimate());  // an Fmax row gives no area
  EXPECT_NE(area.estimate(UnitKind::Improved, c13).luts, 1234);
}

TEST(SweepDistributed, UnknownShardOrTaskIsAOneLineErrorNamingTheOption) {
  TempDir d;
  for (const char* bad : {"4/4", "1-4", "-1/4", "a/4", "3/0", "/4", "1/", "1/4/2"})
    expect_one_line_error(run_command(kBin + " sweep --quick --shard '" + bad + "' --out " +
                                      d.file("r")),
                          "--shard");
  expect_one_line_error(run_command(kBin + " sweep --quick --task 63 --out " + d.file("r")),
                        "--task");
  expect_one_line_error(run_command(kBin + " sweep --quick --task x --out " + d.file("r")),
                        "--task");
  expect_one_line_error(
      run_command(kBin + " sweep --quick --shard 0/2 --task 1 --out " + d.file("r")), "--shard");
  expect_one_line_error(run_command(kBin + " sweep --quick --allow-partial --out " + d.file("r")),
                        "--allow-partial");
  EXPECT_FALSE(file_exists(d.file("r") + "/tasks"));  // nothing ran
}

TEST(SweepDistributed, ShardsMergeToTheSingleRunAndRefuseBadResultSets) {
  TempDir d;
  const std::string res = d.file("res");
  single_run(d.file("single"), "");
  for (int k = 0; k < 3; ++k) {
    const CommandResult r = run_command(kBin + " sweep --quick --no-progress" + kArea +
                                        " --shard " + std::to_string(k) + "/3 --out " + res);
    ASSERT_EQ(r.status, 0) << r.err;
  }
  // 63 tasks, one file each.
  const CommandResult list = run_command(kBin + " sweep --quick --list-tasks");
  ASSERT_EQ(list.status, 0);
  EXPECT_EQ(std::count(list.out.begin(), list.out.end(), '\n'), 63);
  for (int i = 0; i < 63; ++i) EXPECT_TRUE(file_exists(task_file(res, i))) << i;
  auto merge = [&](const std::string& out, const std::string& extra = "") {
    return run_command(kBin + " sweep --quick --no-progress" + kArea + " --merge " + res +
                       " --out " + out + extra);
  };
  CommandResult m = merge(d.file("merged"));
  ASSERT_EQ(m.status, 0) << m.err;
  for (const char* f : {"/sweep.csv", "/sweep_configs.csv"}) {
    const CommandResult c = compare(d.file("single") + f, d.file("merged") + f);
    EXPECT_EQ(c.status, 0) << c.err;
  }
  EXPECT_NE(slurp(d.file("merged") + "/sweep.json").find("\"partial\": false"), std::string::npos);

  // A rerun of a shard redoes nothing.
  const CommandResult again =
      run_command(kBin + " sweep --quick --no-progress" + kArea + " --shard 1/3 --out " + res);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.out.find(" 0 ran, 21 complete already"), std::string::npos) << again.out;

  // A missing task: named, nothing merged, unless --allow-partial (then the output says so).
  const std::string task5 = slurp(task_file(res, 5));
  ASSERT_EQ(std::remove(task_file(res, 5).c_str()), 0);
  m = merge(d.file("partial"));
  expect_one_line_error(m, "task 5 (");
  EXPECT_FALSE(file_exists(d.file("partial") + "/sweep.csv"));
  m = merge(d.file("partial"), " --allow-partial");
  ASSERT_EQ(m.status, 0) << m.err;
  EXPECT_NE(m.out.find("PARTIAL: 1 task"), std::string::npos) << m.out;
  EXPECT_NE(slurp(d.file("partial") + "/sweep.json").find("\"partial\": true"), std::string::npos);

  // A result file cut short.
  test::write_file(task_file(res, 5), task5.substr(0, task5.size() / 2));
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": cut short");
  // Mixed versions: another task list or build (fingerprint), another format version.
  std::string other = task5;
  const size_t at = other.find("fingerprint ") + 12;
  other[at] = other[at] == '0' ? '1' : '0';
  test::write_file(task_file(res, 5), other);
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": fingerprint");
  other = task5;
  other.replace(0, other.find('\n'), "trirast-sweep-result 2");
  test::write_file(task_file(res, 5), other);
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": result format 2");
  test::write_file(task_file(res, 5), task5);
  // A synthesis result cut short or of another format.
  mkdir((res + "/synth").c_str(), 0777);
  test::write_file(res + "/synth/x.synth", "# trirast-synth-result 1\nunit,config\n");
  expect_one_line_error(merge(d.file("bad")), res + "/synth/x.synth: cut short");
  test::write_file(res + "/synth/x.synth", "# trirast-synth-result 9\n# end\n");
  expect_one_line_error(merge(d.file("bad")), res + "/synth/x.synth: not a synthesis result");
  std::remove((res + "/synth/x.synth").c_str());
  EXPECT_FALSE(file_exists(d.file("bad") + "/sweep.csv"));
  m = merge(d.file("merged2"));
  ASSERT_EQ(m.status, 0) << m.err;
  EXPECT_EQ(compare(d.file("single") + "/sweep.csv", d.file("merged2") + "/sweep.csv").status, 0);
}

// GNU parallel: a shard killed mid-run and a deleted result file; the rerun through
// scripts/sweep_parallel.sh completes the sweep without redoing finished tasks.
TEST(SweepDistributed, gnu_parallel_resumes_a_killed_run) {
  TempDir d;
  const std::string res = d.file("res");
  // Larger scenes than --quick's, so that the run lasts seconds and can be killed in the middle.
  const std::string scenes = " --scenes 'builtin:lowpoly-near;builtin:mixed;builtin:torus@back'";
  single_run(d.file("single"), scenes);
  const CommandResult killed = run_command(
      kBin + " sweep --quick --no-progress" + kArea + scenes + " --shard 0/1 --out " + res +
      " >/dev/null 2>&1 & p=$!; for i in $(seq 1 3000); do "
      "[ \"$(cat " + res + "/run.log 2>/dev/null | wc -l)\" -ge 12 ] && break; sleep 0.01; done; "
      "kill -9 $p; wait $p 2>/dev/null; echo \"status $?\"");
  ASSERT_NE(killed.out.find("status 137"), std::string::npos) << "not killed: " << killed.out;
  const std::map<int, int> first = ran_counts(res);
  ASSERT_GE(first.size(), 12u);
  ASSERT_LT(first.size(), 63u) << "the run finished before it was killed";
  // Modification times of the finished tasks' files, and one result deleted.
  std::map<int, long> mtime;
  for (const auto& [i, n] : first) {
    struct stat st;
    ASSERT_EQ(stat(task_file(res, i).c_str(), &st), 0) << i;
    mtime[i] = long(st.st_mtim.tv_sec) * 1000000000L + st.st_mtim.tv_nsec;
  }
  const int deleted = first.begin()->first;
  ASSERT_EQ(std::remove(task_file(res, deleted).c_str()), 0);

  const CommandResult r =
      run_command("TRIRAST_BIN=" + kBin + " " + kSource + "/scripts/sweep_parallel.sh --quick " +
                  "--jobs 2 --results " + res + " -- " + scenes + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  const std::map<int, int> all = ran_counts(res);
  EXPECT_EQ(all.size(), 63u);
  for (const auto& [i, n] : all) {
    const bool was_done = first.count(i) && i != deleted;
    EXPECT_EQ(n, i == deleted ? 2 : 1) << "task " << i << (was_done ? " was redone" : "");
  }
  for (const auto& [i, t] : mtime) {
    if (i == deleted) continue;
    struct stat st;
    ASSERT_EQ(stat(task_file(res, i).c_str(), &st), 0);
    EXPECT_EQ(long(st.st_mtim.tv_sec) * 1000000000L + st.st_mtim.tv_nsec, t)
        << "task " << i << " was rewritten";
  }
  for (const char* f : {"/sweep.csv", "/sweep_configs.csv"}) {
    const CommandResult c = compare(d.file("single") + f, res + "/out" + f);
    EXPECT_EQ(c.status, 0) << c.err;
  }
}

// Slurm: a single-node Slurm of its own (state directory and ports not those of a user's), the
// --quick sweep as a job array and a dependent merge job; fails, never skips, when Slurm cannot
// start; stops the daemons it started.
TEST(SweepDistributed, slurm_local_job_arrays_merge_to_the_single_run) {
  TempDir d;
  const std::string state = d.file("slurm");
  const std::string env = "TRIRAST_SLURMCTLD_PORT=6927 TRIRAST_SLURMD_PORT=6928 SLURM_CONF=" +
                          state + "/slurm.conf ";
  struct Stop {
    std::string cmd;
    ~Stop() { run_command(cmd); }
  } stop{env + kSource + "/scripts/slurm_local.sh stop " + state};
  const CommandResult start = run_command(env + kSource + "/scripts/slurm_local.sh start " + state);
  ASSERT_EQ(start.status, 0) << "Slurm did not start: " << start.err << start.out;
  single_run(d.file("single"), "");
  const CommandResult r =
      run_command(env + "TRIRAST_BIN=" + kBin + " timeout 110 " + kSource +
                  "/scripts/sweep_slurm.sh --quick --shards 4 --results " + d.file("res") + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("63 tasks in 4 shards: array job"), std::string::npos) << r.out;
  for (int k = 0; k < 4; ++k)
    EXPECT_TRUE(file_exists(d.file("res") + "/status/sim-" + std::to_string(k) + ".ok")) << k;
  for (const char* f : {"/sweep.csv", "/sweep_configs.csv"}) {
    const CommandResult c = compare(d.file("single") + f, d.file("res") + "/out" + f);
    EXPECT_EQ(c.status, 0) << c.err;
  }
  const CommandResult stopped = run_command(stop.cmd);
  EXPECT_EQ(stopped.status, 0) << stopped.err;
  for (const char* p : {"/slurmctld.pid", "/slurmd.pid", "/munged.pid"})
    EXPECT_FALSE(file_exists(state + p)) << p;
}

}  // namespace
}  // namespace trirast
