// Speed of the SystemC models on the built-in benchmark scenes (scripts/bench_sim.sh): triangles
// per second and simulated cycles per second of the improved unit's model, the traditional unit's
// model beside it, and, when this build has an "rtl" engine, the model/RTL wall-time ratio.
// Usage: trirast_sc_bench [--repeat R] [scene ...]   (default: the five seed-000 scenes)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <systemc>  // declares sc_main extern "C"
#include <vector>

#include "core/engine.hpp"
#include "core/setup.hpp"
#include "sc/sc_engine.hpp"
#include "scene/scene.hpp"

using namespace trirast;

namespace {

struct Timing {
  double seconds = 0;  // best wall time of one run
  uint64_t cycles = 0;
};

Timing time_engine(Engine& e, const SetupResult& setup, const RasterConfig& cfg, int repeat) {
  Timing t;
  t.seconds = 1e30;
  for (int i = 0; i < repeat; ++i) {
    EngineResult r;
    const auto t0 = std::chrono::steady_clock::now();
    e.run(setup, cfg, r);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    t.seconds = std::min(t.seconds, s);
    t.cycles = r.total_cycles;
  }
  return t;
}

}  // namespace

int sc_main(int argc, char** argv) {
  int repeat = 5;
  std::vector<std::string> scenes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeat" && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else
      scenes.push_back(a);
  }
  if (scenes.empty())
    scenes = {"lowpoly-far", "lowpoly-near", "highpoly-far", "highpoly-near", "mixed"};
  const EngineInfo* rtl = find_engine("rtl");
  RasterConfig cfg;
  std::printf("SystemC model speed, best of %d runs, 1024x768, S=8, N=1, FIFO 8, sink ready\n",
              repeat);
  std::printf("%-15s %9s %11s %9s %12s %14s %11s %14s", "scene", "triangles", "cycles", "model s",
              "model tri/s", "model cycles/s", "trad s", "trad cycles/s");
  if (rtl) std::printf(" %9s %10s", "rtl s", "rtl/model");
  std::printf("\n");
  for (const std::string& name : scenes) {
    const Scene scene = make_builtin(name, cfg, CameraOptions{});
    const SetupResult setup = setup_scene(scene.tris, cfg);
    auto model = make_model_engine();
    auto trad = make_trad_model_engine();
    const Timing m = time_engine(*model, setup, cfg, repeat);
    const Timing t = time_engine(*trad, setup, cfg, repeat);
    const double tris = double(setup.tris.size());
    std::printf("%-15s %9zu %11llu %9.4f %12.0f %14.0f %11.4f %14.0f", name.c_str(),
                setup.tris.size(), (unsigned long long)m.cycles, m.seconds, tris / m.seconds,
                double(m.cycles) / m.seconds, t.seconds, double(t.cycles) / t.seconds);
    if (rtl) {
      auto r = rtl->make();
      const Timing rt = time_engine(*r, setup, cfg, 1);
      std::printf(" %9.4f %10.1f", rt.seconds, rt.seconds / m.seconds);
    }
    std::printf("\n");
    std::fflush(stdout);
  }
  return 0;
}
