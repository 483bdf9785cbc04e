// The improved unit against the traditional one and the half-space tile unit in cycles (scripts/cycles_table.sh writes the
// output to docs/cycles-improved-vs-trad.md): the five seed-000 scene analogues and meshes, both
// SystemC models with the default parameters (N = 1, FIFO 8, sink always ready), and the improved
// unit with N = 4 and in divide mode beside them. Then, after a line "@@", the second-generation
// improved unit (improved2-sc, both corner forms) beside the first and the traditional unit.
#include <cstdio>
#include <string>
#include <systemc>  // declares sc_main extern "C"
#include <vector>

#include "common/setup.hpp"
#include "benchmark_scenes.hpp"
#include "improved/improved_sc.hpp"
#include "improved2/improved2_sc.hpp"
#include "trad/trad_sc.hpp"
#include "halfspace/halfspace_sc.hpp"
#include "scene/scene.hpp"

using namespace trirast;

namespace {

struct Run {
  uint64_t cycles = 0, setup_busy = 0, walk_busy = 0;
};

Run run(Engine& e, const SetupResult& setup, const RasterConfig& cfg) {
  EngineResult r;
  e.run(setup, cfg, r);
  return Run{r.total_cycles, r.work["busy_cycles.setup"], r.work["busy_cycles.walk"]};
}

std::string pct(double improved, double trad) {
  char b[32];
  std::snprintf(b, sizeof b, "%+.1f%%", 100.0 * (trad - improved) / trad);
  return b;
}

}  // namespace

int sc_main(int argc, char** argv) {
  const std::string source = argc > 1 ? argv[1] : ".";
  const std::vector<BenchmarkScene> scenes = benchmark_scenes(source);
  std::printf(
      "| scene | triangles | improved cycles | trad cycles | improved vs trad | improved cyc/tri "
      "(setup, walk) | trad cyc/tri (setup, walk) | improved N=4 | improved divide | "
      "improved fixed divider | half-space cycles (S2 T8 forward) | half-space vs improved | "
      "half-space cyc/tri (setup, walk) | half-space S4 T16 | half-space S1 no tiles |\n");
  std::printf("|---|---:|---:|---:|---:|---|---|---:|---:|---:|---:|---:|---|---:|---:|\n");
  uint64_t sum_i = 0, sum_t = 0, sum_h = 0, sum_g = 0, sum_gd = 0;
  std::string gen2_rows;
  for (const BenchmarkScene& e : scenes) {
    RasterConfig cfg;
    Scene scene;
    try {
      scene = load_scene(e.spec, cfg, CameraOptions{});
    } catch (const std::exception& ex) {
      std::fprintf(stderr, "cycles_table: %s: %s (skipped)\n", e.spec.c_str(), ex.what());
      continue;
    }
    const SetupResult setup = setup_scene(scene.tris, cfg);
    const double n = setup.tris.empty() ? 1.0 : double(setup.tris.size());
    auto model = make_improved_sc_engine();
    auto trad = make_trad_sc_engine();
    const Run i = run(*model, setup, cfg);
    const Run t = run(*trad, setup, cfg);
    RasterConfig cfg4 = cfg;
    cfg4.endpoints = 4;
    const Run i4 = run(*model, setup, cfg4);
    RasterConfig cfgd = cfg;
    cfgd.boundary = BoundaryMode::Divide;
    const Run id = run(*model, setup, cfgd);
    RasterConfig cfgf = cfg;
    cfgf.divider = DividerMode::Fixed;
    const Run ifx = run(*model, setup, cfgf);
    auto hs = make_halfspace_sc_engine();
    const Run h = run(*hs, setup, cfg);
    RasterConfig cfgh4 = cfg;
    cfgh4.halfspace.stamp = 4;
    cfgh4.halfspace.tile = 16;
    const Run h4 = run(*hs, setup, cfgh4);
    RasterConfig cfgh1 = cfg;
    cfgh1.halfspace.stamp = 1;
    cfgh1.halfspace.tile = 0;
    const Run h1 = run(*hs, setup, cfgh1);
    auto gen2 = make_improved2_sc_engine();
    RasterConfig cfgg = cfg;
    cfgg.improved2.corner_form = 1;
    const Run g = run(*gen2, setup, cfgg);
    cfgg.improved2.corner_form = 0;
    const Run gd = run(*gen2, setup, cfgg);
    sum_i += i.cycles;
    sum_t += t.cycles;
    sum_h += h.cycles;
    sum_g += g.cycles;
    sum_gd += gd.cycles;
    char row[512];
    std::snprintf(row, sizeof row, "| %s | %zu | %llu | %llu | %llu | %s | %s | %.2f | %llu | %s | %.2f |\n",
                  e.label.c_str(), setup.tris.size(), (unsigned long long)t.cycles,
                  (unsigned long long)i.cycles, (unsigned long long)g.cycles,
                  pct(double(g.cycles), double(t.cycles)).c_str(),
                  pct(double(g.cycles), double(i.cycles)).c_str(), double(g.cycles) / n,
                  (unsigned long long)gd.cycles, pct(double(gd.cycles), double(t.cycles)).c_str(),
                  double(gd.cycles) / n);
    gen2_rows += row;
    std::printf(
        "| %s | %zu | %llu | %llu | %s | %.1f (%.1f, %.1f) | %.1f (%.1f, %.1f) | %llu | %llu | "
        "%llu | %llu | %s | %.1f (%.1f, %.1f) | %llu | %llu |\n",
        e.label.c_str(), setup.tris.size(), (unsigned long long)i.cycles,
        (unsigned long long)t.cycles, pct(double(i.cycles), double(t.cycles)).c_str(),
        double(i.cycles) / n, double(i.setup_busy) / n, double(i.walk_busy) / n,
        double(t.cycles) / n, double(t.setup_busy) / n, double(t.walk_busy) / n,
        (unsigned long long)i4.cycles, (unsigned long long)id.cycles,
        (unsigned long long)ifx.cycles, (unsigned long long)h.cycles,
        pct(double(h.cycles), double(i.cycles)).c_str(), double(h.cycles) / n,
        double(h.setup_busy) / n, double(h.walk_busy) / n, (unsigned long long)h4.cycles,
        (unsigned long long)h1.cycles);
  }
  std::printf("| **all** | | %llu | %llu | %s | | | | | | %llu | %s | | | |\n",
              (unsigned long long)sum_i, (unsigned long long)sum_t,
              pct(double(sum_i), double(sum_t)).c_str(), (unsigned long long)sum_h,
              pct(double(sum_h), double(sum_i)).c_str());
  std::printf("@@\n");
  std::printf(
      "| scene | triangles | trad cycles | gen1 cycles | gen2 cycles (radix-16 corner) | gen2 vs "
      "trad | gen2 vs gen1 | gen2 cyc/tri | gen2 DSP corner | gen2 DSP vs trad | gen2 DSP "
      "cyc/tri |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::printf("%s", gen2_rows.c_str());
  std::printf("| **all** | | %llu | %llu | %llu | %s | %s | | %llu | %s | |\n",
              (unsigned long long)sum_t, (unsigned long long)sum_i, (unsigned long long)sum_g,
              pct(double(sum_g), double(sum_t)).c_str(), pct(double(sum_g), double(sum_i)).c_str(),
              (unsigned long long)sum_gd, pct(double(sum_gd), double(sum_t)).c_str());
  return 0;
}
