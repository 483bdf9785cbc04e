// The trirast program as a user meets it: outputs, bad input, exit statuses, and a .tri file
// written by an independent program checked against the D3D11 rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "support/run_command.hpp"

namespace trirast {
namespace {

using test::CommandResult;
using test::count_lines;
using test::kBin;
using test::run_command;
using test::slurp;
using test::TempDir;
using test::write_file;

// A bad input: exit status 2, exactly one line on stderr containing `needle`, nothing on disk.
void expect_one_line_error(const std::string& args, const std::string& needle, TempDir& dir) {
  const std::string spans = dir.file("out.spans"), image = dir.file("out.png"),
                    report = dir.file("out.json");
  const int before = dir.entry_count();
  CommandResult r = run_command(kBin + " " + args + " --spans " + spans + " --image " + image +
                                " --report " + report);
  EXPECT_EQ(r.status, 2) << args << "\nstderr: " << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << args << "\nstderr: " << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << args << "\nstderr: " << r.err
                                                   << "\nexpected to contain: " << needle;
  EXPECT_EQ(dir.entry_count(), before) << args << ": output files left behind";
}

TEST(CliBadInput, TriFiles) {
  TempDir dir;
  struct Case {
    std::string name, content, needle;
  };
  const std::vector<Case> cases = {
      {"empty.tri", "", "empty.tri"},
      {"comments.tri", "# only a comment\n\n", "comments.tri"},
      {"truncated.tri", "0 0 10 0 0 10\n1 2 3 4 5\n", "truncated.tri:2"},
      {"text.tri", "0 0 10 0 0 10\n# fine\n0 0 abc 0 0 10\n", "text.tri:3"},
      {"toomany.tri", "0 0 10 0 0 10 7\n", "toomany.tri:1"},
      {"nan.tri", "0 0 10 0 0 10\nnan 0 10 0 0 10\n", "nan.tri:2"},
      {"inf.tri", "0 0 10 0 inf 10\n", "inf.tri:1"},
      {"huge.tri", "\n0 0 1e300 0 0 10\n", "huge.tri:2"},
      {"overflow.tri", "0 0 1e999 0 0 10\n", "overflow.tri:1"},
      {"outside.tri", "0 0 40000 0 0 10\n", "outside.tri:1"},
      {"garbage.tri", std::string("\x7f\x45\x4c\x46\x02\x01\x00\x00\xff\xfe", 10), "garbage.tri"},
  };
  for (const Case& c : cases) {
    write_file(dir.file(c.name), c.content);
    expect_one_line_error("raster --scene " + dir.file(c.name), c.needle, dir);
  }
  expect_one_line_error("raster --scene " + dir.path(), dir.path(), dir);  // a directory
  expect_one_line_error("raster --scene " + dir.file("missing.tri"), "missing.tri", dir);
}

TEST(CliBadInput, MeshFileThatIsNotAMesh) {
  TempDir dir;
  write_file(dir.file("fake.obj"), std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
  expect_one_line_error("raster --scene " + dir.file("fake.obj"), "fake.obj", dir);
  write_file(dir.file("fake.stl"), "this is not an STL file at all\n");
  expect_one_line_error("raster --scene " + dir.file("fake.stl"), "fake.stl", dir);
}

TEST(CliBadInput, Options) {
  TempDir dir;
  const std::string scene = " --scene builtin:fan";
  expect_one_line_error("raster" + scene + " --width 0", "--width", dir);
  expect_one_line_error("raster" + scene + " --height 100000", "--height", dir);
  expect_one_line_error("raster" + scene + " --width abc", "--width", dir);
  expect_one_line_error("raster" + scene + " --subpixel-bits 9", "--subpixel-bits", dir);
  expect_one_line_error("raster" + scene + " --frobnicate 3", "--frobnicate", dir);
  expect_one_line_error("raster" + scene + " --engine nosuch", "nosuch", dir);
  expect_one_line_error("raster" + scene + " --cull sideways", "--cull", dir);
  expect_one_line_error("raster" + scene + " --fov 0", "--fov", dir);
  expect_one_line_error("raster", "--scene", dir);
  expect_one_line_error("raster --scene builtin:nosuchscene", "nosuchscene", dir);
  expect_one_line_error("raster --scene builtin:fan:nosuchkey=1", "nosuchkey", dir);
  expect_one_line_error("frobnicate", "frobnicate", dir);
  // raster --vectors (the testbench kit, docs/port.md): engines without an RTL top or cycles,
  // widths other than the RTL package's, a downstream that reacts to the spans it takes.
  const std::string vectors = " --vectors " + dir.file("vectors");
  expect_one_line_error("raster" + scene + " --engine golden" + vectors, "--vectors", dir);
  expect_one_line_error("raster" + scene + " --engine improved-datapath" + vectors, "--vectors", dir);
  expect_one_line_error("raster" + scene + " --engine improved-sc --subpixel-bits 4" + vectors,
                        "--subpixel-bits 8", dir);
  expect_one_line_error("raster" + scene + " --engine trad-sc --sink-stall queue:2:16" + vectors,
                        "--sink-stall queue:2:16", dir);
}

TEST(Cli, RasterVectorsWritesTheKitsDirectory) {
  TempDir dir;
  const std::string out = dir.file("v");
  CommandResult r = run_command(kBin + " raster --scene builtin:fan:n=4 --engine halfspace-sc " +
                                "--sink-stall periodic:2:1 --vectors " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  // One line per triangle in tris.hex and expect.hex; spans.hex as many lines as the spans.
  auto lines = [&](const std::string& name) {
    std::ifstream in(out + "/" + name);
    std::string l;
    size_t n = 0;
    while (std::getline(in, l)) ++n;
    return n;
  };
  EXPECT_EQ(lines("tris.hex"), 4u);
  EXPECT_EQ(lines("expect.hex"), 4u);
  EXPECT_GT(lines("spans.hex"), 4u);
  std::ifstream params(out + "/params.txt"), args(out + "/plusargs.txt"), readme(out + "/README.txt");
  std::string p((std::istreambuf_iterator<char>(params)), {}), a((std::istreambuf_iterator<char>(args)), {});
  EXPECT_EQ(p, "unit halfspace\nFifoDepth 8\nStampSize 2\nTileSize 8\nWalkMode 2\nCornerForm 0\n");
  EXPECT_NE(a.find("+ntris=4 +nspans=" + std::to_string(lines("spans.hex")) + " "), std::string::npos) << a;
  EXPECT_NE(a.find("+sink=periodic +sink_ready=2 +sink_stall=1 "), std::string::npos) << a;
  EXPECT_TRUE(readme.good());
}

TEST(CliBadInput, UnwritableOutputLeavesNothing) {
  TempDir dir;
  CommandResult r = run_command(kBin + " raster --scene builtin:fan --spans " + dir.file("x.spans") +
                                " --image " + dir.file("no/such/dir/x.png"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--image"), std::string::npos) << r.err;
  EXPECT_EQ(dir.entry_count(), 0);
}

TEST(Cli, HelpOnEverySubcommand) {
  for (const std::string cmd : {"", "raster ", "compare ", "scenes ", "engines "}) {
    CommandResult r = run_command(kBin + " " + cmd + "--help");
    EXPECT_EQ(r.status, 0) << cmd;
    EXPECT_NE(r.out.find("usage: trirast"), std::string::npos) << cmd << r.out;
  }
  // --help lists every option the parser accepts, with defaults.
  CommandResult r = run_command(kBin + " raster --help");
  for (const char* opt : {"--engine", "--scene", "--width", "--height", "--subpixel-bits", "--spans",
                          "--image", "--report", "--cull", "--yaw", "--pitch", "--distance", "--fov"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
}

// The option forms the parser accepts and the one-line errors it gives (cli/args.cpp on CLI11):
// --opt value and --opt=value alike, a range declared with the option checked while parsing and
// shown in --help, a repeated flag accepted, a repeated valued option refused.
TEST(Cli, OptionFormsAndParserErrors) {
  TempDir dir;
  const std::string raster = kBin + " raster --scene builtin:fan --subpixel-bits 4 ";
  ASSERT_EQ(run_command(raster + "--width 64 --height 48 --spans " + dir.file("a")).status, 0);
  ASSERT_EQ(run_command(raster + "--width=64 --height=48 --spans=" + dir.file("b")).status, 0);
  EXPECT_EQ(slurp(dir.file("a")), slurp(dir.file("b")));
  EXPECT_GT(count_lines(slurp(dir.file("a"))), 10);

  const CommandResult help = run_command(kBin + " raster --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("--width W:1..16384"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("(default: 1024)"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("--engine NAME"), std::string::npos) << help.out;
  const CommandResult short_help = run_command(kBin + " raster -h");
  EXPECT_EQ(short_help.status, 0);
  EXPECT_EQ(short_help.out, help.out);

  const CommandResult repeated_flag = run_command(kBin + " sweep --quick --quick --list-tasks");
  EXPECT_EQ(repeated_flag.status, 0) << repeated_flag.err;

  struct Case {
    std::string args, message;
  };
  const std::vector<Case> cases = {
      {"raster --scene builtin:fan --width 10 --width 20", "trirast raster: option '--width' given twice"},
      {"raster --scene builtin:fan --width", "trirast raster: option '--width' needs a value"},
      {"raster --scene builtin:fan --width 0", "trirast raster: --width: 0 is outside 1..16384"},
      {"raster --scene builtin:fan --width=abc", "trirast raster: --width: 'abc' is not an integer"},
      {"raster --scene builtin:fan --width=", "trirast raster: --width: '' is not an integer"},
      {"raster --scene builtin:fan --frobnicate=3",
       "trirast raster: unknown option '--frobnicate' (see trirast raster --help)"},
      {"raster --scene builtin:fan stray",
       "trirast raster: unexpected argument 'stray' (see trirast raster --help)"},
      {"sweep --quick=1 --list-tasks", "trirast sweep: option '--quick' takes no value"},
  };
  for (const Case& c : cases) {
    const CommandResult r = run_command(kBin + " " + c.args);
    EXPECT_EQ(r.status, 2) << c.args;
    EXPECT_EQ(r.err, c.message + "\n") << c.args;
    EXPECT_EQ(r.out, "") << c.args;
  }
}

TEST(Cli, RasterWritesSortedSpansImageAndReport) {
  TempDir dir;
  write_file(dir.file("two.tri"), "# two triangles\n10 10 50 12 20 40\n\n60.5 5 90 30 61 44 # tail\n");
  CommandResult r = run_command(kBin + " raster --engine golden --scene " + dir.file("two.tri") +
                                " --width 100 --height 50 --spans " + dir.file("s") + " --image " +
                                dir.file("i.png") + " --report " + dir.file("r.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string spans = slurp(dir.file("s"));
  ASSERT_GT(count_lines(spans), 10);
  // Sorted by tri, then y; only "tri y x_begin x_end" lines; both triangles present.
  std::istringstream in(spans);
  long tri, y, b, e, last_tri = -1, last_y = -1;
  bool seen[2] = {false, false};
  while (in >> tri >> y >> b >> e) {
    ASSERT_TRUE(tri > last_tri || (tri == last_tri && y > last_y));
    ASSERT_LT(b, e);
    seen[tri] = true;
    last_tri = tri;
    last_y = y;
  }
  EXPECT_TRUE(in.eof());
  EXPECT_TRUE(seen[0] && seen[1]);
  EXPECT_EQ(slurp(dir.file("i.png")).substr(1, 3), "PNG");
  const std::string json = slurp(dir.file("r.json"));
  for (const char* key : {"\"engine\": \"golden\"", "\"read\": 2", "\"culled\": 0", "\"degenerate\": 0",
                          "\"spans\":", "\"pixels\":", "\"wall_seconds\""})
    EXPECT_NE(json.find(key), std::string::npos) << key << "\n" << json;
}

// Acceptance: a .tri file written by another program, with vertices on the
// 1/256 grid inside the viewport, gives exactly the pixels of the D3D11 rule.
TEST(Cli, IndependentD3D11ProgramAgrees) {
  TempDir dir;
  for (int seed : {1, 2, 3}) {
    CommandResult gen = run_command("/usr/bin/python3 " TRIRAST_SOURCE_DIR
                                    "/scripts/d3d11_reference.py " + dir.file("s.tri") + " " +
                                    dir.file("expected.spans") + " --seed " + std::to_string(seed));
    ASSERT_EQ(gen.status, 0) << gen.err;
    CommandResult r = run_command(kBin + " raster --scene " + dir.file("s.tri") +
                                  " --width 320 --height 240 --spans " + dir.file("got.spans"));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string expected = slurp(dir.file("expected.spans"));
    EXPECT_GT(count_lines(expected), 1000);
    EXPECT_EQ(slurp(dir.file("got.spans")), expected) << "seed " << seed;
    // The same through compare with the recorded spans as an engine.
    CommandResult c = run_command(kBin + " compare --width 320 --height 240 --scene " +
                                  dir.file("s.tri") + " --engines golden,file:" +
                                  dir.file("expected.spans"));
    EXPECT_EQ(c.status, 0) << c.out << c.err;
  }
}

TEST(Cli, CompareExitStatusBothWays) {
  TempDir dir;
  write_file(dir.file("t.tri"), "10 10 50 12 20 40\n");
  ASSERT_EQ(run_command(kBin + " raster --scene " + dir.file("t.tri") + " --spans " +
                        dir.file("good.spans")).status, 0);
  CommandResult ok = run_command(kBin + " compare --scene " + dir.file("t.tri") +
                                 " --engines golden,file:" + dir.file("good.spans"));
  EXPECT_EQ(ok.status, 0) << ok.out;
  // One pixel removed from one span: an exact engine now disagrees -> exit 1.
  std::string spans = slurp(dir.file("good.spans"));
  std::istringstream in(spans);
  std::string first;
  std::getline(in, first);
  long tri, y, b, e;
  std::istringstream(first) >> tri >> y >> b >> e;
  write_file(dir.file("bad.spans"), std::to_string(tri) + " " + std::to_string(y) + " " +
                                        std::to_string(b + 1) + " " + std::to_string(e) + "\n" +
                                        spans.substr(first.size() + 1));
  CommandResult bad = run_command(kBin + " compare --scene " + dir.file("t.tri") +
                                  " --engines golden,file:" + dir.file("bad.spans") +
                                  " --diff-image " + dir.file("d.png"));
  EXPECT_EQ(bad.status, 1) << bad.out;
  EXPECT_NE(bad.out.find("DISAGREES"), std::string::npos) << bad.out;
  EXPECT_TRUE(test::file_exists(dir.file("d.png")));
}

// compare's table: the timed engines' total cycles in the cycles column (the model's and the
// RTL's the same number, the one raster --report gives), "-" for untimed ones; the work column
// holds the engine's own counters, not the per-module ones, which --report keeps.
TEST(Cli, CompareShowsCyclesOfTimedEnginesAndShortWork) {
  TempDir dir;
  ASSERT_EQ(run_command(kBin + " raster --scene builtin:fan --engine improved-sc --report " +
                        dir.file("m.json"))
                .status,
            0);
  const std::string report = slurp(dir.file("m.json"));
  const size_t at = report.find("\"total_cycles\":");
  ASSERT_NE(at, std::string::npos) << report;
  const long long cycles = std::stoll(report.substr(at + 15));
  ASSERT_GT(cycles, 0);
  CommandResult r = run_command(
      kBin +
      " compare --scene builtin:fan --engines golden,improved-datapath,improved-sc,improved-rtl");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  auto row = [&](const std::string& engine) {
    const size_t b = r.out.find("\n  " + engine + " ");
    EXPECT_NE(b, std::string::npos) << r.out;
    if (b == std::string::npos) return std::vector<std::string>{};
    std::istringstream line(r.out.substr(b + 1, r.out.find('\n', b + 1) - b - 1));
    std::vector<std::string> cells;
    for (std::string c; line >> c;) cells.push_back(c);
    return cells;
  };
  // engine exact spans pixels missing extra seconds cycles us@Fmax work...
  for (const std::string engine : {"improved-sc", "improved-rtl"}) {
    const auto cells = row(engine);
    ASSERT_GE(cells.size(), 8u) << engine;
    EXPECT_EQ(cells[7], std::to_string(cycles)) << engine << "\n" << r.out;
  }
  for (const std::string engine : {"golden", "improved-datapath"}) {
    const auto cells = row(engine);
    ASSERT_GE(cells.size(), 8u) << engine;
    EXPECT_EQ(cells[7], "-") << engine << "\n" << r.out;
  }
  EXPECT_EQ(r.out.find("busy_cycles."), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("divider_iterations="), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--report FILE.json"), std::string::npos) << r.out;
}

// compare's time column: a timed engine's cycles at its unit's routed iCE40 HX8K Fmax, as
// docs/synth.csv records it for the run's widths (the improved2 unit's row, here), "n/a" where no
// routed row applies (the first generation, which does not fit; a FIFO depth synthesis did not
// build), "-" for untimed engines; the footnote names the row; --report has the same numbers.
TEST(Cli, CompareTimeColumnFromTheRoutedFmax) {
  // The improved2 unit's routed Fmax, read from the CSV as the program reads it: the fmax_mhz
  // column named by the header line.
  double fmax = 0;
  std::istringstream csv(slurp(std::string(TRIRAST_SOURCE_DIR) + "/docs/synth.csv"));
  auto fields = [](const std::string& line) {
    std::vector<std::string> f;
    std::istringstream in(line);
    for (std::string c; std::getline(in, c, ',');) f.push_back(c);
    return f;
  };
  std::string line;
  ASSERT_TRUE(std::getline(csv, line)) << "docs/synth.csv is empty";
  const std::vector<std::string> header = fields(line);
  const size_t col = size_t(std::find(header.begin(), header.end(), "fmax_mhz") - header.begin());
  ASSERT_LT(col, header.size()) << "docs/synth.csv has no fmax_mhz column: " << line;
  while (std::getline(csv, line))
    if (line.rfind("improved2,default,ice40,", 0) == 0) {
      const std::vector<std::string> f = fields(line);
      ASSERT_LT(col, f.size()) << line;
      fmax = std::stod(f[col]);
    }
  ASSERT_GT(fmax, 0) << "docs/synth.csv has no routed improved2 row";
  TempDir dir;
  const std::string base = kBin + " compare --scene builtin:fan --engines improved2-sc,improved-sc,improved2-datapath";
  CommandResult r = run_command(base + " --report " + dir.file("c.json"));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  auto cells_of = [&](const std::string& out, const std::string& engine) {
    const size_t b = out.find("\n  " + engine + " ");
    std::istringstream line(b == std::string::npos ? "" : out.substr(b + 1, out.find('\n', b + 1) - b - 1));
    std::vector<std::string> cells;
    for (std::string c; line >> c;) cells.push_back(c);
    return cells;
  };
  const auto i2 = cells_of(r.out, "improved2-sc");
  ASSERT_GE(i2.size(), 9u) << r.out;
  char expect[32];
  std::snprintf(expect, sizeof expect, "%.1f", std::stod(i2[7]) / fmax);
  EXPECT_EQ(i2[8], expect) << r.out;
  EXPECT_EQ(cells_of(r.out, "improved-sc").at(8), "n/a") << r.out;
  EXPECT_EQ(cells_of(r.out, "improved2-datapath").at(8), "-") << r.out;
  char mhz[64];
  std::snprintf(mhz, sizeof mhz, "improved2-sc %.2f MHz (improved2)", fmax);
  EXPECT_NE(r.out.find(mhz), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("improved-sc none: no routed row of improved"), std::string::npos) << r.out;
  const std::string report = slurp(dir.file("c.json"));
  EXPECT_NE(report.find("\"microseconds_at_fmax\""), std::string::npos) << report;
  EXPECT_NE(report.find("\"fmax_source\": \"" + std::string(mhz).substr(13)), std::string::npos) << report;
  // A FIFO depth that synthesis did not build: no routed clock applies.
  r = run_command(base + " --fifo-depth 4");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(cells_of(r.out, "improved2-sc").at(8), "n/a") << r.out;
}

// Engine names: the list shows <unit>-<view> names and the reference engines; the old names
// (unit, model, rtl, trad, rtl-trad) are unknown engines like any other: a one-line error naming
// the option and the name.
TEST(CliEngineNames, ListedNamesOnlyOldNamesRefused) {
  const CommandResult list = run_command(kBin + " engines");
  ASSERT_EQ(list.status, 0) << list.err;
  std::vector<std::string> names;
  std::istringstream lines(list.out);
  for (std::string line; std::getline(lines, line);)
    names.push_back(line.substr(0, line.find(' ')));
  for (const std::string name :
       {"golden", "improved-datapath", "improved-sc", "trad-sc", "float-scanline"})
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name << "\n" << list.out;
  TempDir dir;
  for (const std::string old_name : {"unit", "model", "rtl", "trad", "rtl-trad"}) {
    EXPECT_EQ(std::find(names.begin(), names.end(), old_name), names.end()) << old_name;
    expect_one_line_error("raster --scene builtin:fan --engine " + old_name,
                          "--engine: unknown engine '" + old_name + "'", dir);
    const CommandResult c =
        run_command(kBin + " compare --scene builtin:fan --engines golden," + old_name);
    EXPECT_EQ(c.status, 2) << c.err;
    EXPECT_EQ(count_lines(c.err), 1) << c.err;
    EXPECT_NE(c.err.find("--engines: unknown engine '" + old_name + "'"), std::string::npos) << c.err;
    EXPECT_EQ(c.out, "");
  }
  const CommandResult f =
      run_command(kBin + " fuzz --scenes 1 --seed 1 --engines golden,unit --out " + dir.path());
  EXPECT_EQ(f.status, 2) << f.err;
  EXPECT_NE(f.err.find("--engines: unknown engine 'unit'"), std::string::npos) << f.err;

  expect_one_line_error("raster --scene builtin:fan --engine models", "--engine", dir);
  expect_one_line_error("raster --scene builtin:fan --engine models", "'models'", dir);
  const CommandResult u = run_command(kBin + " compare --scene builtin:fan --engines golden,rtl-trads");
  EXPECT_EQ(u.status, 2) << u.err;
  EXPECT_EQ(count_lines(u.err), 1) << u.err;
  EXPECT_NE(u.err.find("--engines: unknown engine 'rtl-trads'"), std::string::npos) << u.err;
}

}  // namespace
}  // namespace trirast
