// Limits: for each configuration, the coordinate range, the unit's box width and the
// divider's slope quotient, each at the limit (every exact engine agrees with the golden and the
// independent reference) and one past it (a clear error naming the triangle or option; never a
// wrapped value). Also the configuration options themselves, at and past their bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "common/engine.hpp"
#include "engines.hpp"
#include "common/fixed_point.hpp"
#include "common/span_diff.hpp"
#include "golden/golden.hpp"
#include "fuzz/fuzz_scene.hpp"
#include "common/reference_raster.hpp"
#include "support/run_command.hpp"
#include "improved/improved_unit.hpp"
#include "support/scene_helpers.hpp"

namespace trirast {
namespace {

using test::CommandResult;
using test::kBin;
using test::run_command;
using test::tri;
using test::write_file;

// Engines that model the unit's datapath and therefore its widths (all exact ones but the golden).
std::vector<const EngineInfo*> unit_engines() {
  std::vector<const EngineInfo*> out;
  for (const EngineInfo* e : test::exact_engines())
    if (e->name != "golden") out.push_back(e);
  return out;
}

// The exact engines whose build covers `cfg` (the rtl is built for one set of widths and says so
// with std::invalid_argument before it runs), as a --engines list.
std::string covering_engines(const RasterConfig& cfg) {
  std::string list;
  for (const EngineInfo* e : test::exact_engines()) {
    try {
      EngineResult r;
      e->make()->run(SetupResult{}, cfg, r);
    } catch (const std::invalid_argument&) {
      continue;
    }
    list += (list.empty() ? "" : ",") + e->name;
  }
  return list;
}

// Every exact engine gives the golden's pixels, and the golden the reference's (independent
// per-pixel rasterizer).
void expect_all_agree(const std::vector<InputTriangle>& tris, const RasterConfig& cfg) {
  std::string found;
  for (const FuzzDisagreement& f : check_engines(tris, cfg, test::exact_engines()))
    found += f.engine + ": " + f.what + "\n";
  EXPECT_EQ(found, "") << format_reproducer(tris, cfg, {"golden"}, "");
  // The per-pixel reference tests every pixel of every box: only for moderate viewports.
  if (int64_t(cfg.width) * cfg.height > 4 * 1024 * 1024) return;
  const SetupResult setup = setup_scene(tris, cfg);
  EngineResult golden;
  make_golden_engine()->run(setup, cfg, golden);
  sort_spans(golden.spans);
  EXPECT_TRUE(diff_spans(test::reference_raster(tris, cfg), golden.spans).exact());
}

// The configurations the limits are checked in: (S, coordinate bits, box bits, viewport).
struct Limits {
  int S, coord_bits, box_bits, width, height;
};
const Limits kConfigs[] = {
    {8, 16, 14, 1024, 768},  // the default 16.8
    {0, 16, 14, 640, 480},   // whole-pixel vertices (one extra fractional bit inside)
    {4, 12, 11, 640, 480},   // narrow range, narrow boxes
    {8, 22, 14, 1024, 768},  // the widest range 8 subpixel bits allow (2p + 2 = 62 bits)
    {0, 24, 14, 512, 512},   // the widest range of all
    {8, 2, 1, 2, 2},         // the narrowest: [-2, 2) pixels, 2x2 viewport, 1-bit boxes
    {1, 8, 7, 128, 100},
};

RasterConfig config_of(const Limits& l) {
  return test::config_with_widths(l.S, l.coord_bits, l.box_bits, l.width, l.height);
}

std::string name_of(const RasterConfig& cfg) { return config_options(cfg); }

// ---- coordinates -------------------------------------------------------------------------------

TEST(Limits, CoordinatesAtTheLimitSnapExactly) {
  for (const Limits& l : kConfigs) {
    const RasterConfig cfg = config_of(l);
    SCOPED_TRACE(name_of(cfg));
    const double L = double(cfg.coord_limit_px()), step = std::ldexp(1.0, -cfg.subpixel_bits);
    const double lo = -L, hi = L - step;
    // The lowest and highest representable values snap to exactly -L*2^S and (L*2^S - 1).
    const int64_t scale = cfg.snap_scale();
    EXPECT_EQ(snap_coordinate(lo, cfg, 0, 0), -int64_t(L) * (int64_t(1) << l.S) * scale);
    EXPECT_EQ(snap_coordinate(hi, cfg, 0, 0), (int64_t(L) * (int64_t(1) << l.S) - 1) * scale);
    // Halfway below -L rounds to even: -L itself, inside. Halfway below L rounds to L: outside.
    EXPECT_EQ(snap_coordinate(lo - step / 2, cfg, 0, 0), snap_coordinate(lo, cfg, 0, 0));
    EXPECT_THROW(snap_coordinate(L - step / 2, cfg, 0, 0), SetupError);
    EXPECT_EQ(snap_coordinate(L - step / 2 - step / 4, cfg, 0, 0), snap_coordinate(hi, cfg, 0, 0));
    // Triangles whose vertices sit on every corner of the range, with a part in the viewport.
    const double w = cfg.width, h = cfg.height;
    std::vector<InputTriangle> tris = {
        tri(lo, lo, hi, lo, lo, hi),   tri(hi, hi, lo, hi, hi, lo),  tri(lo, lo, hi, hi, lo, hi),
        tri(lo, lo, hi, hi, hi, lo),   tri(lo, 0.5, hi, 0.5, w / 2, std::min(h, hi)),  // a centre row, full width
        tri(0.5, lo, 0.5, hi, std::min(w, hi), h / 2),                                  // a centre column
        tri(lo, lo, hi, lo + step, w / 3, h / 3),                          // dy = 1 subpixel over the range
        tri(lo, lo, lo + step, hi, w / 2, h / 2),                          // dx = 1 subpixel over the range
        tri(lo, hi, hi, lo, hi, hi),   tri(0, 0, hi, lo + step, lo, hi),
    };
    expect_all_agree(tris, cfg);
  }
}

TEST(Limits, CoordinatesOnePastTheLimitAreRefused) {
  for (const Limits& l : kConfigs) {
    const RasterConfig cfg = config_of(l);
    SCOPED_TRACE(name_of(cfg));
    const double L = double(cfg.coord_limit_px()), step = std::ldexp(1.0, -cfg.subpixel_bits);
    // One subpixel past either end, far past, and values that a narrower integer would wrap to
    // something inside the range (2^16 + 1 -> 1, 2^32 -> 0, -2^31 - 1 -> 2^31 - 1).
    for (double bad : {L, -L - step, L + 1, -L - 1, 65537.0, 4294967296.0, -2147483649.0,
                       9.2233720368547758e18, 1e300, -1e300}) {
      if (std::fabs(bad) < L && bad != L) continue;
      SCOPED_TRACE(bad);
      for (int k = 0; k < 6; ++k) {
        InputTriangle t = tri(1, 1, 2, 1, 1, 2);
        (k < 3 ? t.x[k] : t.y[k - 3]) = bad;
        try {
          setup_scene({tri(0, 0, 1, 0, 0, 1), t}, cfg);
          FAIL() << "accepted " << bad;
        } catch (const SetupError& e) {
          const std::string msg = e.what();
          EXPECT_EQ(e.tri, 1u);
          EXPECT_NE(msg.find("triangle 1"), std::string::npos) << msg;
          EXPECT_NE(msg.find("outside the representable range [-" +
                             std::to_string(cfg.coord_limit_px()) + ", " +
                             std::to_string(cfg.coord_limit_px()) + ")"),
                    std::string::npos)
              << msg;
        }
      }
    }
  }
}

TEST(Limits, CoordinateLimitsThroughTheCli) {
  test::TempDir dir;
  for (const Limits& l : kConfigs) {
    const RasterConfig cfg = config_of(l);
    SCOPED_TRACE(name_of(cfg));
    const double L = double(cfg.coord_limit_px()), step = std::ldexp(1.0, -cfg.subpixel_bits);
    char at[200], past[400];
    std::snprintf(at, sizeof at, "%.17g %.17g %.17g 0.5 0.5 %.17g\n", -L, -L, L - step, L - step);
    std::snprintf(past, sizeof past, "# at the limit, then one subpixel past it\n%s%.17g 0 1 1 0 1\n",
                  at, L);
    write_file(dir.file("at.tri"), at);
    write_file(dir.file("past.tri"), past);
    const std::string engines = covering_engines(cfg);
    const std::string opts = " " + config_options(cfg);
    const CommandResult ok =
        run_command(kBin + " compare --scene " + dir.file("at.tri") + " --engines " + engines + opts);
    EXPECT_EQ(ok.status, 0) << ok.out << ok.err;
    // An engine that reads every option of `opts` (the golden reads none of the unit's).
    const CommandResult bad = run_command(kBin + " raster --engine improved-sc --scene " +
                                          dir.file("past.tri") + opts + " --spans " +
                                          dir.file("s") + " --image " + dir.file("i.png"));
    EXPECT_EQ(bad.status, 2) << bad.out << bad.err;
    EXPECT_EQ(test::count_lines(bad.err), 1) << bad.err;
    EXPECT_NE(bad.err.find("past.tri:3: triangle 1 (line 3): coordinate"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find("outside the representable range"), std::string::npos) << bad.err;
    EXPECT_FALSE(test::file_exists(dir.file("s")));
    EXPECT_FALSE(test::file_exists(dir.file("i.png")));
  }
}

// ---- the unit's box ----------------------------------------------------------------------------

TEST(Limits, BoxAtTheLimitRunsOnePastIsRefusedByEveryUnitEngine) {
  int refused = 0;
  for (const Limits& l : kConfigs) {
    for (int box_bits = 1; box_bits <= l.box_bits; box_bits += (box_bits < 8 ? 1 : 3)) {
      RasterConfig cfg = config_of(l);
      cfg.box_bits = box_bits;
      const int64_t B = int64_t(1) << box_bits;  // the widest box: B pixels
      // A viewport that can hold a box one past the limit, where the range and kMaxViewport allow.
      cfg.width = cfg.height =
          int(std::min({B + 1, int64_t(kMaxViewport), cfg.coord_limit_px()}));
      if (cfg.width < B) continue;  // the range itself caps the box below the limit
      cfg.validate();
      SCOPED_TRACE(name_of(cfg));
      // x from 0 to B - 1/4: the centres 0.5 .. B - 0.5, B pixels, for every S (ties included:
      // with S = 0 or 1 the vertex snaps to B, which still holds exactly B centres).
      const double step = std::ldexp(1.0, -cfg.subpixel_bits);
      const double at = std::min(double(B) - 0.25, double(cfg.coord_limit_px()) - step);
      const double past = double(B) + 0.75;
      expect_all_agree({tri(0, 0, at, 0, 0, 1),        // B wide
                        tri(0, 0, 1, 0, 0, at),        // B tall
                        tri(0, 0, at, 0, at, at),      // B x B, both halves
                        tri(0, 0, at, at, 0, at)},
                       cfg);
      if (cfg.width < B + 1) continue;  // no viewport can hold a larger box
      for (const InputTriangle& t : {tri(0, 0, past, 0, 0, 1), tri(0, 0, 1, 0, 0, past)}) {
        const SetupResult setup = setup_scene({tri(0, 0, 1, 0, 0, 1), t}, cfg);
        ASSERT_EQ(setup.tris.size(), 2u);
        ASSERT_EQ(std::max(setup.tris[1].box.width(), setup.tris[1].box.height()), B + 1);
        for (const EngineInfo* e : unit_engines()) {
          SCOPED_TRACE(e->name);
          EngineResult r;
          try {
            e->make()->run(setup, cfg, r);
            ADD_FAILURE() << "a box of " << B + 1 << " pixels ran with box_bits = " << box_bits;
          } catch (const std::invalid_argument&) {
            // This engine's build does not cover the configuration at all (the rtl's widths).
          } catch (const std::runtime_error& err) {
            ++refused;
            const std::string msg = err.what();
            EXPECT_NE(msg.find("triangle 1: "), std::string::npos) << msg;
            EXPECT_NE(msg.find("max = " + std::to_string(B) + " does not fit " +
                               std::to_string(box_bits) + "-bit"),
                      std::string::npos)
                << msg;
          }
        }
      }
    }
  }
  EXPECT_GT(refused, 20);
}

TEST(Limits, BoxLimitThroughTheCli) {
  test::TempDir dir;
  write_file(dir.file("at.tri"), "10.5 10.5 73.5 10.5 10.5 73.5\n");
  write_file(dir.file("past.tri"), "10.5 10.5 73.5 10.5 10.5 73.5\n10.5 10.5 74.5 10.5 10.5 20.5\n");
  RasterConfig box6;
  box6.box_bits = 6;
  for (const EngineInfo* e : unit_engines()) {
    SCOPED_TRACE(e->name);
    if (covering_engines(box6).find(e->name) == std::string::npos) continue;  // rtl: 14-bit boxes
    const CommandResult ok = run_command(kBin + " compare --box-bits 6 --scene " + dir.file("at.tri") +
                                         " --engines golden," + e->name);
    EXPECT_EQ(ok.status, 0) << ok.out << ok.err;
    const CommandResult bad = run_command(kBin + " raster --box-bits 6 --engine " + e->name +
                                          " --scene " + dir.file("past.tri") + " --spans " +
                                          dir.file("s") + " --report " + dir.file("r.json"));
    EXPECT_EQ(bad.status, 2);
    EXPECT_EQ(test::count_lines(bad.err), 1) << bad.err;
    EXPECT_NE(bad.err.find("triangle 1: Xmax = 64 does not fit 6-bit"), std::string::npos) << bad.err;
    EXPECT_FALSE(test::file_exists(dir.file("s")));
    EXPECT_FALSE(test::file_exists(dir.file("r.json")));
    // compare refuses too (status 2: an error, not a disagreement with a wrapped answer).
    const CommandResult cmp = run_command(kBin + " compare --box-bits 6 --scene " +
                                          dir.file("past.tri") + " --engines golden," + e->name);
    EXPECT_EQ(cmp.status, 2) << cmp.out << cmp.err;
  }
}

// ---- the divider's slope quotient ----------------------------------------------------------------

TEST(Limits, SlopeQuotientAtAndPastItsWidth) {
  // A near-horizontal edge rising dy subpixels over dx subpixels has the slope quotient dx/dy in
  // the divider. Q = box_bits + 1 bits hold it below 2^Q; from 2^Q on the divider saturates
  // (docs/unit.md) and the walker must still give exact spans. Both sides of the edge, both
  // windings, dy of 1..3 subpixels, quotients 2^Q - 1, 2^Q, 2^Q + 1 (and dx one subpixel off).
  for (const int box_bits : {3, 6, 10, 14}) {
    for (const int S : {8, 4, 1}) {
      RasterConfig cfg;
      cfg.subpixel_bits = S;
      cfg.box_bits = box_bits;
      cfg.width = cfg.height = std::min(1 << box_bits, 2048);
      cfg.validate();
      SCOPED_TRACE(name_of(cfg));
      const int64_t Q = box_bits + 1;
      const double s = std::ldexp(1.0, -S);
      int saturated = 0, unsaturated = 0;
      std::vector<InputTriangle> tris;
      for (int64_t dy = 1; dy <= 3; ++dy)
        for (int64_t q : {(int64_t(1) << Q) - 1, int64_t(1) << Q, (int64_t(1) << Q) + 1})
          for (int64_t extra : {-1, 0, 1}) {
            const int64_t dx_sub = q * dy + extra;
            const double dx = double(dx_sub) * s;
            if (dx + 2 >= double(cfg.coord_limit_px())) continue;  // past the range
            // The edge passes the centre row of pixel row 2 within its dy.
            const double y0 = 2.5 - double(dy / 2) * s, x0 = 0.5 + s;
            for (int below = 0; below < 2; ++below) {
              const double apex_y = below ? y0 + 5 : y0 - 2;
              tris.push_back(tri(x0, y0, x0 + dx, y0 + double(dy) * s, x0 + 1, apex_y));
              tris.push_back(tri(x0 + dx, y0 + double(dy) * s, x0, y0, x0 + dx / 2, apex_y));
            }
          }
      ASSERT_FALSE(tris.empty());
      expect_all_agree(tris, cfg);
      // The unit really went past the quotient's width: some slopes saturated, some not.
      const SetupResult setup = setup_scene(tris, cfg);
      ImprovedUnit unit(cfg);
      for (const TriangleSetup& t : setup.tris) {
        SpanList spans;
        const UnitTriangleResult r = unit.run_triangle(t, spans);
        if (r.iface.empty) continue;
        for (int k = 0; k < 3; ++k)
          if (r.norm[k].D != 0) (r.walker_entry[k].slope_saturated ? saturated : unsaturated)++;
      }
      EXPECT_GT(saturated, 0);
      EXPECT_GT(unsaturated, 0);
    }
  }
}

TEST(Limits, EdgeValuesAtTheWidestRange) {
  // p = coord_bits + F = 30 is the widest the 64-bit datapath holds (2p + 2 = 62 bits); the
  // largest edge values come from triangles spanning the whole range.
  for (const int S : {8, 0}) {
    RasterConfig cfg;
    cfg.subpixel_bits = S;
    cfg.coord_int_bits = S == 8 ? 22 : 24;
    cfg.validate();
    SCOPED_TRACE(name_of(cfg));
    EXPECT_EQ(unit_widths(cfg).edge_value, S == 8 ? 62 : 52);
    const double L = double(cfg.coord_limit_px()), s = std::ldexp(1.0, -cfg.subpixel_bits);
    test::TestRng rng(S + 1);
    std::vector<InputTriangle> tris;
    for (int i = 0; i < 300; ++i) {
      InputTriangle t;
      for (int k = 0; k < 3; ++k) {
        t.x[k] = rng.next() & 1 ? -L + double(rng.range(0, 5)) * s : L - double(rng.range(1, 6)) * s;
        t.y[k] = rng.next() & 1 ? -L + double(rng.range(0, 5)) * s : L - double(rng.range(1, 6)) * s;
      }
      if (i % 2) t.x[0] = double(rng.range(0, cfg.width)), t.y[0] = double(rng.range(0, cfg.height));
      tris.push_back(t);
    }
    expect_all_agree(tris, cfg);
  }
}

// ---- configuration options -----------------------------------------------------------------------

TEST(Limits, OptionsAtTheirBoundsAndOnePast) {
  test::TempDir dir;
  write_file(dir.file("t.tri"), "0.5 0.5 1.5 0.5 0.5 1.75\n");
  const std::string scene = " --scene " + dir.file("t.tri");
  struct Case {
    std::string opts;
    bool ok;
    std::string needle;  // for errors: the option named in the one-line message
  };
  const std::vector<Case> cases = {
      {"--width 16384 --height 1", true, ""},
      {"--width 16385", false, "--width"},
      {"--height 16384 --width 1", true, ""},
      {"--height 16385", false, "--height"},
      {"--width 1 --height 1", true, ""},
      {"--width -1", false, "--width"},
      {"--width 4294967297", false, "--width"},  // 2^32 + 1: would wrap to 1 in 32 bits
      {"--width 18446744073709551617", false, "--width"},
      {"--subpixel-bits 0", true, ""},
      {"--subpixel-bits 8", true, ""},
      {"--subpixel-bits -1", false, "--subpixel-bits"},
      {"--coord-bits 2 --width 2 --height 2", true, ""},
      {"--coord-bits 1 --width 1 --height 1", false, "--coord-bits"},
      {"--coord-bits 22", true, ""},
      {"--coord-bits 23", false, "--coord-bits: 23 with 8 subpixel bits needs edge values wider than 63 bits"},
      {"--coord-bits 24 --subpixel-bits 0", true, ""},
      {"--coord-bits 25 --subpixel-bits 0", false, "--coord-bits"},
      {"--coord-bits 11 --width 1024", true, ""},
      {"--coord-bits 11 --width 1025", false, "--coord-bits: 11 bits cannot hold a 1025x768 viewport"},
      {"--box-bits 1 --width 2 --height 2", true, ""},
      {"--box-bits 0", false, "--box-bits"},
      {"--box-bits 14", true, ""},
      {"--box-bits 15", false, "--box-bits"},
      {"--endpoints 4 --fifo-depth 4", true, ""},
      {"--endpoints 4 --fifo-depth 3", false, "--fifo-depth"},
      {"--endpoints 3", false, "--endpoints"},
      {"--endpoints 5", false, "--endpoints"},
      {"--fifo-depth 1024", true, ""},
      {"--fifo-depth 1025", false, "--fifo-depth"},
      {"--sink-stall random:1:99", true, ""},
      {"--sink-stall random:1:100", false, "--sink-stall"},
      {"--sink-stall periodic:0:3", false, "--sink-stall"},
      {"--sink-stall periodic:18446744073709551616:1", false, "--sink-stall"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.opts);
    // Every exact engine that covers the configuration (all of them when it is refused anyway).
    std::string engines = "golden";
    try {
      engines = covering_engines(parse_config_options(c.opts));
    } catch (const std::invalid_argument&) {
    }
    const CommandResult r = run_command(kBin + " compare" + scene + " --engines " + engines + " " +
                                        c.opts + " --report " + dir.file("r.json"));
    if (c.ok) {
      EXPECT_EQ(r.status, 0) << r.out << r.err;
      EXPECT_TRUE(test::file_exists(dir.file("r.json")));
      std::remove(dir.file("r.json").c_str());
    } else {
      EXPECT_EQ(r.status, 2) << r.out << r.err;
      EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
      EXPECT_NE(r.err.find(c.needle), std::string::npos) << r.err;
      EXPECT_EQ(r.out, "");
      EXPECT_FALSE(test::file_exists(dir.file("r.json")));
    }
  }
}

TEST(Limits, ConfigurationsWiderThanTheDatapathAreRefused) {
  // A configuration wider than the 64-bit datapath is refused by every unit engine up front.
  RasterConfig cfg;
  cfg.coord_int_bits = 23;  // p = 31: 2p + 2 = 64 bits
  EXPECT_THROW(cfg.validate(), std::invalid_argument);
  EXPECT_THROW(ImprovedUnit{cfg}, WidthError);
}

}  // namespace
}  // namespace trirast
