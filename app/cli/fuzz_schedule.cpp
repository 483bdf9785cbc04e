#include "cli/fuzz_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <stdexcept>

#include "engines.hpp"

namespace trirast {

namespace {

// CPU nanoseconds per run, triangle, box row, box column and half-space stamp. Measured in two
// steps on a Release build (a load average of 13 on 2 cores, so CPU time): `trirast fuzz
// --calibrate` fits the constants to five fixed scenes (each dominated by one quantity) and
// prints them (the first five columns below); the fuzzer's own scenes (sink stalls, queue downstreams,
// 2 and 4 endpoints) cost some engines more and others less, so each row is then scaled by that
// engine's CPU / estimate ratio of `trirast fuzz --seconds 20 --seed 3031` with the calibrated
// rows (the summary's "CPU s" and "est. s" columns), the `scale` below. The estimates only steer
// the schedule; a wrong constant costs balance, never a comparison.
struct Calibrated {
  const char* engine;
  double run_ns, tri_ns, row_ns, col_ns, stamp_ns, scale;
};
const Calibrated kCalibrated[] = {
    // engine                run_ns  tri_ns  row_ns  col_ns  stamp_ns  scale
    {"golden", 2106, 5, 8, 0, 0, 3.30},
    {"improved-datapath", 3582, 0, 186, 8, 0, 0.28},
    {"improved-sc", 12375, 0, 191, 8, 0, 0.37},
    {"improved-rtl", 95395, 2583, 581, 23, 0, 1.70},
    {"improved2-datapath", 4743, 0, 185, 8, 0, 0.28},
    {"improved2-sc", 13708, 0, 159, 6, 0, 0.42},
    {"improved2-rtl", 88891, 4471, 829, 18, 0, 2.70},
    {"halfspace-datapath", 2596, 0, 136, 15, 28, 1.00},
    {"halfspace-sc", 10931, 0, 210, 18, 22, 1.00},
    {"halfspace-rtl", 110858, 1886, 303, 53, 141, 1.40},
};
const std::vector<FuzzEngineCost> kFuzzCosts = [] {
  std::vector<FuzzEngineCost> v;
  for (const Calibrated& c : kCalibrated)
    v.push_back({c.engine, c.run_ns * c.scale, c.tri_ns * c.scale, c.row_ns * c.scale,
                 c.col_ns * c.scale, c.stamp_ns * c.scale});
  return v;
}();

double process_cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// splitmix64 of (seed, scene, engine): the engine's draw for the scene, uniform in [0, 1).
double schedule_draw(uint64_t seed, uint64_t scene, uint64_t engine) {
  uint64_t z = seed * 0x9e3779b97f4a7c15ull ^ (scene + 1) * 0xd1b54a32d192ed03ull ^
               (engine + 1) * 0x8cb92ba72f3d8dd7ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return double(z >> 11) * 0x1.0p-53;
}

int64_t ceil_div(int64_t a, int64_t b) { return (a + b - 1) / b; }

}  // namespace

const std::vector<FuzzEngineCost>& fuzz_cost_table() { return kFuzzCosts; }

const FuzzEngineCost& fuzz_engine_cost(const std::string& engine) {
  for (const FuzzEngineCost& c : kFuzzCosts)
    if (engine == c.engine) return c;
  // An engine without a row: the dearest constants of the table, column by column.
  static const FuzzEngineCost dearest = [] {
    FuzzEngineCost d{"?", 0, 0, 0, 0, 0};
    for (const FuzzEngineCost& c : kFuzzCosts) {
      d.run_ns = std::max(d.run_ns, c.run_ns);
      d.tri_ns = std::max(d.tri_ns, c.tri_ns);
      d.row_ns = std::max(d.row_ns, c.row_ns);
      d.col_ns = std::max(d.col_ns, c.col_ns);
      d.stamp_ns = std::max(d.stamp_ns, c.stamp_ns);
    }
    return d;
  }();
  return dearest;
}

FuzzCostFeatures fuzz_cost_features(const SetupResult& setup, const RasterConfig& cfg, int width,
                                    int height, uint32_t tri_begin, uint32_t tri_end) {
  FuzzCostFeatures f;
  const int64_t s = std::max(1, cfg.halfspace.stamp), t = cfg.halfspace.tile;
  const int64_t u = t ? t : s;
  for (const TriangleSetup& tri : setup.tris) {
    if (tri.index < tri_begin || tri.index >= tri_end) continue;
    f.tris += 1;
    PixelBox b = tri.box;
    b.x1 = std::min(b.x1, width - 1);
    b.y1 = std::min(b.y1, height - 1);
    const int64_t w = b.width(), h = b.height();
    f.rows += double(h);
    f.cols += double(w);
    if (w == 0 || h == 0) continue;
    // Unit tests, plus the stamps of the partial tiles: the tiles along the edges, at most the
    // whole box in stamps.
    const int64_t units = ceil_div(w, u) * ceil_div(h, u);
    const int64_t all_stamps = ceil_div(w, s) * ceil_div(h, s);
    const int64_t partial = t ? std::min(all_stamps, 2 * (ceil_div(w, t) + ceil_div(h, t)) *
                                                         ceil_div(t, s) * ceil_div(t, s))
                              : 0;
    f.stamps += double(units + partial);
  }
  return f;
}

double fuzz_estimate_ns(const FuzzEngineCost& c, const FuzzCostFeatures& f) {
  return c.run_ns + c.tri_ns * f.tris + c.row_ns * f.rows + c.col_ns * f.cols +
         c.stamp_ns * f.stamps;
}

std::vector<FuzzAssignment> fuzz_schedule_scene(uint64_t seed, uint64_t scene,
                                                const SetupResult& setup, uint32_t n_tris,
                                                const RasterConfig& cfg,
                                                const std::vector<std::string>& engines,
                                                const FuzzSchedulePolicy& policy) {
  std::vector<FuzzAssignment> out(engines.size());
  const double cap = policy.share_ns * policy.slot_period;
  for (size_t e = 0; e < engines.size(); ++e) {
    FuzzAssignment& a = out[e];
    const FuzzEngineCost& cost = fuzz_engine_cost(engines[e]);
    a.width = cfg.width;
    a.height = cfg.height;
    a.tri_begin = 0;
    a.tri_end = n_tris;
    auto estimate = [&] {
      return fuzz_estimate_ns(
          cost, fuzz_cost_features(setup, cfg, a.width, a.height, a.tri_begin, a.tri_end));
    };
    a.estimate_ns = estimate();
    if (engines[e] == "golden") {  // the truth runs every scene whole
      a.runs = true;
      continue;
    }
    // Too dear: crop the viewport at its top-left corner, the larger side first, down to 16.
    while (a.estimate_ns > cap && std::max(a.width, a.height) > 16) {
      if (a.width >= a.height) a.width = std::max(16, a.width / 2);
      else a.height = std::max(16, a.height / 2);
      a.estimate_ns = estimate();
      a.cut = true;
    }
    // Still too dear: a window of consecutive triangles, halved, at an offset drawn from the
    // scene (so every triangle of the scene is as likely to be in it).
    if (a.estimate_ns > cap && n_tris > 1) {
      const double pick = schedule_draw(seed, scene, 1000 + e);
      uint32_t len = n_tris;
      while (a.estimate_ns > cap && len > 1) {
        len = std::max<uint32_t>(1, len / 2);
        a.tri_begin = uint32_t(pick * double(n_tris - len + 1));
        a.tri_end = a.tri_begin + len;
        a.estimate_ns = estimate();
      }
      a.cut = true;
    }
    const bool slot = scene % uint64_t(policy.slot_period) == e % uint64_t(policy.slot_period);
    a.runs = slot || schedule_draw(seed, scene, e) * a.estimate_ns < policy.share_ns;
  }
  return out;
}

// ---- calibration --------------------------------------------------------------------------------

namespace {

// Solves the n x n system m * x = r in place (partial pivoting); a singular column gives 0.
std::vector<double> solve(std::vector<std::vector<double>> m, std::vector<double> r) {
  const size_t n = r.size();
  for (size_t c = 0; c < n; ++c) {
    size_t p = c;
    for (size_t i = c + 1; i < n; ++i)
      if (std::fabs(m[i][c]) > std::fabs(m[p][c])) p = i;
    std::swap(m[c], m[p]);
    std::swap(r[c], r[p]);
    if (std::fabs(m[c][c]) < 1e-12) continue;
    for (size_t i = 0; i < n; ++i) {
      if (i == c) continue;
      const double k = m[i][c] / m[c][c];
      for (size_t j = c; j < n; ++j) m[i][j] -= k * m[c][j];
      r[i] -= k * r[c];
    }
  }
  std::vector<double> x(n, 0.0);
  for (size_t i = 0; i < n; ++i)
    if (std::fabs(m[i][i]) >= 1e-12) x[i] = r[i] / m[i][i];
  return x;
}

InputTriangle tri_at(double x, double y, double w, double h) {
  return InputTriangle{{x, x + w, x}, {y, y, y + h}};
}

}  // namespace

void fuzz_calibrate(const std::vector<std::string>& engines, std::FILE* out) {
  // Five scenes, each dominated by one quantity: a run, triangles, rows, columns, stamps; at the
  // defaults (16.8, 14-bit boxes, stamp 2, tile 8, zig-zag), 1024 x 1024.
  RasterConfig cfg;
  cfg.width = cfg.height = 1024;
  std::vector<std::vector<InputTriangle>> scenes(5);
  scenes[0] = {tri_at(10.2, 10.2, 2, 2)};
  for (int i = 0; i < 300; ++i) scenes[1].push_back(tri_at(3.0 + 3 * (i % 300), 5.0 + 3 * (i / 300), 2.5, 2.5));
  for (int i = 0; i < 40; ++i) scenes[2].push_back(tri_at(4.0 + 20 * i, 4, 3, 1000));
  for (int i = 0; i < 40; ++i) scenes[3].push_back(tri_at(4, 4.0 + 20 * i, 1000, 3));
  for (int i = 0; i < 4; ++i) scenes[4].push_back(tri_at(2, 2, 1000, 1000));
  std::vector<SetupResult> setups;
  std::vector<std::vector<double>> m;
  for (const auto& s : scenes) {
    setups.push_back(setup_scene(s, cfg));
    const FuzzCostFeatures f = fuzz_cost_features(setups.back(), cfg, cfg.width, cfg.height, 0,
                                                  uint32_t(s.size()));
    m.push_back({1.0, f.tris, f.rows, f.cols, f.stamps});
  }
  std::fprintf(out, "    // engine                run_ns    tri_ns   row_ns   col_ns  stamp_ns\n");
  for (const std::string& name : engines) {
    const EngineInfo* info = find_engine(name);
    if (!info) throw std::invalid_argument("unknown engine '" + name + "'");
    std::vector<double> ns;
    for (const SetupResult& setup : setups) {
      // Repeat until 0.2 s of CPU time (at least 3 runs), the mean per run.
      int runs = 0;
      const double t0 = process_cpu_seconds();
      double t = t0;
      while (runs < 3 || t - t0 < 0.2) {
        EngineResult r;
        info->make()->run(setup, cfg, r);
        ++runs;
        t = process_cpu_seconds();
      }
      ns.push_back((t - t0) / runs * 1e9);
    }
    std::vector<double> x = solve(m, ns);
    for (double& v : x) v = std::max(0.0, std::round(v));
    std::fprintf(out, "    {\"%s\", %.0f, %.0f, %.0f, %.0f, %.0f},\n", name.c_str(), x[0], x[1],
                 x[2], x[3], x[4]);
    std::fflush(out);
  }
}

}  // namespace trirast
