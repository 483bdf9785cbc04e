// Differential fuzzing: the reproducers in tests/fuzz-regressions/ through every exact
// engine, the scene generator's promises (every hard-case class, valid varied configurations,
// deterministic), an in-process differential run, and `trirast fuzz` as a user meets it.
#include <gtest/gtest.h>

#include <dirent.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "common/engine.hpp"
#include "engines.hpp"
#include "common/span_diff.hpp"
#include "golden/golden.hpp"
#include "fuzz/fuzz_scene.hpp"
#include "halfspace/halfspace_rtl_engine.hpp"
#include "scene/scene.hpp"
#include "common/reference_raster.hpp"
#include "support/run_command.hpp"

namespace trirast {
namespace {

using test::CommandResult;
using test::count_lines;
using test::exact_engines;
using test::kBin;
using test::run_command;
using test::slurp;
using test::TempDir;

const std::string kRegressions = std::string(TRIRAST_SOURCE_DIR) + "/tests/fuzz-regressions/";

std::vector<std::string> files_in(const std::string& dir, const std::string& suffix) {
  std::vector<std::string> out;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
        out.push_back(name);
    }
    closedir(d);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string describe(const std::vector<FuzzDisagreement>& found) {
  std::string s;
  for (const FuzzDisagreement& f : found) s += f.engine + ": " + f.what + "\n";
  return s;
}

// ---- the reproducers ---------------------------------------------------------------------------

TEST(FuzzRegressions, EveryReproducerAgreesOnEveryExactEngine) {
  const std::vector<std::string> files = files_in(kRegressions, ".tri");
  ASSERT_GE(files.size(), 5u) << "no reproducers in " << kRegressions;
  for (const std::string& name : files) {
    SCOPED_TRACE(name);
    const std::string text = slurp(kRegressions + name);
    ASSERT_NE(text.find("# engines: "), std::string::npos) << "not a reproducer";
    ASSERT_NE(text.find("# config: "), std::string::npos) << "not a reproducer";
    const RasterConfig cfg = parse_reproducer_config(text);
    const Scene scene = parse_tri_text(text, name);
    ASSERT_FALSE(scene.tris.empty());
    const std::vector<FuzzDisagreement> found = check_engines(scene.tris, cfg, exact_engines());
    EXPECT_TRUE(found.empty()) << describe(found);
    // The golden itself against the independent per-pixel reference.
    const SetupResult setup = setup_scene(scene.tris, cfg);
    EngineResult golden;
    make_golden_engine()->run(setup, cfg, golden);
    sort_spans(golden.spans);
    EXPECT_TRUE(diff_spans(test::reference_raster(scene.tris, cfg), golden.spans).exact());
  }
}

TEST(FuzzRegressions, ReplayLineOfEveryReproducerPasses) {
  // The header's replay command, as a user would paste it.
  for (const std::string& name : files_in(kRegressions, ".tri")) {
    SCOPED_TRACE(name);
    const std::string text = slurp(kRegressions + name);
    const size_t at = text.find("# replay: trirast ");
    ASSERT_NE(at, std::string::npos);
    std::string cmd = text.substr(at + 18, text.find('\n', at) - at - 18);
    cmd.replace(cmd.find("THIS_FILE"), 9, kRegressions + name);
    // Engines this build lacks (rtl before it lands) are left out of the replay.
    const size_t e0 = cmd.find("--engines ") + 10, e1 = cmd.find(' ', e0);
    std::string list;
    std::stringstream ss(cmd.substr(e0, e1 - e0));
    std::string engine;
    while (std::getline(ss, engine, ','))
      if (find_engine(engine)) list += (list.empty() ? "" : ",") + engine;
    cmd.replace(e0, e1 - e0, list);
    const CommandResult r = run_command(kBin + " " + cmd);
    EXPECT_EQ(r.status, 0) << cmd << "\n" << r.out << r.err;
  }
}

TEST(FuzzRegressions, ReproducerFormatReadsBackBitForBit) {
  RngDraws d(99);
  for (int i = 0; i < 300; ++i) {
    const RasterConfig cfg = draw_fuzz_config(d);
    const std::vector<InputTriangle> tris = draw_fuzz_scene(d, cfg, 40);
    const std::string text =
        format_reproducer(tris, cfg, {"golden", "improved-datapath"}, "line one\nline two");
    const Scene back = parse_tri_text(text, "r.tri");
    ASSERT_EQ(back.tris.size(), tris.size());
    for (size_t t = 0; t < tris.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(back.tris[t].x[k], tris[t].x[k]) << text;
        ASSERT_EQ(back.tris[t].y[k], tris[t].y[k]) << text;
      }
    EXPECT_EQ(config_options(parse_reproducer_config(text)), config_options(cfg));
    EXPECT_NE(text.find("# line two\n"), std::string::npos);
  }
  EXPECT_THROW(parse_config_options("--width 0"), std::invalid_argument);
  EXPECT_THROW(parse_config_options("--width 12x"), std::invalid_argument);
  EXPECT_THROW(parse_config_options("--frobnicate 1"), std::invalid_argument);
  EXPECT_THROW(parse_config_options("--width"), std::invalid_argument);
}

// ---- the generator -----------------------------------------------------------------------------

TEST(FuzzGenerator, ConfigurationsAreValidAndCoverEveryParameter) {
  RngDraws d(1);
  std::set<int> s_values, endpoints, box_bits;
  std::set<std::string> modes, dividers, culls, sinks;
  int big = 0, tiny = 0, narrow = 0;
  for (int i = 0; i < 5000; ++i) {
    const RasterConfig cfg = draw_fuzz_config(d);
    ASSERT_NO_THROW(cfg.validate());
    // Every box the viewport allows fits the unit's box width.
    ASSERT_LE(std::max(cfg.width, cfg.height), 1 << cfg.box_bits);
    s_values.insert(cfg.subpixel_bits);
    endpoints.insert(cfg.endpoints);
    box_bits.insert(cfg.box_bits);
    modes.insert(boundary_mode_name(cfg.boundary));
    dividers.insert(divider_mode_name(cfg.divider));
    culls.insert(cull_mode_name(cfg.cull));
    sinks.insert(cfg.sink_stall.substr(0, cfg.sink_stall.find(':')));
    big += std::max(cfg.width, cfg.height) == kMaxViewport;
    tiny += std::min(cfg.width, cfg.height) <= 8;
    narrow += cfg.coord_int_bits < 16;
  }
  EXPECT_EQ(s_values.size(), 9u);
  EXPECT_EQ(endpoints.size(), 3u);
  EXPECT_GE(box_bits.size(), 10u);
  EXPECT_EQ(modes.size(), 2u);
  EXPECT_EQ(dividers.size(), 2u);
  EXPECT_EQ(culls.size(), 3u);
  // none, periodic, random (and queue when the fuzzer draws reacting downstreams).
  EXPECT_EQ(sinks.size(), kFuzzDrawsQueueDownstreams ? 4u : 3u);
  EXPECT_GT(big, 20);
  EXPECT_GT(tiny, 100);
  EXPECT_GT(narrow, 500);
}

TEST(FuzzGenerator, EveryClassStaysInRangeAndDoesWhatItSays) {
  for (int c = 0; c < int(FuzzClass::kCount); ++c) {
    const FuzzClass cls = FuzzClass(c);
    SCOPED_TRACE(fuzz_class_name(cls));
    RngDraws d(1000 + c);
    int with_pixels = 0, degenerate = 0, ties = 0, at_limit = 0, straddle = 0, n = 0;
    for (int i = 0; i < 3000; ++i, ++n) {
      const RasterConfig cfg = draw_fuzz_config(d);
      const InputTriangle t = draw_fuzz_triangle(d, cfg, cls);
      TriangleSetup s;
      const char* why = nullptr;
      bool accepted = false;
      ASSERT_NO_THROW(accepted = setup_triangle(t, 0, cfg, s, &why));  // never out of range
      if (!accepted && why && why[0] == 'd') ++degenerate;
      if (accepted && !s.box.empty()) {
        SpanList spans;
        golden_triangle(s, cfg, spans);
        with_pixels += !spans.empty();
      }
      const double lim = double(cfg.coord_limit_px());
      for (int k = 0; k < 3; ++k) {
        for (double v : {t.x[k], t.y[k]}) {
          const double fine = std::ldexp(v, cfg.subpixel_bits + 1);
          if (fine == std::floor(fine) && std::fmod(std::fabs(fine), 2.0) == 1.0) ++ties;
          if (v == -lim || v == lim - std::ldexp(1.0, -cfg.subpixel_bits)) ++at_limit;
        }
        straddle += t.x[k] < 0 || t.y[k] < 0;
      }
    }
    switch (cls) {
      case FuzzClass::Degenerate: EXPECT_GT(degenerate, n / 2); break;
      case FuzzClass::SnapTie: EXPECT_GT(ties, n); break;
      case FuzzClass::Extreme: EXPECT_GT(at_limit, n / 2); break;
      case FuzzClass::Straddle: EXPECT_GT(straddle, n); break;
      default: EXPECT_GT(with_pixels, n / 4) << "too few triangles with pixels"; break;
    }
  }
}

TEST(FuzzGenerator, DeterministicAndByteDecoderIsTotal) {
  RngDraws a(5), b(5);
  for (int i = 0; i < 50; ++i) {
    const RasterConfig ca = draw_fuzz_config(a), cb = draw_fuzz_config(b);
    ASSERT_EQ(config_options(ca), config_options(cb));
    const auto ta = draw_fuzz_scene(a, ca, 100), tb = draw_fuzz_scene(b, cb, 100);
    ASSERT_EQ(format_reproducer(ta, ca, {}, ""), format_reproducer(tb, cb, {}, ""));
  }
  // Any byte string decodes to a valid configuration and in-range triangles, the empty one too.
  test::TestRng rng(77);
  for (int i = 0; i < 2000; ++i) {
    std::vector<uint8_t> bytes(size_t(rng.range(0, 300)));
    for (uint8_t& byte : bytes) byte = uint8_t(rng.next());
    if (i % 10 == 0) std::fill(bytes.begin(), bytes.end(), uint8_t(i % 20 == 0 ? 0 : 0xff));
    ByteDraws d(bytes.data(), bytes.size());
    RasterConfig cfg;
    ASSERT_NO_THROW(cfg = draw_fuzz_config(d));
    while (!d.exhausted()) {
      const InputTriangle t = draw_fuzz_triangle(d, cfg);
      TriangleSetup s;
      const char* why;
      ASSERT_NO_THROW(setup_triangle(t, 0, cfg, s, &why));
    }
  }
}

// ---- in process: the engines against the golden ------------------------------------------------

TEST(FuzzDifferential, GeneratedScenesOnEveryExactEngine) {
  // A few seconds of what `trirast fuzz` does, in process, on a fixed seed. The half-space
  // engines walk a box a tile or a stamp per cycle (their time grows with the box area, not its
  // height): they run the scenes of viewports up to 512 x 512 pixels here (trirast fuzz runs them on
  // every scene).
  const std::vector<const EngineInfo*> engines = exact_engines();
  std::vector<const EngineInfo*> without_hs;
  for (const EngineInfo* e : engines)
    if (e->name.rfind("halfspace-", 0) != 0) without_hs.push_back(e);
  ASSERT_GE(engines.size(), 2u);
  ASSERT_GT(engines.size(), without_hs.size());
  uint64_t triangles = 0, pixels = 0, hs_scenes = 0;
  std::map<std::string, int> skipped;  // scenes an engine's build does not cover (the rtl's widths)
  for (uint64_t scene = 0; scene < 3000; ++scene) {
    RngDraws d(0xfeed0000 + scene);
    RasterConfig cfg = draw_fuzz_config(d);
    const std::vector<InputTriangle> tris = draw_fuzz_scene(d, cfg, 100);
    // As trirast fuzz: the half-space unit's parameters among halfspace-rtl's builds.
    draw_fuzz_hs_config(d, cfg, rtl::halfspace_built_params(cfg));
    uint64_t p = 0;
    std::vector<std::string> skips;
    const bool hs = int64_t(cfg.width) * cfg.height <= 512 * 512;
    hs_scenes += hs;
    const std::vector<FuzzDisagreement> found =
        check_engines(tris, cfg, hs ? engines : without_hs, &p, &skips);
    for (const std::string& e : skips) ++skipped[e];
    triangles += tris.size();
    pixels += p;
    ASSERT_TRUE(found.empty()) << "scene " << scene << "\n"
                               << describe(found)
                               << format_reproducer(reduce_scene(tris, cfg, *find_engine(found[0].engine), found[0]),
                                                    cfg, {"golden", found[0].engine}, "");
  }
  EXPECT_GT(triangles, 60000u);
  EXPECT_GT(pixels, 1000000u);
  // Only the engines built for fixed widths skip (the half-space one never for its stamp, tile
  // or walk: they are drawn among its builds; improved2-rtl has the widths of improved-rtl's
  // builds, at every N and depth); they still run a good share of the scenes.
  for (const auto& [engine, n] : skipped) {
    EXPECT_TRUE(engine == "improved-rtl" || engine == "halfspace-rtl" || engine == "improved2-rtl")
        << engine;
    EXPECT_LT(n, 3000 * 7 / 10) << engine;
  }
  EXPECT_GT(hs_scenes, 600u);
  EXPECT_LT(skipped["halfspace-rtl"], hs_scenes * 7 / 10);
  // improved2-rtl covers every N and depth: it skips the scenes improved-rtl skips, no more.
  EXPECT_EQ(skipped["improved2-rtl"], skipped["improved-rtl"]);
}

TEST(FuzzDifferential, CheckerCatchesWrongEnginesAndReducesToTheCulprit) {
  // Engines that are wrong in three ways: the checker must name each, and the reduction must keep
  // the one triangle that shows it.
  struct DropLastPixelOfTri3 : Engine {
    void run(const SetupResult& s, const RasterConfig& c, EngineResult& out) override {
      make_golden_engine()->run(s, c, out);
      for (Span& sp : out.spans)
        if (sp.tri == 3) {
          --sp.x_end;
          break;
        }
      out.spans.erase(std::remove_if(out.spans.begin(), out.spans.end(),
                                     [](const Span& sp) { return sp.x_begin >= sp.x_end; }),
                      out.spans.end());
    }
  };
  // The same fault keyed on the geometry (the triangle whose box starts at x = 29) instead of the
  // index: reducible to that one triangle.
  struct DropLastPixelAtX29 : Engine {
    void run(const SetupResult& s, const RasterConfig& c, EngineResult& out) override {
      make_golden_engine()->run(s, c, out);
      for (const TriangleSetup& t : s.tris)
        if (t.box.x0 == 29)
          for (Span& sp : out.spans)
            if (sp.tri == t.index) {
              --sp.x_end;
              break;
            }
    }
  };
  struct Throws : Engine {
    void run(const SetupResult&, const RasterConfig&, EngineResult&) override {
      throw std::runtime_error("boom");
    }
  };
  struct OutsideViewport : Engine {
    void run(const SetupResult& s, const RasterConfig& c, EngineResult& out) override {
      make_golden_engine()->run(s, c, out);
      out.spans.push_back({0, c.height, 0, 1});
    }
  };
  const EngineInfo drop{"drop", "", true, [] { return std::unique_ptr<Engine>(new DropLastPixelOfTri3); }};
  const EngineInfo drop29{"drop29", "", true, [] { return std::unique_ptr<Engine>(new DropLastPixelAtX29); }};
  const EngineInfo boom{"boom", "", true, [] { return std::unique_ptr<Engine>(new Throws); }};
  const EngineInfo out{"outside", "", true, [] { return std::unique_ptr<Engine>(new OutsideViewport); }};
  RasterConfig cfg;
  cfg.width = cfg.height = 64;
  std::vector<InputTriangle> tris;
  for (int i = 0; i < 6; ++i)
    tris.push_back(InputTriangle{{2.0 + 9 * i, 9.0 + 9 * i, 2.0 + 9 * i}, {2, 2, 30}});
  const auto found = check_engines(tris, cfg, {&drop, &boom, &out});
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0].engine, "drop");
  EXPECT_EQ(found[0].what, "missing 1, extra 0 pixels");
  EXPECT_EQ(found[0].tris, std::vector<uint32_t>{3});
  EXPECT_EQ(found[1].what, "threw: boom");
  EXPECT_NE(found[2].what.find("bad span"), std::string::npos);
  // Keyed on the index, the fault needs the whole scene: the reduction keeps all of it.
  EXPECT_EQ(reduce_scene(tris, cfg, drop, found[0]).size(), tris.size());
  const auto found29 = check_engines(tris, cfg, {&drop29});
  ASSERT_EQ(found29.size(), 1u);
  EXPECT_EQ(found29[0].tris, std::vector<uint32_t>{3});
  const auto small = reduce_scene(tris, cfg, drop29, found29[0]);
  ASSERT_EQ(small.size(), 1u);
  EXPECT_EQ(small[0].x[0], tris[3].x[0]);
}

// ---- trirast fuzz ------------------------------------------------------------------------------

TEST(FuzzCli, ShortRunOverAllEnginesAgreesAndReportsProgress) {
  TempDir dir;
  const CommandResult r =
      run_command(kBin + " fuzz --seconds 3 --seed 42 --out " + dir.path());
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  // Every exact engine of the build by default, progress once a second on stderr.
  for (const EngineInfo* e : exact_engines())
    EXPECT_NE(r.out.find(e->name), std::string::npos) << e->name << "\n" << r.out;
  // The progress line's clock reads whatever a loaded machine gives (1.0 s, 1.3 s, ...).
  EXPECT_TRUE(std::regex_search(r.err, std::regex("(^|\n)fuzz: [0-9]+\\.[0-9] s, ")))
      << r.err;
  EXPECT_NE(r.err.find(" triangles, 0 disagreements\n"), std::string::npos) << r.err;
  EXPECT_GE(count_lines(r.err), 3);
  EXPECT_NE(r.out.find("0 disagreements"), std::string::npos) << r.out;
  EXPECT_EQ(dir.entry_count(), 0);
  // With improved-rtl among the engines, the widths are its builds': no scene skips it, nor any
  // other engine (improved2-rtl has builds of the same widths, at every N).
  EXPECT_NE(r.err.find("widths of the RTL builds"), std::string::npos) << r.err;
  EXPECT_FALSE(std::regex_search(r.out, std::regex("skipped +[^ ]"))) << r.out;
}

TEST(FuzzCli, DisagreementWritesReproducersAndExitsOne) {
  TempDir dir;
  const CommandResult r =
      run_command(kBin + " fuzz --scenes 6 --seed 3 --engines golden,improved-datapath " +
                  "--inject-fault improved-datapath --out " + dir.path());
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("DISAGREEMENT in scene "), std::string::npos) << r.err;
  const std::vector<std::string> files = files_in(dir.path(), ".tri");
  ASSERT_GE(files.size(), 3u) << r.err;
  for (const std::string& f : files) {
    SCOPED_TRACE(f);
    EXPECT_EQ(f.rfind("fuzz-3-", 0), 0u);
    const std::string text = slurp(dir.file(f));
    EXPECT_NE(text.find("# engines: golden,improved-datapath\n"), std::string::npos) << text;
    EXPECT_NE(text.find("improved-datapath disagrees with golden: missing 1, extra 0 pixels"),
              std::string::npos)
        << text;
    // The reproducer is reduced to the triangle that lost its pixel, and its configuration reads
    // back; replayed without the fault, the engines agree.
    const Scene s = parse_tri_text(text, f);
    EXPECT_EQ(s.tris.size(), 1u) << text;
    const RasterConfig cfg = parse_reproducer_config(text);
    EXPECT_NE(text.find("# config: " + config_options(cfg) + "\n"), std::string::npos) << text;
    // The replay line leaves out the options neither engine reads (the timed units' ones).
    const size_t at = text.find("# replay: trirast ");
    ASSERT_NE(at, std::string::npos) << text;
    const std::string replay_line = text.substr(at + 18, text.find('\n', at) - at - 18);
    EXPECT_EQ(replay_line.find("--endpoints"), std::string::npos) << replay_line;
    EXPECT_NE(replay_line.find("--box-bits " + std::to_string(cfg.box_bits)), std::string::npos)
        << replay_line;
    const CommandResult replay = run_command(kBin + " " + replay_line);
    EXPECT_EQ(replay.status, 0) << replay.out << replay.err;
  }
  // The same seed finds the same scenes.
  TempDir again;
  run_command(kBin +
              " fuzz --scenes 6 --seed 3 --engines golden,improved-datapath --inject-fault "
              "improved-datapath --out " +
              again.path());
  ASSERT_EQ(files_in(again.path(), ".tri"), files);
  // Equal but for the folder the replay line names the reproducer in.
  auto in_folder = [](std::string text, const std::string& from, const std::string& to) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
    return text;
  };
  for (const std::string& f : files)
    EXPECT_EQ(slurp(again.file(f)), in_folder(slurp(dir.file(f)), dir.path(), again.path()));
  // --max-reproducers caps the files, not the count.
  TempDir capped;
  const CommandResult c =
      run_command(kBin + " fuzz --scenes 6 --seed 3 --engines golden,improved-datapath " +
                  "--inject-fault improved-datapath --max-reproducers 1 --out " + capped.path());
  EXPECT_EQ(c.status, 1);
  EXPECT_EQ(capped.entry_count(), 1);
  EXPECT_NE(c.out.find(std::to_string(files.size()) + " disagreements"), std::string::npos) << c.out;
}

TEST(FuzzCli, BadOptionsOneLineErrorNoFiles) {
  TempDir dir;
  const std::string out = " --out " + dir.path();
  struct Case {
    std::string args, needle;
  };
  const std::vector<Case> cases = {
      {"--seconds -1" + out, "--seconds"},
      {"--seconds abc" + out, "--seconds"},
      {"--seconds 1.5" + out, "--seconds"},
      {"--seconds 0" + out, "--scenes"},
      {"--scenes -2" + out, "--scenes"},
      {"--max-triangles 0" + out, "--max-triangles"},
      {"--seed -3" + out, "--seed"},
      {"--seed 12ab" + out, "--seed"},
      {"--seed 99999999999999999999999" + out, "--seed"},
      {"--engines golden,nosuch" + out, "nosuch"},
      {"--engines golden,trad-sc" + out, "trad-sc"},
      {"--engines golden" + out, "--engines"},
      {"--engines ''" + out, "--engines"},
      {"--inject-fault golden" + out, "--inject-fault"},
      {"--inject-fault nosuch" + out, "--inject-fault"},
      {"--out " + dir.file("no/such/dir"), "--out"},
      {"--out /proc/version", "--out"},
      {"--frobnicate 1" + out, "--frobnicate"},
      {"--seconds 1 --seconds 2" + out, "--seconds"},
      {"stray" + out, "stray"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    const CommandResult r = run_command(kBin + " fuzz " + c.args);
    EXPECT_EQ(r.status, 2) << r.out << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(dir.entry_count(), 0);
  }
  const CommandResult help = run_command(kBin + " fuzz --help");
  EXPECT_EQ(help.status, 0);
  for (const char* opt : {"--seconds", "--engines", "--seed", "--out", "--scenes", "--inject-fault"})
    EXPECT_NE(help.out.find(opt), std::string::npos) << opt;
}

}  // namespace
}  // namespace trirast
