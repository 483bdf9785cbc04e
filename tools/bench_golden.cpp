// Speed of the golden traversals (docs/golden-performance.md, made by scripts/bench_golden.sh):
// triangles and covered pixels per second of every traversal on the five seed-000 scene analogues
// (Table 1's cases C1..C5), two meshes, 10-pixel and large synthetic triangles, and the
// multi-threaded golden on scenes of >= 100,000 triangles. Setup (snapping, edge functions) is
// done once outside the timed loop: it is common to every engine; its own speed is measured
// separately ("setup/...").
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "common/setup.hpp"
#include "golden/golden.hpp"
#include "golden/helper_pool.hpp"
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
  RasterConfig cfg;  // 1024x768 as in the tests of Mileff, Nehéz & Dudra, S = 8
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

// ---- Threads: one thread against two, and the machine's ceiling ---------------------------------
//
// The machine is shared: what other jobs take from it drifts over seconds, so two medians taken
// at different moments (even interleaved) differ by 10-20% on the same code. So each iteration of
// a thread benchmark runs, a few milliseconds apart, in an order that rotates from one iteration
// to the next:
//   one   the golden engine on one thread,
//   two   the golden engine on two threads,
//   solo  the "twin" workload on one thread: every triangle rasterized twice, into two lists,
//   twin  the twin workload on two threads: each rasterizes every triangle once, into its list.
// The twin workload is the golden's own work with nothing to balance, order, copy or join (both
// threads do the same work, into lists of their own kept between runs, each on a cache line of
// its own): solo / twin is what the machine gave two threads of this very workload (its memory
// traffic and instruction mix included) at that moment, the ceiling of any 2-thread golden.
// Reported: medians of each time, of the engine's speed-up one / two ("speedup"), of the
// ceiling solo / twin ("ceiling") and of the engine's share of the ceiling, the ratio of the two
// taken within each iteration ("of_ceiling").

double seconds_of(const std::function<void()>& work) {
  const auto t0 = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

// A second thread for the ceilings: the engine's own HelperPool (golden/helper_pool.hpp), asleep
// between runs, so that the ceiling pays what the engine pays to start its helper (a wake-up),
// not a thread's creation. run(mine, theirs) has the helper do `theirs` while the caller does
// `mine`, and returns when both are done.
class Partner {
 public:
  Partner() {
    if (pool_.reserve(1) != 1) throw std::runtime_error("bench_golden: no second thread");
  }
  void run(const std::function<void()>& mine, const std::function<void()>& theirs) {
    const HelperPool::Job job = [&](size_t) { theirs(); };
    pool_.start(job, 1);
    mine();
    pool_.finish();
  }

 private:
  HelperPool pool_;
};

// Runs works[0..n) once per iteration, one after the other, the order rotating by one from an
// iteration to the next; returns each work's times (seconds), one per iteration. The iteration's
// time is the sum.
std::vector<std::vector<double>> rotating_times(benchmark::State& state,
                                                const std::vector<std::function<void()>>& works) {
  const size_t n = works.size();
  std::vector<std::vector<double>> t(n);
  size_t rotation = 0;
  for (auto _ : state) {
    double total = 0;
    for (size_t k = 0; k < n; ++k) {
      const size_t w = (rotation + k) % n;
      t[w].push_back(seconds_of(works[w]));
      total += t[w].back();
    }
    rotation = (rotation + 1) % n;
    state.SetIterationTime(total);
  }
  return t;
}

void bench_threads(benchmark::State& state, std::string name, Traversal traversal) {
  const BenchScene& s = scene(name);
  const RasterConfig cfg = bench_config();
  auto engine1 = make_golden_engine(traversal, 1), engine2 = make_golden_engine(traversal, 2);
  size_t spans = 0;
  // The engine: the wall clock of everything a caller of Engine::run pays for: waking the helper,
  // the chunk lists, and a fresh output list (its allocation and growth included) holding every
  // span in triangle order. Setup is not included: the caller has done it before run() for any
  // engine; "setup/<scene>" measures it on its own.
  auto run = [&](Engine& engine) {
    EngineResult r;
    engine.run(s.setup, cfg, r);
    benchmark::DoNotOptimize(r.spans.data());
    spans = r.spans.size();
  };
  struct alignas(64) OwnList {
    SpanList spans;
  } own[2];
  for (OwnList& l : own) l.spans.reserve(1 << 21);
  auto pass = [&](size_t id) {
    own[id].spans.clear();
    for (const TriangleSetup& t : s.setup.tris) golden_triangle(t, cfg, traversal, own[id].spans);
    benchmark::DoNotOptimize(own[id].spans.data());
  };
  Partner partner;
  const std::vector<std::vector<double>> t = rotating_times(
      state, {[&] { run(*engine1); },
              [&] { run(*engine2); },
              [&] {
                pass(0);
                pass(1);
              },
              [&] { partner.run([&] { pass(0); }, [&] { pass(1); }); }});
  std::vector<double> speedup, ceiling, share;
  for (size_t i = 0; i < t[0].size(); ++i) {
    speedup.push_back(t[0][i] / t[1][i]);
    ceiling.push_back(t[2][i] / t[3][i]);
    share.push_back(speedup.back() / ceiling.back());
  }
  state.counters["one_ms"] = median_of(t[0]) * 1e3;
  state.counters["two_ms"] = median_of(t[1]) * 1e3;
  state.counters["solo_ms"] = median_of(t[2]) * 1e3;
  state.counters["twin_ms"] = median_of(t[3]) * 1e3;
  state.counters["speedup"] = median_of(speedup);
  state.counters["ceiling"] = median_of(ceiling);
  state.counters["of_ceiling"] = median_of(share);
  state.counters["iterations"] = double(speedup.size());
  state.counters["tris"] = double(s.setup.tris.size());
  state.counters["spans"] = double(spans);
}

// The ceiling for pure arithmetic: a chain of multiply-adds (no memory, nothing shared). Two idle
// cores give 2x.
uint64_t arithmetic(uint64_t steps, uint64_t seed) {
  uint64_t x = seed;
  for (uint64_t k = 0; k < steps; ++k) x = x * 6364136223846793005ull + 1442695040888963407ull;
  return x;
}

// The same pairing for any work cut in two: one thread does both halves, against two threads one
// half each (the second woken as above), one after the other in alternating order.
void paired_halves(benchmark::State& state, const std::function<void()>& first,
                   const std::function<void()>& second) {
  Partner partner;
  const std::function<void()> one = [&] {
    first();
    second();
  };
  const std::function<void()> two = [&] { partner.run(first, second); };
  const std::vector<std::vector<double>> t = rotating_times(state, {one, two});
  std::vector<double> ratio;
  for (size_t i = 0; i < t[0].size(); ++i) ratio.push_back(t[0][i] / t[1][i]);
  state.counters["one_ms"] = median_of(t[0]) * 1e3;
  state.counters["two_ms"] = median_of(t[1]) * 1e3;
  state.counters["speedup"] = median_of(ratio);
  state.counters["iterations"] = double(ratio.size());
}

void bench_ceiling_arithmetic(benchmark::State& state, uint64_t steps) {
  struct alignas(64) Result {
    uint64_t value = 0;
  } results[2];
  paired_halves(
      state, [&] { benchmark::DoNotOptimize(results[0].value = arithmetic(steps / 2, 1)); },
      [&] { benchmark::DoNotOptimize(results[1].value = arithmetic(steps - steps / 2, 2)); });
}

// The ceiling for streaming memory: each half reads one array and writes a running sum into
// another, 16 MB each (about a scene's triangles and spans), no array shared between halves.
void bench_ceiling_stream(benchmark::State& state) {
  constexpr size_t kWords = (16u << 20) / sizeof(uint64_t);
  struct Arrays {
    std::vector<uint64_t> in, out;
  } arrays[2];
  for (size_t h = 0; h < 2; ++h) {
    arrays[h].in.assign(kWords, h + 1);
    arrays[h].out.assign(kWords, 0);
  }
  auto half = [&](size_t h) {
    uint64_t sum = 0;
    const uint64_t* in = arrays[h].in.data();
    uint64_t* out = arrays[h].out.data();
    for (size_t k = 0; k < kWords; ++k) out[k] = sum += in[k];
    benchmark::DoNotOptimize(out);
    benchmark::ClobberMemory();
  };
  paired_halves(state, [&] { half(0); }, [&] { half(1); });
}

// Two of the engine's own costs, on their own: waking a sleeping second thread and waiting for it
// to report back (a Partner with nothing to do: what starting the helper and learning that it
// is done costs at least), and copying a scene's spans from one list to the end of another
// (warm, reserved) one: the writer copies every chunk the helper rasterized this way.
void bench_wake(benchmark::State& state) {
  Partner partner;
  for (auto _ : state) partner.run([] {}, [] {});
}

void bench_copy(benchmark::State& state, std::string name) {
  const BenchScene& s = scene(name);
  const RasterConfig cfg = bench_config();
  SpanList all, to;
  for (const TriangleSetup& t : s.setup.tris) golden_triangle(t, cfg, all);
  to.reserve(all.size());
  for (auto _ : state) {
    to.clear();
    to.insert(to.end(), all.begin(), all.end());
    benchmark::DoNotOptimize(to.data());
  }
  state.counters["spans"] = double(all.size());
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

// Each thread benchmark runs this many batches of iterations (each batch at least kThreadSeconds
// of measured time); scripts/bench_golden.sh reports the median batch and the range.
// TRIRAST_BENCH_QUICK=1 (scripts/bench_golden.sh --quick, run by the suite) cuts every time to a
// few iterations: it checks that the program and the document's rendering work, nothing more.
const bool kQuick = [] {
  const char* q = std::getenv("TRIRAST_BENCH_QUICK");
  return q != nullptr && std::string(q) == "1";
}();
const int kThreadBatches = kQuick ? 1 : 3;
const double kThreadSeconds = kQuick ? 0.02 : 3.0;
const double kTraversalSeconds = kQuick ? 0.005 : 0.3;

// The ceiling's amount of arithmetic: about 16 ms on one thread here, the order of the thread
// benchmarks' one-thread times.
constexpr uint64_t kCeilingSteps = 12000000;

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
          ->MinTime(kTraversalSeconds);
  for (const char* sc : {"highpoly-near", "random100k"})
    for (Traversal tr : {Traversal::Auto, Traversal::Incremental, Traversal::Simple})
      benchmark::RegisterBenchmark(
          (std::string("threads/") + sc + "/" + traversal_name(tr)).c_str(), bench_threads,
          std::string(sc), tr)
          ->Unit(benchmark::kMillisecond)
          ->MinTime(kThreadSeconds)
          ->Repetitions(kThreadBatches)
          ->UseManualTime();
  benchmark::RegisterBenchmark("ceiling/arithmetic", bench_ceiling_arithmetic, kCeilingSteps)
      ->Unit(benchmark::kMillisecond)
      ->MinTime(kThreadSeconds)
      ->Repetitions(kThreadBatches)
      ->UseManualTime();
  benchmark::RegisterBenchmark("ceiling/stream", bench_ceiling_stream)
      ->Unit(benchmark::kMillisecond)
      ->MinTime(kThreadSeconds)
      ->Repetitions(kThreadBatches)
      ->UseManualTime();
  benchmark::RegisterBenchmark("threads/wake", bench_wake)
      ->Unit(benchmark::kMicrosecond)
      ->MinTime(kTraversalSeconds);
  for (const char* sc : {"highpoly-near", "random100k"})
    benchmark::RegisterBenchmark((std::string("copy/") + sc).c_str(), bench_copy, std::string(sc))
        ->Unit(benchmark::kMillisecond)
        ->MinTime(kTraversalSeconds);
  for (const char* sc : {"tri10", "highpoly-near", "random100k"})
    benchmark::RegisterBenchmark((std::string("setup/") + sc).c_str(), bench_setup,
                                 std::string(sc))
        ->Unit(benchmark::kMillisecond)
        ->MinTime(kTraversalSeconds);
  return true;
}();

}  // namespace
}  // namespace trirast

BENCHMARK_MAIN();
