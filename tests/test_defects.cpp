// Defects a new user hit: one test (or a few) per defect, each failing on the code
// before its fix. Every command runs the trirast program as a user would.
#include <gtest/gtest.h>
#include <png.h>
#include <signal.h>
#include <sys/stat.h>
#include <utime.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"
#include "support/signal_command.hpp"

using trirast::test::CommandResult;
using trirast::test::file_exists;
using trirast::test::run_and_signal;
using trirast::test::run_command;
using trirast::test::TempDir;
using trirast::test::write_file;

namespace {

// TRIRAST_TEST_BIN runs the tests against another build (e.g. the tree before the fixes).
const std::string kBin = std::getenv("TRIRAST_TEST_BIN") ? std::getenv("TRIRAST_TEST_BIN") : TRIRAST_BIN;
const std::string kSrc = TRIRAST_SOURCE_DIR;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Every "wrote PATH (...)" line of a run's stdout names a file that exists and was written at or
// after `since` (not a stale one from an earlier run).
void expect_wrote_lines_true(const std::string& out, time_t since) {
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    const size_t w = line.find("wrote ");
    if (w == std::string::npos) continue;
    std::istringstream fields(line.substr(w + 6));
    std::string path;
    fields >> path;
    struct stat st;
    ASSERT_EQ(stat(path.c_str(), &st), 0) << "reported but missing: " << line;
    EXPECT_GE(st.st_mtime, since) << "reported but not written by this run: " << line;
  }
}

// ---- 1. --trace file types and the save file -----------------------------------------------
TEST(DefectTrace, ScEngineFstIsARealFstWithItsSaveFile) {
  TempDir dir;
  const CommandResult r = run_command(kBin + " raster --scene builtin:lowpoly-far --engine improved-sc --trace " +
                                      dir.file("x.fst"));
  if (r.status == 2) {  // refusing .fst is allowed: one line naming --trace, nothing written
    EXPECT_NE(r.err.find("--trace"), std::string::npos) << r.err;
    EXPECT_EQ(dir.entry_count(), 0);
    return;
  }
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string fst = slurp(dir.file("x.fst"));
  ASSERT_FALSE(fst.empty());
  EXPECT_NE(fst[0], '$') << "x.fst holds VCD text";
  const CommandResult back = run_command("fst2vcd -f " + dir.file("x.fst"));
  EXPECT_EQ(back.status, 0) << back.err;
  EXPECT_NE(back.out.find("$enddefinitions"), std::string::npos);
  EXPECT_TRUE(file_exists(dir.file("x.gtkw")));
  EXPECT_FALSE(file_exists(dir.file("x.fst.gtkw")));
  EXPECT_NE(r.out.find("x.gtkw"), std::string::npos) << r.out;
  // x.fst, x.gtkw, its two translate filters (x.setup_state.filter, x.walk_state.filter), no temporary
  EXPECT_TRUE(file_exists(dir.file("x.setup_state.filter")));
  EXPECT_EQ(dir.entry_count(), 4);
}

TEST(DefectTrace, WroteLinesNameOnlyFilesOfThisRun) {
  TempDir dir;
  // A stale save file from an earlier run, dated 2001.
  write_file(dir.file("t.gtkw"), "[dumpfile] \"old\"\n");
  struct utimbuf old_time = {1000000000, 1000000000};
  utime(dir.file("t.gtkw").c_str(), &old_time);
  const time_t start = time(nullptr) - 1;
  const CommandResult r = run_command(kBin + " raster --scene builtin:lowpoly-far --engine improved-rtl --trace " +
                                      dir.file("t.vcd"));
  ASSERT_EQ(r.status, 0) << r.err;
  expect_wrote_lines_true(r.out, start);
}

TEST(DefectTrace, UntimedEngineRefusesTrace) {
  TempDir dir;
  for (const char* engine : {"golden", "improved-datapath", "float-scanline"}) {
    const CommandResult r = run_command(kBin + " raster --scene builtin:lowpoly-far --engine " +
                                        engine + " --trace " + dir.file("u.vcd"));
    EXPECT_EQ(r.status, 2) << engine << ": " << r.out;
    EXPECT_NE(r.err.find("--trace"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("wrote"), std::string::npos) << r.out;
    EXPECT_EQ(dir.entry_count(), 0);
  }
}

// ---- 2. interrupts ----------------------------------------------------------------------------
void expect_interrupted(const trirast::test::SignalledResult& r, int sig) {
  ASSERT_FALSE(r.exited_before_signal) << "the run ended before the signal: make it longer";
  EXPECT_EQ(r.status, 128 + sig);
  // One line says so, the last one (a sweep prints its plan before).
  const std::string last = "trirast: interrupted\n";
  EXPECT_TRUE(r.err.size() >= last.size() && r.err.compare(r.err.size() - last.size(), last.size(), last) == 0) << r.err;
  EXPECT_EQ(r.err.find("interrupted"), r.err.rfind("interrupted")) << r.err;
}

TEST(DefectInterrupt, RtlTraceLeavesNothing) {
  for (const char* name : {"a.vcd", "a.fst"}) {
    for (int sig : {SIGINT, SIGTERM}) {
      TempDir dir;
      const auto r = run_and_signal(kBin + " raster --scene builtin:highpoly-near --engine improved-rtl --trace " +
                                        dir.file(name),
                                    1.5, sig);
      expect_interrupted(r, sig);
      EXPECT_EQ(run_command("ls -A " + dir.path()).out, "") << name << " signal " << sig;
    }
  }
}

TEST(DefectInterrupt, SweepLeavesNoOutputFolder) {
  TempDir dir;
  const auto r = run_and_signal(kBin + " sweep --quick --no-progress --scenes 'builtin:highpoly-near;builtin:mixed' --out " +
                                    dir.file("sw"),
                                1.5,
                                SIGINT);
  expect_interrupted(r, SIGINT);
  EXPECT_EQ(run_command("ls -A " + dir.path()).out, "");
}

TEST(DefectInterrupt, ScTraceLeavesNothing) {
  TempDir dir;
  const auto r = run_and_signal(kBin + " raster --scene builtin:highpoly-near --engine improved-sc --trace " +
                                    dir.file("m.vcd"),
                                0.8, SIGTERM);
  expect_interrupted(r, SIGTERM);
  EXPECT_EQ(run_command("ls -A " + dir.path()).out, "");
}

// ---- 3. fit finds docs/synth.csv from any working directory -----------------------------------
std::string area_line(const std::string& out) {
  const size_t a = out.find("  area ");
  return a == std::string::npos ? "" : out.substr(a, out.find('\n', a) - a);
}

TEST(DefectFit, SynthCsvFromAnotherWorkingDirectory) {
  TempDir dir;
  const std::string fit = kBin + " fit --scene builtin:lowpoly-far --width 64 --height 48";
  const CommandResult in_src = run_command("cd " + kSrc + " && " + fit);
  const CommandResult elsewhere = run_command("cd " + dir.path() + " && " + fit);
  ASSERT_EQ(in_src.status, 0) << in_src.err;
  ASSERT_EQ(elsewhere.status, 0) << elsewhere.err;
  EXPECT_NE(area_line(in_src.out).find("synth"), std::string::npos) << in_src.out;
  EXPECT_EQ(area_line(elsewhere.out), area_line(in_src.out));
  EXPECT_EQ(elsewhere.err, "");
}

TEST(DefectFit, WarnsWhenItFallsBackToTheEstimate) {
  TempDir dir;
  const CommandResult r = run_command(kBin + " fit --scene builtin:lowpoly-far --width 64 --height 48 --synth-csv " +
                                      dir.file("none.csv"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("estimate"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("none.csv"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// ---- 4. options silently accepted -------------------------------------------------------------
TEST(DefectOptions, TraceTrisBeyondTheScene) {
  TempDir dir;
  const CommandResult r = run_command(kBin + " raster --scene builtin:lowpoly-far --engine improved-sc --trace " +
                                      dir.file("w.vcd") + " --trace-tris 5000:6000");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--trace-tris"), std::string::npos) << r.err;
  const CommandResult count = run_command(kBin + " raster --scene builtin:lowpoly-far");
  const size_t p = count.out.find(" read");
  ASSERT_NE(p, std::string::npos);
  const std::string n = count.out.substr(count.out.rfind(' ', p - 1) + 1, p - count.out.rfind(' ', p - 1) - 1);
  EXPECT_NE(r.err.find(n), std::string::npos) << "names the count " << n << ": " << r.err;
  EXPECT_EQ(dir.entry_count(), 0);
}

TEST(DefectOptions, TraceTrisWithoutTrace) {
  const CommandResult r = run_command(kBin + " raster --scene builtin:lowpoly-far --engine improved-sc --trace-tris 0:3");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--trace-tris"), std::string::npos) << r.err;
}

TEST(DefectOptions, ImageMustBePng) {
  TempDir dir;
  for (const char* opt : {"--image", "--diff-image"}) {
    const std::string cmd = std::string(opt) == "--image" ? " raster" : " compare --engines golden";
    const CommandResult r = run_command(kBin + cmd + " --scene builtin:lowpoly-far " + opt + " " +
                                        dir.file("x.jpg"));
    EXPECT_EQ(r.status, 2) << opt;
    EXPECT_NE(r.err.find(opt), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("PNG"), std::string::npos) << r.err;
    EXPECT_EQ(dir.entry_count(), 0);
  }
}

TEST(DefectOptions, FitTakesTheSceneOptionsOfRaster) {
  const std::string fit = kBin + " fit --scene " + kSrc + "/tests/data/cube.obj --width 64 --height 48";
  const CommandResult plain = run_command(fit);
  const CommandResult turned = run_command(fit + " --yaw 75 --pitch -10 --fov 60 --distance 4");
  const CommandResult fixed_s = run_command(fit + " --subpixel-bits 4 --error-budget 1000000");
  ASSERT_EQ(plain.status, 0) << plain.err;
  ASSERT_EQ(turned.status, 0) << turned.err;
  ASSERT_EQ(fixed_s.status, 0) << fixed_s.err;
  auto first_line = [](const std::string& s) { return s.substr(0, s.find('\n')); };
  // The camera changes the reference pixels named on the first line.
  EXPECT_NE(first_line(plain.out), first_line(turned.out));
  // --subpixel-bits fixes S: the fitted configuration has it.
  EXPECT_NE(fixed_s.out.find("fit        S=4 "), std::string::npos) << fixed_s.out;
}

// ---- 5. counters ------------------------------------------------------------------------------
TEST(DefectCounters, OffscreenMeansOffScreen) {
  TempDir dir;
  // 1: on screen, large; 2: on screen, no pixel centre inside; 3: wholly right of the viewport.
  write_file(dir.file("s.tri"),
             "10 10 50 10 10 50\n"
             "20.1 20.1 20.4 20.1 20.1 20.4\n"
             "200 10 240 10 200 50\n");
  const CommandResult r = run_command(kBin + " raster --width 100 --height 100 --scene " +
                                      dir.file("s.tri") + " --report " + dir.file("r.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("1 offscreen"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2 without a pixel centre"), std::string::npos) << r.out;
  const std::string json = slurp(dir.file("r.json"));
  EXPECT_NE(json.find("\"offscreen\": 1,"), std::string::npos) << json;
  EXPECT_NE(json.find("\"no_pixel_centre\": 2,"), std::string::npos) << json;
}

TEST(DefectCounters, ReadIsTheTrianglesInTheFile) {
  TempDir dir;
  // The eye inside the cube: faces behind it are dropped at the near plane, others clipped.
  const CommandResult r = run_command(kBin + " raster --scene " + kSrc +
                                      "/tests/data/cube.obj --distance 0.3 --report " +
                                      dir.file("r.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_NE(r.out.find("near-dropped"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" 12 read"), std::string::npos) << r.out;
  EXPECT_NE(slurp(dir.file("r.json")).find("\"read\": 12,"), std::string::npos);
}

// ---- 6. the diff image ------------------------------------------------------------------------
struct Png {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
};

Png read_png(const std::string& path) {
  Png img;
  png_image im{};
  im.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&im, path.c_str())) return img;
  im.format = PNG_FORMAT_RGB;
  img.width = int(im.width);
  img.height = int(im.height);
  img.rgb.resize(PNG_IMAGE_SIZE(im));
  if (!png_image_finish_read(&im, nullptr, img.rgb.data(), 0, nullptr)) img.rgb.clear();
  return img;
}

// Pixels drawn in a colour that is neither background (black) nor agreed (grey).
int64_t marked_pixels(const Png& img) {
  int64_t n = 0;
  for (size_t i = 0; i + 2 < img.rgb.size(); i += 3) {
    const uint8_t r = img.rgb[i], g = img.rgb[i + 1], b = img.rgb[i + 2];
    if (!(r == g && g == b)) ++n;
  }
  return n;
}

int64_t json_int(const std::string& json, const std::string& key, size_t from = 0) {
  const size_t p = json.find("\"" + key + "\": ", from);
  if (p == std::string::npos) return -1;
  return std::stoll(json.substr(p + key.size() + 4));
}

TEST(DefectDiffImage, SmallErrorsAreVisibleForEveryInexactEngine) {
  TempDir dir;
  const std::string scene = kSrc + "/tests/data/two_tris.tri";
  const CommandResult r =
      run_command(kBin + " compare --scene " + scene + " --engines golden,float-scanline,trad-sc --diff-image " +
                  dir.file("d.png") + " --report " + dir.file("r.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = slurp(dir.file("r.json"));
  for (const char* engine : {"float-scanline", "trad-sc"}) {
    const size_t at = json.find("\"engine\": \"" + std::string(engine) + "\"");
    ASSERT_NE(at, std::string::npos);
    const int64_t differing = json_int(json, "missing_pixels", at) + json_int(json, "extra_pixels", at);
    ASSERT_GT(differing, 0) << engine << " must differ on this scene for the test to mean anything";
    // The JSON names the triangles and pixels that differ.
    EXPECT_GT(json_int(json, "differing_triangle_count", at), 0) << engine;
    EXPECT_NE(json.find("\"differing_pixels\": [", at), std::string::npos) << engine;
    // Each engine has an image, and every differing pixel is marked well beyond itself.
    const size_t img_at = json.find("\"diff_image\": \"", at);
    ASSERT_NE(img_at, std::string::npos) << engine;
    const std::string path = json.substr(img_at + 15, json.find('"', img_at + 15) - img_at - 15);
    EXPECT_NE(r.out.find(path), std::string::npos) << r.out;
    const Png img = read_png(path);
    ASSERT_FALSE(img.rgb.empty()) << path;
    EXPECT_GE(marked_pixels(img), std::min<int64_t>(9 * differing, int64_t(img.width) * img.height / 4))
        << engine << " " << differing << " differing pixels";
  }
}

// ---- every statistic of a --report has a one-line description ---------------------------------
TEST(DefectReport, EveryStatisticHasADescription) {
  TempDir dir;
  const std::string scene = " --scene builtin:lowpoly-far --width 160 --height 120";
  std::vector<std::string> reports;
  for (const char* engine : {"golden", "improved-datapath", "improved-sc", "improved-rtl", "trad-sc", "trad-rtl", "float-scanline"}) {
    const std::string path = dir.file(std::string(engine) + ".json");
    const CommandResult r = run_command(kBin + " raster --engine " + engine + scene + " --report " + path);
    ASSERT_EQ(r.status, 0) << engine << ": " << r.err;
    reports.push_back(path);
  }
  const CommandResult c = run_command(kBin + " compare --engines golden,improved-datapath,improved-sc,improved-rtl,trad-sc,trad-rtl,float-scanline" +
                                      scene + " --report " + dir.file("compare.json"));
  ASSERT_LE(c.status, 1) << c.err;
  reports.push_back(dir.file("compare.json"));
  for (const std::string& path : reports) {
    const CommandResult check = run_command("/usr/bin/python3 " + kSrc + "/tests/support/check_report_descriptions.py " + path);
    EXPECT_EQ(check.status, 0) << path << ":\n" << check.out << check.err;
  }
}

}  // namespace
