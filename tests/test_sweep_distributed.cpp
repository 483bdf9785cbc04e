// The distributed sweep: task shards, result files, the merge, and the two runners
// (scripts/sweep_slurm.sh on a local single-node Slurm, scripts/sweep_parallel.sh through GNU
// parallel); each merged CSV is compared with a single-process run's on every column but the wall
// times (scripts/sweep_compare.py).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstring>
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

// A stand-in for scripts/synth.sh --one's result file: the rows of synth_row.
std::string synth_result(const std::vector<std::string>& rows) {
  std::string out =
      "{\n  \"format\": \"trirast-sweep-result\",\n  \"version\": 2,\n  \"kind\": \"synthesis\",\n"
      "  \"rows\": [";
  for (size_t i = 0; i < rows.size(); ++i) out += (i ? ",\n    " : "\n    ") + rows[i];
  return out + "\n  ]\n}\n";
}

std::string synth_row(const std::string& unit, const std::string& target, int luts, int ffs,
                      const std::string& fmax, int s, int c, int b, int n) {
  return "{\"unit\": \"" + unit + "\", \"config\": \"x\", \"target\": \"" + target +
         "\", \"luts\": " + std::to_string(luts) + ", \"ffs\": " + std::to_string(ffs) +
         ", \"carry\": 0, \"bram\": 0, \"dsp\": 0, \"fmax_mhz\": " + fmax +
         ", \"subpixel_bits\": " + std::to_string(s) + ", \"coord_bits\": " + std::to_string(c) +
         ", \"box_bits\": " + std::to_string(b) + ", \"endpoints\": " + std::to_string(n) +
         ", \"seconds\": 60}";
}

// `text` with the first `from` after `after` replaced by `to`.
std::string replaced(std::string text, const std::string& after, const std::string& from,
                     const std::string& to) {
  const size_t at = text.find(from, text.find(after));
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
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
                   synth_result({synth_row("improved", "xilinx7", 1234, 567, "null", 8, 13, 14, 1),
                                 synth_row("trad", "ice40-pnr", 100, 50, "42.5", 8, 13, 14, 1)}));
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

// A result file and the worker pipe carry every number as it was: doubles bit for bit.
TEST(SweepDistributed, ResultFilesAndTheWorkerPipeKeepEveryNumberExactly) {
  TempDir d;
  mkdir(d.file("tasks").c_str(), 0777);
  const double seconds[] = {0.1, 1.0 / 3.0, 5e-324, 1.7976931348623157e308, 2.5e-7,
                            12345.678901234567, 0.0, 3.0};
  for (const double w : seconds) {
    PointResult r;
    r.read = UINT64_MAX;
    r.offered = 17;
    r.pixels = INT64_MIN;
    r.missing = INT64_MAX;
    r.cracks = -1;
    r.doubles = -1;
    r.total_cycles = uint64_t(1) << 63;
    r.wall_seconds = w;
    r.error = "line one\nline \"two\"\t\\";
    SceneFigures f;
    f.triangles = 9;
    f.reference_pixels = -5;
    f.golden_seconds = w / 7;
    SweepTask t;
    t.index = 3;
    const std::string path = task_path(d.path(), 3);
    write_task_result(path, "00ff", t, "improved-sc S8 c16 b14 K- N1", "builtin:mixed", f, r);
    ASSERT_TRUE(task_result_complete(path, "00ff", 3));
    EXPECT_FALSE(task_result_complete(path, "00fe", 3));
    EXPECT_FALSE(task_result_complete(path, "00ff", 4));
    const TaskResult back = read_task_result(path, "00ff", 3);
    for (const PointResult& x : {back.result, decode_point_result(encode_point_result(r))}) {
      EXPECT_EQ(std::memcmp(&x.wall_seconds, &r.wall_seconds, sizeof(double)), 0) << w;
      EXPECT_EQ(x.read, r.read);
      EXPECT_EQ(x.offered, r.offered);
      EXPECT_EQ(x.pixels, r.pixels);
      EXPECT_EQ(x.missing, r.missing);
      EXPECT_EQ(x.cracks, r.cracks);
      EXPECT_EQ(x.total_cycles, r.total_cycles);
      EXPECT_EQ(x.error, r.error);
    }
    EXPECT_EQ(std::memcmp(&back.scene.golden_seconds, &f.golden_seconds, sizeof(double)), 0) << w;
    EXPECT_EQ(back.scene.triangles, 9u);
    EXPECT_EQ(back.scene.reference_pixels, -5);
    const std::string text = slurp(path);
    EXPECT_NE(text.find("\"version\": " + std::to_string(kSweepResultFormat)), std::string::npos);
    EXPECT_EQ(encode_point_result(r).find('\n'), std::string::npos);  // one line through the pipe
  }
  EXPECT_THROW(decode_point_result("{\"read\": 1"), std::runtime_error);
  EXPECT_THROW(decode_point_result("{\"read\": 1}"), std::runtime_error);
}

// The hardware fronts hold buildable configurations only: an improved configuration with quotient
// truncation K (C++ model only, no RTL) is never on a front, even when it dominates; it is marked
// as a model-only what-if instead.
TEST(SweepDistributed, QuotientTruncationIsAWhatIfNeverOnAHardwareFront) {
  auto point = [](double err, double cyc, double luts, bool rtl) {
    PointSummary s;
    s.error_ppm = err;
    s.cycles_per_triangle = cyc;
    s.timed = true;
    s.area.luts = luts;
    s.area.source = rtl ? "synth:xilinx7" : "estimate";
    s.rtl = rtl;
    return s;
  };
  // 0: exact and big; 1: K, dominating 2 on both; 2: hardware; 3: K, dominated by 0.
  std::vector<PointSummary> all = {point(0, 10, 6000, true), point(5, 8, 4000, false),
                                   point(10, 9, 5000, true), point(20, 11, 7000, false)};
  mark_pareto(all);
  EXPECT_TRUE(all[0].pareto_cycles && all[0].pareto_area);
  EXPECT_FALSE(all[1].pareto_cycles || all[1].pareto_area);
  EXPECT_TRUE(all[1].whatif_cycles && all[1].whatif_area);
  EXPECT_TRUE(all[2].pareto_cycles && all[2].pareto_area);  // K does not push it off
  EXPECT_FALSE(all[2].whatif_cycles || all[2].whatif_area);
  EXPECT_FALSE(all[3].pareto_cycles || all[3].pareto_area || all[3].whatif_cycles ||
               all[3].whatif_area);
  SweepPoint k;
  k.engine = "improved-sc";
  k.cfg.divider_quotient_bits = 6;
  EXPECT_FALSE(k.rtl());
  k.cfg.divider_quotient_bits = 0;
  EXPECT_TRUE(k.rtl());
  k.engine = "trad-sc";
  EXPECT_TRUE(k.rtl());
  k.engine = "float-scanline";
  EXPECT_FALSE(k.rtl());
}

// The synthesis rounds of a distributed run: --synth-todo lists the buildable front configurations
// (and both default units) whose area is not from the run's own synthesis jobs, docs/synth.csv
// rows included (they may be of an older RTL), never a K configuration; once each listed
// configuration has a result file, no front point carries an estimated or reused area.
TEST(SweepDistributed, EveryHardwareFrontPointIsSynthesizedByTheRun) {
  TempDir d;
  const std::string res = d.file("res");
  const CommandResult sim =
      run_command(kBin + " sweep --quick --no-progress" + kArea + " --shard 0/1 --out " + res);
  ASSERT_EQ(sim.status, 0) << sim.err;
  mkdir((res + "/synth").c_str(), 0777);
  std::set<std::string> synthesized;
  std::string first_todo;
  int rounds = 0;
  for (; rounds < 8; ++rounds) {
    const std::string todo = d.file("todo-" + std::to_string(rounds));
    const CommandResult m = run_command(kBin + " sweep --quick --no-progress" + kArea +
                                        " --merge " + res + " --out " + d.file("m") +
                                        " --synth-todo " + todo);
    ASSERT_EQ(m.status, 0) << m.err;
    const std::string list = slurp(todo);
    if (rounds == 0) first_todo = list;
    if (list.empty()) break;
    std::istringstream in(list);
    std::string line;
    while (std::getline(in, line)) {
      EXPECT_TRUE(synthesized.insert(line).second) << "listed twice: " << line;
      // A stand-in for scripts/synth.sh --one (its result file format): made-up figures.
      std::vector<int> f;
      std::string unit = line.substr(0, line.find(':')), rest = line.substr(line.find(':') + 1);
      std::istringstream fs(rest);
      for (std::string x; std::getline(fs, x, ':');) f.push_back(std::stoi(x));
      ASSERT_EQ(f.size(), 4u) << line;
      const int luts = (unit == "trad" ? 900 : 2000) + 100 * f[0] + 50 * f[1] + 20 * f[2] + 3000 * (f[3] - 1);
      test::write_file(res + "/synth/" + unit + "-" + std::to_string(rounds) + "-" +
                           std::to_string(synthesized.size()) + ".synth",
                       synth_result({synth_row(unit, "xilinx7", luts, luts / 3, "null", f[0], f[1],
                                               f[2], f[3])}));
    }
  }
  ASSERT_LT(rounds, 8) << "the synthesis rounds did not converge";
  // docs/synth.csv covers both default units, yet they are redone (this tree's RTL).
  EXPECT_NE(first_todo.find("improved:8:16:14:1\n"), std::string::npos) << first_todo;
  EXPECT_NE(first_todo.find("trad:8:16:14:1\n"), std::string::npos) << first_todo;
  // The final merge: every front point is buildable and synthesized by the run; K never on one.
  std::istringstream csv(slurp(d.file("m/sweep_configs.csv")));
  std::string header, row;
  std::getline(csv, header);
  std::map<std::string, size_t> col;
  {
    std::istringstream hs(header);
    size_t i = 0;
    for (std::string h; std::getline(hs, h, ',');) col[h] = i++;
  }
  for (const char* c : {"pareto_cycles", "pareto_area", "area_source", "quotient_bits", "rtl",
                        "whatif_cycles", "whatif_area", "unit", "subpixel_bits", "coord_bits",
                        "box_bits", "endpoints"})
    ASSERT_TRUE(col.count(c)) << c;
  int front = 0, k_rows = 0;
  while (std::getline(csv, row)) {
    std::vector<std::string> f;
    std::string cell;
    bool q = false;
    for (char ch : row) {
      if (ch == '"') q = !q;
      else if (ch == ',' && !q) { f.push_back(cell); cell.clear(); }
      else cell += ch;
    }
    f.push_back(cell);
    ASSERT_EQ(f.size(), col.size()) << row;
    const bool on_front = f[col["pareto_cycles"]] == "1" || f[col["pareto_area"]] == "1";
    const bool k = !f[col["quotient_bits"]].empty() && f[col["quotient_bits"]] != "0";
    if (k) {
      ++k_rows;
      EXPECT_FALSE(on_front) << row;
      EXPECT_EQ(f[col["rtl"]], "0") << row;
      EXPECT_EQ(f[col["area_source"]], "estimate") << row;
    }
    if (f[col["whatif_cycles"]] == "1" || f[col["whatif_area"]] == "1") {
      EXPECT_EQ(f[col["rtl"]], "0") << row;
    }
    if (!on_front) continue;
    ++front;
    EXPECT_EQ(f[col["rtl"]], "1") << row;
    EXPECT_EQ(f[col["area_source"]], "synth:xilinx7") << row;
    // ... from one of the run's synthesis results, not docs/synth.csv.
    const bool trad = f[col["unit"]] == "trad";
    const std::string line = f[col["unit"]] + ":" + f[col["subpixel_bits"]] + ":" +
                             f[col["coord_bits"]] + ":" + (trad ? "14" : f[col["box_bits"]]) +
                             ":" + (trad ? "1" : f[col["endpoints"]]);
    EXPECT_TRUE(synthesized.count(line)) << line;
  }
  EXPECT_GT(front, 0);
  EXPECT_GT(k_rows, 0);
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
  test::write_file(task_file(res, 5), task5.substr(0, task5.rfind('}')));
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": cut short");
  test::write_file(task_file(res, 5), "");
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": cut short");
  // Mixed versions: another task list or build (fingerprint), another format version (the text
  // format before JSON among them).
  std::string other = task5;
  const size_t at = other.find("\"fingerprint\": \"") + 16;
  other[at] = other[at] == '0' ? '1' : '0';
  test::write_file(task_file(res, 5), other);
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": fingerprint");
  test::write_file(task_file(res, 5), replaced(task5, "", "\"version\": 2", "\"version\": 3"));
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": result format 3");
  test::write_file(task_file(res, 5), "trirast-sweep-result 1\nfingerprint 0\ntask 5\nend\n");
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": result format 1 (text)");
  // Not a result of this format, a member missing or of another type, another task's file.
  test::write_file(task_file(res, 5), "{\"format\": \"something else\"}\n");
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": not a sweep result file");
  test::write_file(task_file(res, 5), "{\"format\": \"trirast-sweep-result\", x}\n");
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": not a sweep result file");
  test::write_file(task_file(res, 5),
                   replaced(task5, "\"result\"", "\"pixels\": ", "\"pixels\": 0.5, \"p\": "));
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": malformed 'result.pixels'");
  test::write_file(task_file(res, 5), replaced(task5, "\"result\"", "\"spans\": ", "\"spans\": -"));
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": malformed 'result.spans'");
  test::write_file(task_file(res, 5), replaced(task5, "\"result\"", "\"error\": ", "\"error2\": "));
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": no 'result.error'");
  test::write_file(task_file(res, 5), slurp(task_file(res, 6)));
  expect_one_line_error(merge(d.file("bad")), task_file(res, 5) + ": holds task 6, not task 5");
  test::write_file(task_file(res, 5), task5);
  // A synthesis result cut short, of another format or kind, or with a malformed row.
  mkdir((res + "/synth").c_str(), 0777);
  const std::string synth =
      synth_result({synth_row("trad", "xilinx7", 900, 300, "null", 8, 16, 14, 1)});
  test::write_file(res + "/synth/x.synth", synth.substr(0, synth.size() - 4));
  expect_one_line_error(merge(d.file("bad")), res + "/synth/x.synth: cut short");
  test::write_file(res + "/synth/x.synth", "# trirast-synth-result 1\n# end\n");
  expect_one_line_error(merge(d.file("bad")), res + "/synth/x.synth: result format 1 (text)");
  test::write_file(res + "/synth/x.synth", replaced(synth, "", "\"version\": 2", "\"version\": 9"));
  expect_one_line_error(merge(d.file("bad")), res + "/synth/x.synth: result format 9");
  test::write_file(res + "/synth/x.synth", task5);
  expect_one_line_error(merge(d.file("bad")),
                        res + "/synth/x.synth: holds a simulation result, not a synthesis result");
  test::write_file(res + "/synth/x.synth", replaced(synth, "", "\"luts\": 900", "\"luts\": null"));
  expect_one_line_error(merge(d.file("bad")), res + "/synth/x.synth: malformed 'rows[0].luts'");
  test::write_file(res + "/synth/x.synth", synth_result({}));
  expect_one_line_error(merge(d.file("bad")), res + "/synth/x.synth: no result row");
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
  // The finished tasks are those with a result file: a task's "ran" line in run.log follows its
  // file, so a kill between the two leaves a finished task without its line.
  std::map<int, long> mtime;  // modification times of the finished tasks' files
  for (int i = 0; i < 63; ++i) {
    struct stat st;
    if (stat(task_file(res, i).c_str(), &st) == 0)
      mtime[i] = long(st.st_mtim.tv_sec) * 1000000000L + st.st_mtim.tv_nsec;
  }
  ASSERT_GE(mtime.size(), 12u);
  ASSERT_LT(mtime.size(), 63u) << "the run finished before it was killed";
  const int deleted = mtime.begin()->first;
  ASSERT_EQ(std::remove(task_file(res, deleted).c_str()), 0);
  const size_t log_before = slurp(res + "/run.log").size();

  const CommandResult r =
      run_command("TRIRAST_BIN=" + kBin + " " + kSource + "/scripts/sweep_parallel.sh --quick " +
                  "--jobs 2 --results " + res + " -- " + scenes + " 2>&1");
  ASSERT_EQ(r.status, 0) << r.out;
  // The rerun's log: every task without a file ran once, every other one was skipped.
  std::map<int, int> ran, skipped;
  std::istringstream in(slurp(res + "/run.log").substr(log_before));
  std::string word;
  for (int i; in >> word >> i;) {
    ++(word == "ran" ? ran : skipped)[i];
    std::getline(in, word);
  }
  for (int i = 0; i < 63; ++i) {
    const bool was_done = mtime.count(i) && i != deleted;
    EXPECT_TRUE(file_exists(task_file(res, i))) << "task " << i;
    EXPECT_EQ(ran[i], was_done ? 0 : 1) << "task " << i << (was_done ? " was redone" : " did not run");
    EXPECT_EQ(skipped[i], was_done ? 1 : 0) << "task " << i;
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
