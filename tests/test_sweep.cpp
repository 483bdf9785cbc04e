// Speed against error: the sweep's outputs, its determinism, the error measurements,
// the fit, the quotient truncation of the unit, and the area model.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "common/engine.hpp"
#include "engines.hpp"
#include "common/watertight.hpp"
#include "scene/scene.hpp"
#include "support/run_command.hpp"
#include "sweep/sweep.hpp"
#include "sweep/sweep_area.hpp"

namespace trirast {
namespace {

using test::CommandResult;
using test::file_exists;
using test::kBin;
using test::run_command;
using test::slurp;
using test::TempDir;
using test::write_file;

const std::string kSource = TRIRAST_SOURCE_DIR;

// The fields of one CSV line; a quoted field may hold the separator.
std::vector<std::string> csv_fields(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (char c : s) {
    if (c == '"') quoted = !quoted;
    if (c == sep && !quoted) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

// A CSV as rows of column -> value.
std::vector<std::map<std::string, std::string>> read_csv(const std::string& path) {
  std::istringstream in(slurp(path));
  std::string line;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    const auto f = csv_fields(line, ',');
    if (header.empty()) {
      header = f;
      continue;
    }
    std::map<std::string, std::string> row;
    for (size_t i = 0; i < header.size() && i < f.size(); ++i) row[header[i]] = f[i];
    rows.push_back(row);
  }
  return rows;
}

const std::map<std::string, std::string>* find_row(
    const std::vector<std::map<std::string, std::string>>& rows, const std::string& engine,
    const std::string& config, const std::string& scene = "") {
  for (const auto& r : rows)
    if (r.at("engine") == engine && r.at("config") == config &&
        (scene.empty() || r.at("scene") == scene))
      return &r;
  return nullptr;
}

// The CSV without its timing columns (the only ones allowed to change between runs).
std::string without_timings(const std::string& path) {
  const auto rows = read_csv(path);
  std::string out;
  for (const auto& r : rows) {
    for (const auto& [k, v] : r)
      if (k != "wall_seconds" && k != "wall_ratio") out += k + "=" + v + ";";
    out += "\n";
  }
  return out;
}

bool is_png(const std::string& path) {
  const std::string s = slurp(path);
  return s.size() > 1000 && s.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

// ---- the one command, quick mode --------------------------------------------------------------

TEST(SweepScript, QuickModeWritesEveryOutput) {
  TempDir dir;
  const CommandResult r = run_command("TRIRAST_BIN=" + kBin + " " + kSource +
                                      "/scripts/sweep.sh --quick --out " + dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* f : {"data/sweep.csv", "data/sweep_configs.csv", "data/sweep.json",
                        "data/fit_1.json", "data/fit_2.json", "data/fit_3.json",
                        "data/fit_4.json", "data/fit_5.json", "data/fit_6.json",
                        "speed-vs-error.md"})
    EXPECT_TRUE(file_exists(dir.file(f)) && !slurp(dir.file(f)).empty()) << f;
  for (const char* png : {"cycles_vs_error.png", "area_vs_error.png", "error_vs_subpixel.png",
                          "improved_vs_trad.png"})
    EXPECT_TRUE(is_png(dir.file(std::string("img/speed-vs-error/") + png))) << png;
  const std::string md = slurp(dir.file("speed-vs-error.md"));
  // Every image the report shows exists, relative to the report.
  size_t at = 0;
  int images = 0;
  while ((at = md.find("](img/", at)) != std::string::npos) {
    const size_t end = md.find(')', at);
    const std::string rel = md.substr(at + 2, end - at - 2);
    EXPECT_TRUE(is_png(dir.file(rel))) << rel;
    ++images;
    at = end;
  }
  EXPECT_EQ(images, 4);
  for (const char* needle :
       {"Pareto", "cycles front", "area front", "Improved vs traditional", "32%", "3,120", "4,653",
        "3,728", "6,936", "float scanline", "Cracks and double hits", "trirast fit",
        "builtin:sphere:tess=12", "builtin:lowpoly-near", "builtin:hard-tiny", "estimate",
        "Model-only what-ifs", "buildable hardware", "improved2 (radix16)", "improved2 (dsp)",
        "quick mode"})
    EXPECT_NE(md.find(needle), std::string::npos) << "report lacks: " << needle;
}

// ---- the sweep itself -------------------------------------------------------------------------

class QuickSweep : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    one_ = run_command(kBin + " sweep --quick --no-progress --jobs 1 --out " + dir_->file("j1"));
    two_ = run_command(kBin + " sweep --quick --no-progress --jobs 2 --out " + dir_->file("j2"));
  }
  static void TearDownTestSuite() { delete dir_; }
  static TempDir* dir_;
  static CommandResult one_, two_;
};
TempDir* QuickSweep::dir_ = nullptr;
CommandResult QuickSweep::one_, QuickSweep::two_;

TEST_F(QuickSweep, ParallelRunEqualsSerialExceptTimings) {
  ASSERT_EQ(one_.status, 0) << one_.err;
  ASSERT_EQ(two_.status, 0) << two_.err;
  for (const char* f : {"sweep.csv", "sweep_configs.csv"}) {
    const std::string a = without_timings(dir_->file(std::string("j1/") + f));
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, without_timings(dir_->file(std::string("j2/") + f))) << f;
  }
}

TEST_F(QuickSweep, ErrorsAreWhereTheyShouldBe) {
  ASSERT_EQ(one_.status, 0) << one_.err;
  const auto cfgs = read_csv(dir_->file("j1/sweep_configs.csv"));
  // The default improved unit and the golden are exact and watertight.
  for (const auto& [engine, config] : std::vector<std::pair<std::string, std::string>>{
           {"golden", "S8 c16"},
           {"improved-sc", "S8 c16 b14 K- N1"},
           {"improved-sc", "S8 c16 b14 K- N4"},
           {"improved-sc", "S8 c16 b14 K- N1 fixed"}}) {
    const auto* r = find_row(cfgs, engine, config);
    ASSERT_NE(r, nullptr) << engine << " " << config;
    EXPECT_EQ(r->at("exact"), "1") << config;
    EXPECT_EQ(r->at("cracks"), "0") << config;
    EXPECT_EQ(r->at("doubles"), "0") << config;
    EXPECT_EQ(r->at("failures"), "0") << config;
  }
  // Fewer subpixel bits, quotient truncation, a narrow box: measurable error, no failure.
  for (const char* config : {"S0 c16 b14 K- N1", "S8 c16 b14 K6 N1", "S8 c16 b8 K- N1"}) {
    const auto* r = find_row(cfgs, "improved-sc", config);
    ASSERT_NE(r, nullptr) << config;
    EXPECT_EQ(r->at("exact"), "0") << config;
    EXPECT_GT(std::stod(r->at("error_ppm")), 0.0) << config;
    EXPECT_EQ(r->at("failures"), "0") << config;
  }
  EXPECT_GT(std::stoi(find_row(cfgs, "improved-sc", "S8 c16 b8 K- N1")->at("rejected")), 0);
  // Truncating the quotient saves divider iterations: fewer cycles than the default.
  EXPECT_LT(std::stol(find_row(cfgs, "improved-sc", "S8 c16 b14 K6 N1")->at("total_cycles")),
            std::stol(find_row(cfgs, "improved-sc", "S8 c16 b14 K- N1")->at("total_cycles")));
  // The fixed divider runs Q iterations: more cycles than the adaptive default.
  EXPECT_GT(std::stol(find_row(cfgs, "improved-sc", "S8 c16 b14 K- N1 fixed")->at("total_cycles")),
            std::stol(find_row(cfgs, "improved-sc", "S8 c16 b14 K- N1")->at("total_cycles")));
  // The traditional unit and the float scanline are not exact; trad has double hits.
  EXPECT_EQ(find_row(cfgs, "trad-sc", "S8 c16")->at("exact"), "0");
  EXPECT_GT(std::stol(find_row(cfgs, "trad-sc", "S8 c16")->at("doubles")), 0);
  EXPECT_NE(find_row(cfgs, "float-scanline", "S8 c16"), nullptr);
  // Per scene: on the near low-poly sphere the improved unit beats the traditional one.
  const auto rows = read_csv(dir_->file("j1/sweep.csv"));
  const auto* imp = find_row(rows, "improved-sc", "S8 c16 b14 K- N1", "builtin:lowpoly-near");
  const auto* trad = find_row(rows, "trad-sc", "S8 c16", "builtin:lowpoly-near");
  ASSERT_TRUE(imp && trad);
  EXPECT_LT(std::stol(imp->at("total_cycles")), std::stol(trad->at("total_cycles")));
  // The RTL, when it is in the build, has the model's cycles.
  if (const auto* rtl =
          find_row(rows, "improved-rtl", "S8 c16 b14 K- N1", "builtin:lowpoly-near")) {
    EXPECT_EQ(rtl->at("total_cycles"), imp->at("total_cycles"));
  }
  // Some configuration lies on each Pareto front, and the exact default's area is known.
  int front_c = 0, front_a = 0;
  for (const auto& r : cfgs) {
    front_c += r.at("pareto_cycles") == "1";
    front_a += r.at("pareto_area") == "1";
  }
  EXPECT_GT(front_c, 0);
  EXPECT_GT(front_a, 0);
  // The fronts are of buildable hardware: a quotient-truncation (K) configuration has no RTL and
  // is never on one (at most a model-only what-if); a point on a front is buildable.
  int k_rows = 0;
  for (const auto& r : cfgs) {
    const bool k = !r.at("quotient_bits").empty() && r.at("quotient_bits") != "0";
    k_rows += k;
    if (k) {
      EXPECT_EQ(r.at("rtl"), "0") << r.at("config");
      EXPECT_EQ(r.at("pareto_cycles"), "0") << r.at("config");
      EXPECT_EQ(r.at("pareto_area"), "0") << r.at("config");
    }
    if (r.at("pareto_cycles") == "1" || r.at("pareto_area") == "1") {
      EXPECT_EQ(r.at("rtl"), "1") << r.at("config");
    }
    if (r.at("whatif_cycles") == "1" || r.at("whatif_area") == "1") {
      EXPECT_EQ(r.at("rtl"), "0") << r.at("config");
    }
  }
  EXPECT_GT(k_rows, 0);
  EXPECT_FALSE(find_row(cfgs, "improved-sc", "S8 c16 b14 K- N1")->at("luts").empty());
}

// The half-space unit in the sweep (--engines halfspace-*): its stamp, tile and walk as points,
// exact against the golden, its RTL with its model's cycles, and its area where synthesis has
// its stamp size at the synthesized tile and walk (tile 8, forward), unknown elsewhere.
TEST(SweepHalfspace, StampTileAndWalkAreSweptExactWithSynthesizedArea) {
  // The full sweep's points: every stamp x tile x walk once, with distinct names.
  const std::vector<SweepPoint> full = sweep_points(false, {"halfspace-sc"});
  ASSERT_EQ(full.size(), 27u);
  std::set<std::string> names;
  for (const SweepPoint& p : full) {
    EXPECT_EQ(p.kind(), UnitKind::Halfspace);
    EXPECT_TRUE(p.rtl()) << p.label();
    names.insert(p.config_name());
  }
  EXPECT_EQ(names.size(), 27u);
  EXPECT_TRUE(names.count("S8 c16 b14 s4 t- row"));
  // Not in the default engines: the default sweep has no half-space point.
  for (const SweepPoint& p : sweep_points(false, {}))
    EXPECT_NE(p.kind(), UnitKind::Halfspace) << p.label();

  TempDir dir;
  write_file(dir.file("synth.csv"),
             "unit,config,target,luts,ffs,carry,bram,dsp,fmax_mhz\n"
             "improved,default,xilinx7,6536,2320,818,0,9,\n"
             "halfspace-s1,default,xilinx7,5403,2393,666,0,15,\n"
             "halfspace-s2,default,xilinx7,5944,2393,799,0,15,\n");
  const CommandResult r = run_command(
      kBin + " sweep --quick --no-progress --engines golden,halfspace-sc,halfspace-rtl "
             "--scenes 'builtin:mixed:objects=2,tess=8;builtin:hard-tiny' --synth-csv " +
      dir.file("synth.csv") + " --out " + dir.file("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto cfgs = read_csv(dir.file("out/sweep_configs.csv"));
  int hs = 0;
  for (const auto& row : cfgs) {
    if (row.at("unit") != "halfspace") continue;
    ++hs;
    EXPECT_EQ(row.at("exact"), "1") << row.at("config");
    EXPECT_EQ(row.at("failures"), "0") << row.at("config");
    EXPECT_EQ(row.at("box_bits"), "14") << row.at("config");
  }
  EXPECT_EQ(hs, 4);  // quick: three model points and the RTL
  const auto* s1 = find_row(cfgs, "halfspace-sc", "S8 c16 b14 s1 t8 forward");
  const auto* s2 = find_row(cfgs, "halfspace-sc", "S8 c16 b14 s2 t8 forward");
  const auto* s4 = find_row(cfgs, "halfspace-sc", "S8 c16 b14 s4 t16 row");
  const auto* rtl = find_row(cfgs, "halfspace-rtl", "S8 c16 b14 s2 t8 forward");
  ASSERT_TRUE(s1 && s2 && s4 && rtl);
  EXPECT_EQ(s1->at("luts"), "5403");
  EXPECT_EQ(s2->at("luts"), "5944");
  EXPECT_EQ(s2->at("area_source"), "synth:xilinx7");
  EXPECT_EQ(s4->at("luts"), "");  // stamp 4 not in this CSV, tile 16 row never synthesized
  EXPECT_EQ(s4->at("area_source"), "");
  EXPECT_EQ(rtl->at("total_cycles"), s2->at("total_cycles"));
  // A larger stamp tests more pixels per cycle: fewer cycles.
  EXPECT_LT(std::stol(s2->at("total_cycles")), std::stol(s1->at("total_cycles")));
  // The synthesized half-space rows are in the report's area model without a width estimate.
  const std::string json = slurp(dir.file("out/sweep.json"));
  const size_t row = json.find("\"unit\": \"halfspace-s2\"");
  ASSERT_NE(row, std::string::npos);
  EXPECT_EQ(json.substr(row, json.find('}', row) - row).find("estimate"), std::string::npos);
}

// The second-generation unit in the sweep (--engines improved2-sc, improved2-datapath): the
// improved unit's widths with N = 1 in both corner forms, exact where the widths are the
// golden's, the same pixels as gen1 at every width (both follow the rule at their S), the DSP
// corner form never slower than radix 16; its area the synthesis row of its corner form where one
// covers the point ("improved2", "improved2-products"), never gen1's synthesis or estimate, and
// unknown elsewhere.
TEST(SweepImproved2, CornerFormsSweptExactWithTheirOwnArea) {
  // The full sweep's points: 29 widths x 2 corner forms, with distinct names, all buildable
  // (rtl/improved2/trirast_improved2.f is parametric in the widths).
  const std::vector<SweepPoint> full = sweep_points(false, {"improved2-sc"});
  ASSERT_EQ(full.size(), 58u);
  std::set<std::string> names;
  for (const SweepPoint& p : full) {
    EXPECT_EQ(p.kind(), UnitKind::Improved2);
    EXPECT_TRUE(p.rtl()) << p.label();
    EXPECT_EQ(p.cfg.endpoints, 1) << p.label();
    names.insert(p.config_name());
  }
  EXPECT_EQ(names.size(), 58u);
  EXPECT_TRUE(names.count("S8 c16 b14 N1 gen2 dsp"));
  EXPECT_TRUE(names.count("S4 c12 b10 N1 gen2 radix16"));
  EXPECT_EQ(sweep_points(false, {"improved2-datapath"}).size(), 29u);  // the corner form once
  // Not in the default engines.
  for (const SweepPoint& p : sweep_points(false, {}))
    EXPECT_NE(p.kind(), UnitKind::Improved2) << p.label();

  TempDir dir;
  // A synthesized improved row at the default widths: gen2 must not take it; its own rows, one
  // per corner form, it takes.
  write_file(dir.file("synth.csv"),
             "unit,config,target,luts,ffs,carry,bram,dsp,fmax_mhz\n"
             "improved,default,xilinx7,6536,2320,818,0,9,\n"
             "improved2,default,xilinx7,6100,2700,900,0,0,\n"
             "improved2-products,default,xilinx7,4300,2360,748,0,15,\n");
  const std::string scenes = "builtin:hard-tiny;builtin:lowpoly-far;builtin:mixed:objects=2,tess=8";
  const CommandResult r = run_command(
      kBin + " sweep --quick --no-progress --engines golden,improved-sc,improved2-sc,"
             "improved2-datapath --scenes '" + scenes + "' --synth-csv " + dir.file("synth.csv") +
      " --out " + dir.file("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto cfgs = read_csv(dir.file("out/sweep_configs.csv"));
  int g2 = 0;
  for (const auto& row : cfgs) {
    if (row.at("unit") != "improved2") continue;
    ++g2;
    EXPECT_EQ(row.at("failures"), "0") << row.at("config");
    const std::string& name = row.at("config");
    const bool default_widths = name.rfind("S8 c16 b14 ", 0) == 0;
    // At the default widths the form's synthesized row; elsewhere the second generation's own
    // estimate, scaled to that row (smaller widths: less area).
    const int synthesized = name.find(" dsp") != std::string::npos ? 4300 : 6100;
    if (default_widths)
      EXPECT_EQ(row.at("luts"), std::to_string(synthesized)) << name;
    else
      EXPECT_LT(std::stoi(row.at("luts")), synthesized) << name;
    EXPECT_EQ(row.at("area_source"), default_widths ? "synth:xilinx7" : "estimate") << name;
    EXPECT_EQ(row.at("rtl"), "1") << name;
    // The same pixels as the first generation at the same widths.
    std::string gen1 = row.at("config");
    gen1 = gen1.substr(0, gen1.find(" N1 gen2"));
    gen1 += " K- N1";
    const auto* g1 = find_row(cfgs, "improved-sc", gen1);
    ASSERT_TRUE(g1) << gen1;
    for (const char* col : {"error_ppm", "missing_ppm", "extra_ppm", "max_error_ppm"})
      EXPECT_EQ(row.at(col), g1->at(col)) << row.at("config") << " " << col;
    EXPECT_EQ(row.at("rejected"), g1->at("rejected")) << row.at("config");
  }
  EXPECT_EQ(g2, 9);  // quick: three widths x (dsp, radix16, datapath)
  for (const std::string engine_config :
       {"improved2-sc|S8 c16 b14 N1 gen2 dsp", "improved2-sc|S8 c16 b14 N1 gen2 radix16",
        "improved2-datapath|S8 c16 b14 N1 gen2"}) {
    const size_t bar = engine_config.find('|');
    const auto* row = find_row(cfgs, engine_config.substr(0, bar), engine_config.substr(bar + 1));
    ASSERT_TRUE(row) << engine_config;
    EXPECT_EQ(row->at("exact"), "1") << engine_config;
    EXPECT_EQ(row->at("error_ppm"), "0.000") << engine_config;
  }
  EXPECT_EQ(find_row(cfgs, "improved2-datapath", "S8 c16 b14 N1 gen2")->at("total_cycles"), "");
  // Per scene: radix 16 spends its digit-serial corner runs, so never fewer cycles than the DSP
  // form, and more on the small triangles of lowpoly-far.
  const auto rows = read_csv(dir.file("out/sweep.csv"));
  for (const std::string scene : {"builtin:hard-tiny", "builtin:lowpoly-far"}) {
    const auto* dsp = find_row(rows, "improved2-sc", "S8 c16 b14 N1 gen2 dsp", scene);
    const auto* r16 = find_row(rows, "improved2-sc", "S8 c16 b14 N1 gen2 radix16", scene);
    ASSERT_TRUE(dsp && r16) << scene;
    EXPECT_GT(std::stol(dsp->at("total_cycles")), 0) << scene;
    EXPECT_GE(std::stol(r16->at("total_cycles")), std::stol(dsp->at("total_cycles"))) << scene;
    EXPECT_EQ(r16->at("missing"), "0") << scene;
    EXPECT_EQ(r16->at("extra"), "0") << scene;
    EXPECT_EQ(r16->at("luts"), "6100") << scene;
  }
  EXPECT_GT(std::stol(find_row(rows, "improved2-sc", "S8 c16 b14 N1 gen2 radix16",
                               "builtin:lowpoly-far")->at("total_cycles")),
            std::stol(find_row(rows, "improved2-sc", "S8 c16 b14 N1 gen2 dsp",
                               "builtin:lowpoly-far")->at("total_cycles")));
  // The JSON names the corner form and gives its synthesized area; a point of other widths its
  // estimate.
  const std::string json = slurp(dir.file("out/sweep.json"));
  const size_t at = json.find("\"config\": \"S8 c16 b14 N1 gen2 dsp\"");
  ASSERT_NE(at, std::string::npos);
  const std::string point = json.substr(at, json.find("\"scenes\"", at) - at);
  EXPECT_NE(point.find("\"corner_form\": \"dsp\""), std::string::npos) << point;
  EXPECT_NE(point.find("\"luts\": 4300"), std::string::npos) << point;
  const size_t other = json.find("\"config\": \"S4 c16 b14 N1 gen2 dsp\"");
  ASSERT_NE(other, std::string::npos);
  const std::string point2 = json.substr(other, json.find("\"scenes\"", other) - other);
  EXPECT_NE(point2.find("\"area_source\": \"estimate\""), std::string::npos) << point2;
}

TEST(SweepCli, BadUsageIsOneLine) {
  TempDir dir;
  for (const std::string& args :
       {std::string("sweep --jobs 0 --out ") + dir.file("x"),
        std::string("sweep --engines nope --out ") + dir.file("x"),
        std::string("sweep --scenes '' --out ") + dir.file("x"), std::string("fit"),
        std::string("fit --scene builtin:sphere --error-budget -1"),
        std::string("fit --scene builtin:sphere --endpoints 3"),
        std::string("fit --scene builtin:nosuchscene"),
        std::string("fit --scene builtin:sphere --unit improved3"),
        std::string("fit --scene builtin:sphere --corner-form dsp"),
        std::string("fit --scene builtin:sphere --unit improved2 --corner-form fast")}) {
    const CommandResult r = run_command(kBin + " " + args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
  }
  EXPECT_EQ(run_command(kBin + " sweep --help").status, 0);
  EXPECT_EQ(run_command(kBin + " fit --help").status, 0);
}

// ---- fit --------------------------------------------------------------------------------------

std::string json_field(const std::string& json, const std::string& object, const std::string& key) {
  const size_t o = json.find("\"" + object + "\": {");
  if (o == std::string::npos) return "";
  const size_t k = json.find("\"" + key + "\": ", o);
  if (k == std::string::npos) return "";
  const size_t v = k + key.size() + 4;
  return json.substr(v, json.find_first_of(",\n}", v) - v);
}

TEST(Fit, FloatMeshNeedsEightSubpixelBits) {
  TempDir dir;
  const CommandResult r = run_command(kBin + " fit --scene builtin:sphere:tess=12 --cull back " +
                                      "--report " + dir.file("fit.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string j = slurp(dir.file("fit.json"));
  EXPECT_EQ(json_field(j, "fit", "subpixel_bits"), "8") << j;
  EXPECT_EQ(json_field(j, "fit", "missing"), "0");
  EXPECT_EQ(json_field(j, "fit", "extra"), "0");
  EXPECT_EQ(json_field(j, "fit", "coord_bits"), "11");  // the 1024-pixel viewport's minimum
  EXPECT_EQ(json_field(j, "default", "subpixel_bits"), "8");
  EXPECT_LT(std::stod(json_field(j, "fit", "luts")), std::stod(json_field(j, "default", "luts")));
}

TEST(Fit, IntegerVerticesFitTheSmallestWidths) {
  // Integer-pixel vertices are exact at S = 0; boxes of at most 10 x 10 centres need 4 box bits
  // (Xmax = 9 < 16); a 64 x 64 viewport needs coordinates of 7 bits ([-64, 64)).
  TempDir dir;
  write_file(dir.file("ints.tri"),
             "0 0 10 0 0 10\n10 0 10 10 0 10\n20 20 30 25 22 30\n40 40 50 41 41 50\n");
  const CommandResult r = run_command(kBin + " fit --width 64 --height 64 --scene " +
                                      dir.file("ints.tri") + " --report " + dir.file("fit.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string j = slurp(dir.file("fit.json"));
  EXPECT_EQ(json_field(j, "fit", "subpixel_bits"), "0") << j;
  EXPECT_EQ(json_field(j, "fit", "coord_bits"), "7") << j;
  EXPECT_EQ(json_field(j, "fit", "box_bits"), "4") << j;
  EXPECT_EQ(json_field(j, "fit", "error_ppm"), "0") << j;
}

// The second generation: the same widths as the first on the same scene (both follow the rule;
// neither has a quotient truncation here), its own cycles (improved2-sc) and its own area, per
// corner form: the synthesized row at the default, an estimate scaled to it at the fit.
TEST(Fit, SecondGenerationFitsItsOwnUnit) {
  TempDir dir;
  const std::string scene = " --width 64 --height 64 --scene " + dir.file("ints.tri");
  write_file(dir.file("ints.tri"), "0 0 10 0 0 10\n10 0 10 10 0 10\n20 20 30 25 22 30\n");
  ASSERT_EQ(run_command(kBin + " fit" + scene + " --report " + dir.file("g1.json")).status, 0);
  const CommandResult r = run_command(kBin + " fit --unit improved2" + scene + " --report " +
                                      dir.file("g2.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("unit improved2 (radix16)"), std::string::npos) << r.out;
  ASSERT_EQ(run_command(kBin + " fit --unit improved2 --corner-form dsp" + scene + " --report " +
                        dir.file("dsp.json")).status, 0);
  const std::string g1 = slurp(dir.file("g1.json")), g2 = slurp(dir.file("g2.json")),
                    dsp = slurp(dir.file("dsp.json"));
  for (const char* key : {"subpixel_bits", "coord_bits", "box_bits"}) {
    EXPECT_EQ(json_field(g2, "fit", key), json_field(g1, "fit", key)) << key;
    EXPECT_EQ(json_field(dsp, "fit", key), json_field(g1, "fit", key)) << key;
  }
  EXPECT_EQ(json_field(g2, "fit", "quotient_bits"), "0");
  EXPECT_EQ(json_field(g2, "fit", "error_ppm"), "0");
  // Cycles of the second generation's model, not the first's.
  EXPECT_NE(json_field(g2, "default", "total_cycles"), json_field(g1, "default", "total_cycles"));
  // Area: the synthesized rows of docs/synth.csv at the default, each form its own; the fit an
  // estimate below it.
  EXPECT_EQ(json_field(g2, "default", "area_source"), "\"synth:xilinx7\"");
  EXPECT_EQ(json_field(g2, "fit", "area_source"), "\"estimate\"");
  EXPECT_LT(std::stod(json_field(g2, "fit", "luts")), std::stod(json_field(g2, "default", "luts")));
  EXPECT_NE(json_field(dsp, "default", "luts"), json_field(g2, "default", "luts"));
  EXPECT_NE(json_field(g2, "default", "luts"), json_field(g1, "default", "luts"));
}

TEST(Fit, ABudgetAllowsFewerBits) {
  TempDir dir;
  const std::string scene = " --scene builtin:mixed:objects=2,tess=8";
  ASSERT_EQ(run_command(kBin + " fit" + scene + " --report " + dir.file("exact.json")).status, 0);
  ASSERT_EQ(run_command(kBin + " fit" + scene + " --error-budget 1000000 --report " +
                        dir.file("loose.json")).status, 0);
  const std::string exact = slurp(dir.file("exact.json")), loose = slurp(dir.file("loose.json"));
  EXPECT_EQ(json_field(exact, "fit", "subpixel_bits"), "8");
  EXPECT_LT(std::stoi(json_field(loose, "fit", "subpixel_bits")), 8);
  EXPECT_LT(std::stod(json_field(loose, "fit", "luts")), std::stod(json_field(exact, "fit", "luts")));
}

// ---- the library: closed-mesh counting, truncation, area --------------------------------------

// The sweep counts cracks and double hits with the closed-mesh check of tb/common.
TEST(CountClosed, CracksAndDoubleHitsOfAFan) {
  RasterConfig cfg;
  const Scene scene = make_builtin("fan:n=8", cfg, CameraOptions{});
  const SetupResult setup = setup_scene(scene.tris, cfg);
  EngineResult golden;
  find_engine("golden")->make()->run(setup, cfg, golden);
  sort_spans(golden.spans);
  WatertightResult c = check_watertight(setup, golden.spans, cfg);
  EXPECT_EQ(c.cracks, 0);
  EXPECT_EQ(c.doubles, 0);
  // Drop a span from the middle of the list (an inner row of some triangle): a crack of its size.
  SpanList cracked = golden.spans;
  const size_t mid = cracked.size() / 2;
  const int64_t gap = cracked[mid].pixels();
  cracked.erase(cracked.begin() + long(mid));
  c = check_watertight(setup, cracked, cfg);
  EXPECT_EQ(c.cracks, gap);
  EXPECT_EQ(c.doubles, 0);
  // Draw a span twice: as many double hits as it has pixels.
  SpanList doubled = golden.spans;
  doubled.push_back(golden.spans[mid]);
  c = check_watertight(setup, doubled, cfg);
  EXPECT_EQ(c.cracks, 0);
  EXPECT_EQ(c.doubles, gap);
}

TEST(QuotientTruncation, DefaultUntouchedSmallKInexactNeverThrows) {
  RasterConfig cfg;
  const Scene scene = make_builtin("lowpoly-near", cfg, CameraOptions{});
  const SetupResult setup = setup_scene(scene.tris, cfg);
  auto run = [&](int K) {
    RasterConfig c = cfg;
    c.divider_quotient_bits = K;
    EngineResult r;
    find_engine("improved-datapath")->make()->run(setup, c, r);
    sort_spans(r.spans);
    return r;
  };
  const EngineResult def = run(0), full = run(15), wide = run(40), k4 = run(4);
  EXPECT_EQ(def.spans, full.spans);  // K = Q is the untruncated divider
  EXPECT_EQ(def.spans, wide.spans);  // a cap above Q changes nothing
  EXPECT_EQ(def.work.at("divider_iterations"), full.work.at("divider_iterations"));
  EXPECT_NE(def.spans, k4.spans);    // 4 quotient bits cannot hold these boxes
  EXPECT_LT(k4.work.at("divider_iterations"), def.work.at("divider_iterations"));
}

TEST(AreaModel, SynthesisWhereCoveredEstimateElsewhere) {
  TempDir dir;
  const AreaModel none(dir.file("missing.csv"), dir.file("missing.sh"));
  EXPECT_FALSE(none.have_synth());
  RasterConfig def;
  EXPECT_EQ(none.area(UnitKind::Improved, def).source, "estimate");
  EXPECT_EQ(none.area(UnitKind::Cpu, def).source, "");
  write_file(dir.file("synth.csv"),
             "unit,config,target,luts,ffs,carry,bram,dsp,fmax_mhz\n"
             "improved,default,ice40,15982,2896,3400,0,0,\n"
             "improved,default,xilinx7,6605,2320,818,0,9,\n"
             "improved,small,xilinx7,4500,1612,573,0,9,\n");
  const AreaModel synth(dir.file("synth.csv"), dir.file("missing.sh"));
  ASSERT_TRUE(synth.have_synth());
  EXPECT_EQ(synth.target(), "xilinx7");
  const Area d = synth.area(UnitKind::Improved, def);
  EXPECT_EQ(d.source, "synth:xilinx7");
  EXPECT_EQ(d.luts, 6605);
  EXPECT_EQ(d.ffs, 2320);
  RasterConfig small;
  small.subpixel_bits = 4;
  small.coord_int_bits = 12;
  small.box_bits = 10;
  EXPECT_EQ(synth.area(UnitKind::Improved, small).luts, 4500);
  // N = 4 or a truncated quotient is not what was synthesized: an estimate, calibrated so that
  // the formula meets synthesis at the default, and larger for N = 4.
  RasterConfig n4;
  n4.endpoints = 4;
  const Area e = synth.area(UnitKind::Improved, n4);
  EXPECT_EQ(e.source, "estimate");
  EXPECT_GT(e.luts, d.luts);
  EXPECT_EQ(synth.area(UnitKind::Trad, def).source, "estimate");
  // Without its own row the traditional unit takes the improved unit's scale; with one, its own:
  // its estimate then meets its synthesis at the default, and the improved unit's is unchanged.
  RasterConfig trad_small = small;
  const Area trad_before = synth.estimate(UnitKind::Trad, trad_small);
  write_file(dir.file("trad.csv"), slurp(dir.file("synth.csv")) + "trad,default,xilinx7,2092,846,0,0,2,\n");
  const AreaModel with_trad(dir.file("trad.csv"), dir.file("missing.sh"));
  EXPECT_EQ(with_trad.estimate(UnitKind::Trad, def).luts, 2092);
  EXPECT_EQ(with_trad.estimate(UnitKind::Trad, def).ffs, 846);
  EXPECT_NE(with_trad.estimate(UnitKind::Trad, trad_small).luts, trad_before.luts);
  EXPECT_LT(with_trad.estimate(UnitKind::Trad, trad_small).luts, 2092);
  EXPECT_EQ(with_trad.estimate(UnitKind::Improved, n4).luts, e.luts);
  // The half-space unit: synthesized per stamp size at tile 8, forward; no width formula.
  write_file(dir.file("hs.csv"),
             "unit,config,target,luts,ffs,carry,bram,dsp,fmax_mhz\n"
             "improved,default,xilinx7,6605,2320,818,0,9,\n"
             "halfspace-s2,default,xilinx7,5944,2393,799,0,15,\n");
  const AreaModel hs(dir.file("hs.csv"), dir.file("missing.sh"));
  RasterConfig hs_cfg;
  EXPECT_EQ(synth_unit_name(UnitKind::Halfspace, hs_cfg), "halfspace-s2");
  EXPECT_EQ(hs.area(UnitKind::Halfspace, hs_cfg).luts, 5944);
  EXPECT_EQ(hs.area(UnitKind::Improved, hs_cfg).luts, 6605);  // not confused with the improved row
  hs_cfg.halfspace.tile = 16;
  EXPECT_FALSE(hs.area(UnitKind::Halfspace, hs_cfg).known());
  hs_cfg.halfspace.tile = 8;
  hs_cfg.halfspace.walk = HalfspaceWalk::Row;
  EXPECT_FALSE(hs.area(UnitKind::Halfspace, hs_cfg).known());
  hs_cfg.halfspace.walk = HalfspaceWalk::Zigzag;
  EXPECT_FALSE(hs.area(UnitKind::Halfspace, hs_cfg).known());
  hs_cfg.halfspace.walk = HalfspaceWalk::Forward;
  hs_cfg.halfspace.stamp = 4;
  EXPECT_FALSE(hs.area(UnitKind::Halfspace, hs_cfg).known());
  EXPECT_FALSE(hs.estimate(UnitKind::Halfspace, RasterConfig{}).known());
  // The second-generation unit: never the improved unit's synthesis or estimate.
  EXPECT_FALSE(hs.area(UnitKind::Improved2, RasterConfig{}).known());
  EXPECT_FALSE(hs.estimate(UnitKind::Improved2, RasterConfig{}).known());
  RasterConfig products;
  products.improved2.corner_form = 0;
  // With its own row (radix 16 only): its estimate meets that row at the default widths and
  // grows with the widths; the products form, not synthesized, stays unknown.
  write_file(dir.file("g2.csv"),
             "unit,config,target,luts,ffs,carry,bram,dsp,fmax_mhz\n"
             "improved,default,xilinx7,6536,2320,818,0,9,\n"
             "improved2,default,xilinx7,6100,2700,900,0,0,\n");
  const AreaModel g2(dir.file("g2.csv"), dir.file("missing.sh"));
  const Area g2_def = g2.estimate(UnitKind::Improved2, RasterConfig{});
  EXPECT_EQ(g2_def.luts, 6100);
  EXPECT_EQ(g2_def.ffs, 2700);
  EXPECT_EQ(g2.area(UnitKind::Improved2, RasterConfig{}).source, "synth:xilinx7");
  RasterConfig g2_wide;
  g2_wide.coord_int_bits = 20;
  const Area w = g2.area(UnitKind::Improved2, g2_wide);
  EXPECT_EQ(w.source, "estimate");
  EXPECT_GT(w.luts, 6100);
  EXPECT_GT(w.ffs, 2700);
  EXPECT_FALSE(g2.area(UnitKind::Improved2, products).known());
  EXPECT_EQ(g2.area(UnitKind::Improved, RasterConfig{}).luts, 6536);  // gen1 unchanged
  EXPECT_EQ(synth_unit_name(UnitKind::Improved2, RasterConfig{}), "improved2");
  EXPECT_EQ(synth_unit_name(UnitKind::Improved2, products), "improved2-products");
  EXPECT_EQ(hs.fmax_mhz(UnitKind::Improved2, RasterConfig{}), 0);
  write_file(dir.file("bad.csv"), "unit,config,luts\nimproved,default,1\n");
  EXPECT_THROW(AreaModel(dir.file("bad.csv"), ""), std::runtime_error);
}

}  // namespace
}  // namespace trirast
