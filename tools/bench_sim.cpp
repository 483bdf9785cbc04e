// Speed of the SystemC models on the built-in benchmark scenes (scripts/bench_sim.sh): triangles
// per second and simulated cycles per second of the improved unit's model, the traditional unit's
// model beside it, and, when this build has an "improved-rtl" engine, the Verilated RTL's time on
// the same scene in the same run and the RTL/model time ratio (target: the model >= 20x faster).
// Runs alternate (model, trad, rtl, model, trad, rtl, ...) so that a change of the machine's load
// hits all of them; each time is the best of its runs. Wall time and process CPU time are both
// measured: on a shared machine the CPU-time ratio is the steadier of the two.
// Usage: trirast_sc_bench [--unit improved|improved2] [--repeat R] [--rtl-repeat R] [--model-only]
//                         [--md FILE] [scene ...]
//        trirast_sc_bench --units [--repeat R] [--rtl-repeat R] [--md FILE] [scene ...]
//        (--units: every timed unit -- improved, improved2 in both corner forms, trad, halfspace --
//        its model's and its RTL's cycles per CPU-second and the ratio; default scenes
//        highpoly-far and mixed)
//        (default: the improved unit, the five seed-000 benchmark scenes, R = 5, RTL R = 3; --md
//        also writes the table as Markdown, for docs/sc-model.md; --unit improved2: the
//        second-generation unit's model improved2-sc and RTL improved2-rtl, the trad model beside)
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <systemc>  // declares sc_main extern "C"
#include <vector>

#include "common/engine.hpp"
#include "engines.hpp"
#include "common/setup.hpp"
#include "improved/improved_sc.hpp"
#include "improved2/improved2_sc.hpp"
#include "trad/trad_sc.hpp"
#include "scene/scene.hpp"

using namespace trirast;

namespace {

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct Timing {
  double wall = 1e30;  // best wall time of one run
  double cpu = 1e30;   // best process CPU time of one run
  uint64_t cycles = 0;
  int runs = 0;
};

void time_once(Engine& e, const SetupResult& setup, const RasterConfig& cfg, Timing& t) {
  EngineResult r;
  const double c0 = cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  e.run(setup, cfg, r);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double c = cpu_seconds() - c0;
  t.wall = std::min(t.wall, s);
  t.cpu = std::min(t.cpu, c);
  t.cycles = r.total_cycles;
  ++t.runs;
}

// --units: for each unit (improved, improved2 in its radix-16 and DSP corner forms, trad,
// halfspace) and scene, the SystemC model's and the Verilated RTL's cycles per CPU-second and
// their ratio, runs alternating model, RTL, model, RTL, ...; each the best of its runs.
int every_unit(const std::vector<std::string>& scenes, int repeat, int rtl_repeat,
               const std::string& md_path) {
  struct UnitRow {
    const char* label;
    const char* base;  // engines base-sc, base-rtl
    int corner_form;   // improved2's corner form (1 radix-16 digit-serial, 0 DSP products)
  };
  const UnitRow units[] = {{"improved", "improved", 1},
                           {"improved2 (radix-16)", "improved2", 1},
                           {"improved2 (DSP)", "improved2", 0},
                           {"trad", "trad", 1},
                           {"halfspace", "halfspace", 1}};
  std::printf("SystemC models against the Verilated RTL, every timed unit: cycles per CPU-second "
              "(process CPU time), 1024x768, S=8, N=1, FIFO 8, sink ready; best of %d model and %d "
              "RTL runs, alternating\n",
              repeat, rtl_repeat);
  std::printf("%-22s %-14s %9s %9s %11s %9s %11s %9s\n", "unit", "scene", "cycles", "model cpu",
              "model cyc/s", "rtl cpu", "rtl cyc/s", "model/rtl");
  std::ofstream md;
  if (!md_path.empty()) {
    md.open(md_path);
    md << "| unit | scene | cycles | model CPU s | model cycles/CPU-s | RTL CPU s | RTL cycles/CPU-s | "
          "model / RTL |\n|---|---|---:|---:|---:|---:|---:|---:|\n";
  }
  auto num = [](double v, const char* fmt) {
    char b[64];
    std::snprintf(b, sizeof b, fmt, v);
    return std::string(b);
  };
  int status = 0;
  for (const UnitRow& u : units) {
    const EngineInfo* sc = find_engine(std::string(u.base) + "-sc");
    const EngineInfo* rtl = find_engine(std::string(u.base) + "-rtl");
    if (!sc) {
      std::fprintf(stderr, "trirast_sc_bench: no engine %s-sc\n", u.base);
      return 2;
    }
    for (const std::string& name : scenes) {
      RasterConfig cfg;
      cfg.improved2.corner_form = u.corner_form;
      const Scene scene = make_builtin(name, cfg, CameraOptions{});
      const SetupResult setup = setup_scene(scene.tris, cfg);
      auto model = sc->make();
      std::unique_ptr<Engine> r = rtl ? rtl->make() : nullptr;
      Timing m, rt;
      for (int i = 0; i < std::max(repeat, r ? rtl_repeat : 0); ++i) {
        if (i < repeat) time_once(*model, setup, cfg, m);
        if (r && i < rtl_repeat) time_once(*r, setup, cfg, rt);
      }
      if (r && rt.cycles != m.cycles) {
        std::fprintf(stderr, "trirast_sc_bench: %s %s: rtl cycles %llu != model cycles %llu\n",
                     u.label, name.c_str(), (unsigned long long)rt.cycles,
                     (unsigned long long)m.cycles);
        status = 1;
      }
      const double mc = double(m.cycles) / m.cpu * 1e-6;
      std::printf("%-22s %-14s %9llu %9.4f %10.3gM", u.label, name.c_str(),
                  (unsigned long long)m.cycles, m.cpu, mc);
      if (r)
        std::printf(" %9.4f %10.3gM %9.1f\n", rt.cpu, double(rt.cycles) / rt.cpu * 1e-6,
                    rt.cpu / m.cpu);
      else
        std::printf(" %9s %11s %9s\n", "-", "-", "-");
      std::fflush(stdout);
      if (md.is_open()) {
        md << "| " << u.label << " | " << name << " | " << m.cycles << " | " << num(m.cpu, "%.4f")
           << " | " << num(mc, "%.3g M") << " | ";
        if (r)
          md << num(rt.cpu, "%.4f") << " | " << num(double(rt.cycles) / rt.cpu * 1e-6, "%.3g M")
             << " | " << num(rt.cpu / m.cpu, "%.1f") << " |\n";
        else
          md << "- | - | - |\n";
      }
    }
  }
  return status;
}

}  // namespace

int sc_main(int argc, char** argv) {
  int repeat = 5, rtl_repeat = 3;
  bool model_only = false, units = false;
  std::string md_path, unit = "improved";
  std::vector<std::string> scenes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeat" && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else if (a == "--rtl-repeat" && i + 1 < argc)
      rtl_repeat = std::max(1, std::atoi(argv[++i]));
    else if (a == "--units")  // every timed unit, model and RTL cycles per CPU-second
      units = true;
    else if (a == "--model-only")  // for profiling: no trad, no rtl
      model_only = true;
    else if (a == "--md" && i + 1 < argc)
      md_path = argv[++i];
    else if (a == "--unit" && i + 1 < argc)
      unit = argv[++i];
    else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "trirast_sc_bench: unknown option %s\n", a.c_str());
      return 2;
    } else
      scenes.push_back(a);
  }
  if (units) {
    if (scenes.empty()) scenes = {"highpoly-far", "mixed"};
    return every_unit(scenes, repeat, rtl_repeat, md_path);
  }
  if (scenes.empty())
    scenes = {"lowpoly-far", "lowpoly-near", "highpoly-far", "highpoly-near", "mixed"};
  if (unit != "improved" && unit != "improved2") {
    std::fprintf(stderr, "trirast_sc_bench: --unit: '%s' is not improved or improved2\n", unit.c_str());
    return 2;
  }
  const EngineInfo* rtl = model_only ? nullptr : find_engine(unit + "-rtl");
  RasterConfig cfg;
  std::printf("SystemC model speed (%s-sc), 1024x768, S=8, N=1, FIFO 8, sink ready; best of %d runs "
              "(RTL %d), runs alternating\n",
              unit.c_str(), repeat, rtl ? rtl_repeat : 0);
  std::printf("%-14s %7s %9s %8s %9s %10s %11s %8s %10s", "scene", "tris", "cycles", "model s",
              "model tri/s", "model cyc/s", "cyc/cpu-s", "trad s", "trad cyc/s");
  if (rtl)
    std::printf(" %8s %10s %8s %10s %9s %8s", "rtl s", "rtl cyc/s", "rtl cpu", "cyc/cpu-s",
                "rtl/model", "cpu ratio");
  std::printf("\n");
  std::ofstream md;
  if (!md_path.empty()) {
    md.open(md_path);
    md << "| scene | triangles | cycles | model s | model tri/s | model cycles/s | trad s | "
          "trad cycles/s";
    if (rtl)
      md << " | RTL s | RTL cycles/s | RTL CPU s | RTL cycles/CPU-s | **RTL / model wall** | "
            "RTL / model CPU";
    md << " |\n|---|---:|---:|---:|---:|---:|---:|---:" << (rtl ? "|---:|---:|---:|---:|---:|---:" : "")
       << "|\n";
  }
  auto num = [](double v, const char* fmt) {
    char b[64];
    std::snprintf(b, sizeof b, fmt, v);
    return std::string(b);
  };
  for (const std::string& name : scenes) {
    const Scene scene = make_builtin(name, cfg, CameraOptions{});
    const SetupResult setup = setup_scene(scene.tris, cfg);
    auto model = unit == "improved2" ? make_improved2_sc_engine() : make_improved_sc_engine();
    auto trad = make_trad_sc_engine();
    std::unique_ptr<Engine> r = rtl ? rtl->make() : nullptr;
    Timing m, t, rt;
    for (int i = 0; i < std::max(repeat, rtl ? rtl_repeat : 0); ++i) {
      if (i < repeat) time_once(*model, setup, cfg, m);
      if (i < repeat && !model_only) time_once(*trad, setup, cfg, t);
      if (r && i < rtl_repeat) time_once(*r, setup, cfg, rt);
    }
    const double tris = double(setup.tris.size());
    std::printf("%-14s %7zu %9llu %8.4f %9.3gM %9.3gM %10.3gM", name.c_str(), setup.tris.size(),
                (unsigned long long)m.cycles, m.wall, tris / m.wall * 1e-6,
                double(m.cycles) / m.wall * 1e-6, double(m.cycles) / m.cpu * 1e-6);
    if (model_only)
      std::printf(" %8s %10s", "-", "-");
    else
      std::printf(" %8.4f %9.3gM", t.wall, double(t.cycles) / t.wall * 1e-6);
    if (rtl) {
      if (rt.cycles != m.cycles)
        std::fprintf(stderr, "trirast_sc_bench: %s: rtl cycles %llu != model cycles %llu\n",
                     name.c_str(), (unsigned long long)rt.cycles, (unsigned long long)m.cycles);
      std::printf(" %8.4f %9.3gM %8.4f %9.3gM %9.1f %8.1f", rt.wall,
                  double(rt.cycles) / rt.wall * 1e-6, rt.cpu, double(rt.cycles) / rt.cpu * 1e-6,
                  rt.wall / m.wall, rt.cpu / m.cpu);
    }
    std::printf("\n");
    std::fflush(stdout);
    if (md.is_open()) {
      md << "| " << name << " | " << setup.tris.size() << " | " << m.cycles << " | "
         << num(m.wall, "%.4f") << " | " << num(tris / m.wall * 1e-6, "%.3g M") << " | "
         << num(double(m.cycles) / m.wall * 1e-6, "%.3g M") << " | ";
      if (model_only)
        md << "- | -";
      else
        md << num(t.wall, "%.4f") << " | " << num(double(t.cycles) / t.wall * 1e-6, "%.3g M");
      if (rtl)
        md << " | " << num(rt.wall, "%.4f") << " | " << num(double(rt.cycles) / rt.wall * 1e-6, "%.3g M")
           << " | " << num(rt.cpu, "%.4f") << " | " << num(double(rt.cycles) / rt.cpu * 1e-6, "%.3g M")
           << " | **" << num(rt.wall / m.wall, "%.1f") << "** | " << num(rt.cpu / m.cpu, "%.1f");
      md << " |\n";
    }
  }
  return 0;
}
