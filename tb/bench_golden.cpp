// Speed of the golden traversals (docs/golden-performance.md, made by scripts/bench_golden.sh):
// triangles and covered pixels per second of every traversal on the five seed-000 scene analogues
// (Table 1's cases C1..C5), two meshes, 10-pixel and large synthetic triangles, and the
// multi-threaded golden on scenes of >= 100,000 triangles. Setup (snapping, edge functions) is
// done once outside the timed loop: it is common to every engine; its own speed is measured
// separately ("setup/...").
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "core/setup.hpp"
#include "golden/golden.hpp"
#include "scene/scene.hpp"

namespace trirast {
namespace {

struct BenchScene {
  std::vector<InputTriangle> input;
  SetupResult setup;
  int64_t pixels = 0;  // covered pixels of one pass
};

// n triangles of about `area` square pixels each, random shape, orientation and position on the
// 1/256 grid, inside a width x height viewport.
std::vector<InputTriangle> sized_triangles(int n, double area, int width, int height,
                                           unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto grid = [](double v) { return std::nearbyint(v * 256) / 256; };
  std::vector<InputTriangle> tris;
  const double side = std::sqrt(2 * area);
  for (int k = 0; k < n; ++k) {
    // A triangle with base b and height 2*area/b, its apex anywhere above the base, rotated.
    const double b = side * (0.6 + 0.8 * unit(rng)), h = 2 * area / b, s = b * unit(rng);
    const double a = 2 * M_PI * unit(rng), c = std::cos(a), sn = std::sin(a);
    const double lx[3] = {0, b, s}, ly[3] = {0, 0, h};
    const double r = side * 1.5;
    const double ox = r + unit(rng) * (width - 2 * r), oy = r + unit(rng) * (height - 2 * r);
    InputTriangle t;
    for (int i = 0; i < 3; ++i) {
      t.x[i] = grid(ox + (lx[i] - b / 2) * c - (ly[i] - h / 2) * sn);
      t.y[i] = grid(oy + (lx[i] - b / 2) * sn + (ly[i] - h / 2) * c);
    }
    tris.push_back(t);
  }
  return tris;
}

RasterConfig bench_config() {
  RasterConfig cfg;  // 1024x768 as in seed 000's tests, S = 8
  return cfg;
}

const BenchScene& scene(const std::string& name) {
  static std::map<std::string, BenchScene> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  const RasterConfig cfg = bench_config();
  BenchScene s;
  if (name == "tri10") s.input = sized_triangles(100000, 10, cfg.width, cfg.height, 1);
  else if (name == "large") s.input = sized_triangles(200, 150000, cfg.width, cfg.height, 2);
  else if (name == "random100k") s.input = sized_triangles(120000, 60, cfg.width, cfg.height, 3);
  else s.input = make_builtin(name, cfg, CameraOptions{}).tris;
  s.setup = setup_scene(s.input, cfg);
  SpanList spans;
  for (const TriangleSetup& t : s.setup.tris) golden_triangle(t, cfg, spans);
  s.pixels = count_pixels(spans);
  return cache.emplace(name, std::move(s)).first->second;
}

void set_counters(benchmark::State& state, const BenchScene& s) {
  using benchmark::Counter;
  state.counters["tris"] = Counter(double(s.setup.tris.size()));
  state.counters["tris_per_s"] =
      Counter(double(s.setup.tris.size()), Counter::kIsIterationInvariantRate);
  state.counters["pixels_per_s"] = Counter(double(s.pixels), Counter::kIsIterationInvariantRate);
}

// One traversal over every triangle of a scene, single thread.
void bench_traversal(benchmark::State& state, std::string name, Traversal traversal) {
  const BenchScene& s = scene(name);
  const RasterConfig cfg = bench_config();
  SpanList spans;
  spans.reserve(1 << 20);
  for (auto _ : state) {
    spans.clear();
    for (const TriangleSetup& t : s.setup.tris) golden_triangle(t, cfg, traversal, spans);
    benchmark::DoNotOptimize(spans.data());
    benchmark::ClobberMemory();
  }
  set_counters(state, s);
}

// The golden engine on `threads` threads, wall-clock time of everything a caller of
// Engine::run pays for: thread start and join, the chunk lists, and a fresh output list (its
// allocation and growth included) holding every span in triangle order. Setup is not included:
// the caller has done it before run() for any engine; "setup/<scene>" measures it on its own.
void bench_threads(benchmark::State& state, std::string name, Traversal traversal, int threads) {
  const BenchScene& s = scene(name);
  const RasterConfig cfg = bench_config();
  auto engine = make_golden_engine(traversal, threads);
  size_t spans = 0;
  for (auto _ : state) {
    EngineResult r;
    engine->run(s.setup, cfg, r);
    benchmark::DoNotOptimize(r.spans.data());
    spans = r.spans.size();
  }
  set_counters(state, s);
  state.counters["spans"] = benchmark::Counter(double(spans));
}

// The floor of any 2-thread golden: two threads (one started per run, as the engine does), each
// rasterizing half of the triangles into a list of its own, kept between runs; no output list, no
// order, no balancing. Its speed-up over one thread is what the machine gives two threads at the
// time of the run (on the shared machine, other jobs take their share of the cores).
void bench_halves(benchmark::State& state, std::string name, Traversal traversal) {
  const BenchScene& s = scene(name);
  const RasterConfig cfg = bench_config();
  const size_t half = s.setup.tris.size() / 2;
  SpanList lists[2];
  for (SpanList& l : lists) l.reserve(1 << 21);
  auto part = [&](size_t id) {
    lists[id].clear();
    const size_t first = id == 0 ? 0 : half, last = id == 0 ? half : s.setup.tris.size();
    for (size_t k = first; k < last; ++k) golden_triangle(s.setup.tris[k], cfg, traversal, lists[id]);
  };
  for (auto _ : state) {
    std::thread other(part, size_t(1));
    part(0);
    other.join();
    benchmark::DoNotOptimize(lists[0].data());
    benchmark::DoNotOptimize(lists[1].data());
  }
  set_counters(state, s);
}

// Setup alone (snap, orient, edge functions, box), for scale.
void bench_setup(benchmark::State& state, std::string name) {
  const BenchScene& s = scene(name);
  const RasterConfig cfg = bench_config();
  for (auto _ : state) {
    SetupResult r = setup_scene(s.input, cfg);
    benchmark::DoNotOptimize(r.tris.data());
  }
  set_counters(state, s);
}

// The thread benchmarks run this many times each; scripts/bench_golden.sh interleaves them in a
// random order (--benchmark_enable_random_interleaving), so that a burst of load from other jobs
// on the shared machine hits 1-thread and 2-thread runs alike, and reports medians.
constexpr int kThreadRepetitions = 9;

const bool registered = [] {
  const char* scenes[] = {"lowpoly-far", "lowpoly-near", "highpoly-far", "highpoly-near", "mixed",
                          "sphere",      "torus",        "tri10",        "large"};
  int n = 0;
  const Traversal* all = all_traversals(&n);
  for (const char* sc : scenes)
    for (int k = 0; k < n; ++k)
      benchmark::RegisterBenchmark(
          (std::string("traversal/") + sc + "/" + traversal_name(all[k])).c_str(),
          bench_traversal, std::string(sc), all[k])
          ->Unit(benchmark::kMillisecond)
          ->MinTime(0.3);
  for (const char* sc : {"highpoly-near", "random100k"})
    for (Traversal tr : {Traversal::Auto, Traversal::Incremental, Traversal::Simple})
      for (int threads : {1, 2}) {
        benchmark::RegisterBenchmark((std::string("threads/") + sc + "/" + traversal_name(tr) +
                                      "/" + std::to_string(threads))
                                         .c_str(),
                                     bench_threads, std::string(sc), tr, threads)
            ->Unit(benchmark::kMillisecond)
            ->MinTime(0.2)
            ->Repetitions(kThreadRepetitions)
            ->UseRealTime();
      }
  for (const char* sc : {"highpoly-near", "random100k"})
    for (Traversal tr : {Traversal::Auto, Traversal::Incremental, Traversal::Simple})
      benchmark::RegisterBenchmark(
          (std::string("halves/") + sc + "/" + traversal_name(tr)).c_str(), bench_halves,
          std::string(sc), tr)
          ->Unit(benchmark::kMillisecond)
          ->MinTime(0.2)
          ->Repetitions(kThreadRepetitions)
          ->UseRealTime();
  for (const char* sc : {"tri10", "highpoly-near", "random100k"})
    benchmark::RegisterBenchmark((std::string("setup/") + sc).c_str(), bench_setup,
                                 std::string(sc))
        ->Unit(benchmark::kMillisecond)
        ->MinTime(0.3);
  return true;
}();

}  // namespace
}  // namespace trirast

BENCHMARK_MAIN();
