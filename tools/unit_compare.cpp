// Which unit wins where (scripts/which_unit_wins.sh turns the output into docs/which-unit-wins.md):
// the timed SystemC models of the improved unit, the second-generation improved unit in both corner
// forms (radix-16 digit-serial, the iCE40 form and the default; DSP products, the xc7 form), the
// traditional unit and the half-space unit (stamp 1, 2, 4; tile 8, forward walk; in both corner
// forms: DSP products, the CLI default and the xc7 form; radix-16 digit-serial, the iCE40 form),
// the CLI defaults
// otherwise (N = 1, FIFO 8, sink always ready, S = 8, 1024x768)
// on the benchmark scenes and meshes, and on a sweep of scenes whose triangles all have one box
// size and aspect ratio.
//
//   trirast_unit_compare OUTDIR SOURCE_ROOT [MESH ...]
//
// Writes into OUTDIR:
//   scenes.csv        scene,label,spec,triangles,<unit> (total cycles of each unit)
//   tris-<scene>.csv  tri,box_w,box_h,pixels,trad_pixels,<unit>...: per accepted triangle its clipped
//                     pixel box (TriangleSetup::box), covered pixels (the coverage rule's, which
//                     every exact unit draws; trad_pixels: the inexact traditional unit's own), and
//                     per unit the cycles it adds to the
//                     scene's total (added_cycles: done cycle minus the latest done cycle before
//                     it), so the column sums to the unit's total cycles
//   sweep.csv         box_area,aspect,box_w,box_h,triangles,mean_box,mean_pixels,trad_mean_pixels,
//                     <unit>: the total cycles of each unit on a scene of equal-shaped triangles
//                     (cycles per triangle = total / triangles)
// The unit columns are improved, improved2 (radix-16 corners), improved2p (product corners), trad,
// hs1, hs2, hs4 (product corners), hsr1, hsr2, hsr4 (radix-16 corners).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
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

struct Unit {
  const char* name;
  int stamp;        // half-space stamp size, 0 for the Bresenham units
  int corner_form;  // the corner form of the second-generation or half-space unit, else -1
};
const Unit kUnits[] = {{"improved", 0, -1}, {"improved2", 0, 1}, {"improved2p", 0, 0},
                       {"trad", 0, -1},     {"hs1", 1, 0},       {"hs2", 2, 0},
                       {"hs4", 4, 0},       {"hsr1", 1, 1},      {"hsr2", 2, 1},
                       {"hsr4", 4, 1}};

std::unique_ptr<Engine> make(const Unit& u) {
  if (u.stamp > 0) return make_halfspace_sc_engine();
  if (u.corner_form >= 0) return make_improved2_sc_engine();
  return std::string(u.name) == "improved" ? make_improved_sc_engine() : make_trad_sc_engine();
}

RasterConfig config_of(const Unit& u) {
  RasterConfig cfg;  // the defaults: tile 8, forward walk
  if (u.stamp > 0) {
    cfg.halfspace.stamp = u.stamp;
    cfg.halfspace.corner_form = u.corner_form;
  } else if (u.corner_form >= 0) {
    cfg.improved2.corner_form = u.corner_form;
  }
  return cfg;
}

// Per-triangle cycles: what each triangle adds to the run's total, in completion order: its done
// cycle minus the latest done cycle of the triangles completed before it (a triangle with nothing
// to walk can complete while an earlier one is still walking: it adds 0 then). The column sums to
// the run's total cycles.
std::vector<uint64_t> added_cycles(const EngineResult& r, size_t n, const std::string& what) {
  if (r.cycles.size() != n)
    throw std::runtime_error(what + ": " + std::to_string(r.cycles.size()) + " cycle records for " +
                             std::to_string(n) + " triangles");
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return r.cycles[a].done_cycle < r.cycles[b].done_cycle;
  });
  std::vector<uint64_t> out(n);
  uint64_t prev_end = 0;  // one past the latest done cycle so far
  for (size_t i : order) {
    const uint64_t end = r.cycles[i].done_cycle + 1;
    out[i] = end - prev_end;
    prev_end = end;
  }
  return out;
}

std::string slug(const std::string& s) {
  std::string o;
  for (char c : s) o += (std::isalnum(static_cast<unsigned char>(c)) ? c : '-');
  return o;
}

// n triangles whose clipped boxes are w x h pixels (w, h >= 1): a triangle spanning the box with
// one vertex on each of three sides, mirrored four ways and placed at random positions (fixed seed)
// wholly inside the viewport, at random sub-pixel offsets.
std::vector<InputTriangle> shaped(double w, double h, int n, const RasterConfig& cfg, uint64_t seed) {
  std::vector<InputTriangle> tris;
  uint64_t s = seed;
  auto rnd = [&s]() {  // splitmix64 -> [0, 1)
    uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return double((z ^ (z >> 31)) >> 11) / double(1ULL << 53);
  };
  // Vertices on the box [0, w] x [0, h] measured between pixel centres: the box holds w x h
  // centres when its extent is (w - 1) x (h - 1) plus a sub-pixel margin on each side.
  const double ex = w - 1 + 0.5, ey = h - 1 + 0.5;
  const double u[3] = {0.0, 1.0, 0.3}, v[3] = {1.0, 0.6, 0.0};
  for (int k = 0; k < n; ++k) {
    const double ox = 1 + rnd() * std::max(0.0, cfg.width - ex - 3);
    const double oy = 1 + rnd() * std::max(0.0, cfg.height - ey - 3);
    const double fx = std::floor(ox) + 0.25 + 0.25 * rnd(), fy = std::floor(oy) + 0.25 + 0.25 * rnd();
    const bool mx = k & 1, my = k & 2;
    InputTriangle t;
    for (int i = 0; i < 3; ++i) {
      t.x[i] = fx + ex * (mx ? 1 - u[i] : u[i]);
      t.y[i] = fy + ey * (my ? 1 - v[i] : v[i]);
    }
    tris.push_back(t);
  }
  return tris;
}

}  // namespace

int sc_main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: trirast_unit_compare OUTDIR SOURCE_ROOT [MESH ...]\n");
    return 2;
  }
  const std::string out = argv[1], source = argv[2];
  std::vector<BenchmarkScene> scenes = benchmark_scenes(source);
  for (int i = 3; i < argc; ++i) {
    std::string p = argv[i];
    scenes.push_back({"mesh: " + p.substr(p.find_last_of('/') + 1), p});
  }
  try {
    std::ofstream sc(out + "/scenes.csv");
    if (!sc) throw std::runtime_error(out + "/scenes.csv: cannot write");
    sc << "scene,label,spec,triangles";
    for (const Unit& u : kUnits) sc << ',' << u.name;
    sc << '\n';
    for (const BenchmarkScene& e : scenes) {
      const RasterConfig cfg;
      Scene scene;
      try {
        scene = load_scene(e.spec, cfg, CameraOptions{});
      } catch (const std::exception& ex) {
        std::fprintf(stderr, "unit_compare: %s: %s (skipped)\n", e.spec.c_str(), ex.what());
        continue;
      }
      const SetupResult setup = setup_scene(scene.tris, cfg);
      const size_t n = setup.tris.size();
      std::vector<std::vector<uint64_t>> cyc;
      std::vector<uint64_t> total, pixels, trad_pixels;
      for (const Unit& u : kUnits) {
        EngineResult r;
        make(u)->run(setup, config_of(u), r);
        cyc.push_back(added_cycles(r, n, e.spec + " " + u.name));
        total.push_back(r.total_cycles);
        if (pixels.empty())
          for (const TriangleCycles& c : r.cycles) pixels.push_back(c.pixels);
        if (std::string(u.name) == "trad")
          for (const TriangleCycles& c : r.cycles) trad_pixels.push_back(c.pixels);
      }
      const std::string name = slug(e.label);
      std::ofstream t(out + "/tris-" + name + ".csv");
      t << "tri,box_w,box_h,pixels,trad_pixels";
      for (const Unit& u : kUnits) t << ',' << u.name;
      t << '\n';
      for (size_t i = 0; i < n; ++i) {
        t << setup.tris[i].index << ',' << setup.tris[i].box.width() << ','
          << setup.tris[i].box.height() << ',' << pixels[i] << ',' << trad_pixels[i];
        for (size_t k = 0; k < cyc.size(); ++k) t << ',' << cyc[k][i];
        t << '\n';
      }
      sc << name << ',' << e.label << ',' << e.spec << ',' << n;
      for (uint64_t v : total) sc << ',' << v;
      sc << '\n';
      std::fprintf(stderr, "unit_compare: %s: %zu triangles\n", e.label.c_str(), n);
    }

    // The sweep: box areas 1 .. 2^16 pixels in powers of 4 (and the powers of 2 between), aspect
    // ratios w/h of 1/16 .. 16.
    std::ofstream sw(out + "/sweep.csv");
    sw << "box_area,aspect,box_w,box_h,triangles,mean_box,mean_pixels,trad_mean_pixels";
    for (const Unit& u : kUnits) sw << ',' << u.name;
    sw << '\n';
    for (int la = 0; la <= 16; ++la) {
      const double area = std::ldexp(1.0, la);
      for (double aspect : {1.0 / 16, 1.0 / 4, 1.0, 4.0, 16.0}) {
        const double w = std::round(std::sqrt(area * aspect)), h = std::round(std::sqrt(area / aspect));
        const RasterConfig cfg;
        if (w < 1 || h < 1 || w > cfg.width - 4 || h > cfg.height - 4) continue;
        // About 2^18 box pixels per scene (at least 16, at most 1024 triangles).
        const int n = int(std::min(1024.0, std::max(16.0, std::ldexp(1.0, 18) / (w * h))));
        const SetupResult setup = setup_scene(shaped(w, h, n, cfg, uint64_t(la * 100 + aspect * 16)), cfg);
        if (setup.tris.empty()) continue;
        double box = 0, pix = 0, tpix = 0;
        std::vector<uint64_t> per;
        for (const Unit& u : kUnits) {
          EngineResult r;
          make(u)->run(setup, config_of(u), r);
          per.push_back(r.total_cycles);
          if (std::string(u.name) == "trad")
            for (const TriangleCycles& c : r.cycles) tpix += double(c.pixels);
          if (box == 0)
            for (size_t i = 0; i < setup.tris.size(); ++i) {
              box += double(setup.tris[i].box.width() * setup.tris[i].box.height());
              pix += double(r.cycles[i].pixels);
            }
        }
        const double m = double(setup.tris.size());
        char line[256];
        std::snprintf(line, sizeof line, "%.0f,%.4g,%.0f,%.0f,%zu,%.1f,%.1f,%.1f", area, aspect, w,
                      h, setup.tris.size(), box / m, pix / m, tpix / m);
        sw << line;
        for (uint64_t p : per) sw << ',' << p;
        sw << '\n';
      }
      std::fprintf(stderr, "unit_compare: sweep box area %.0f done\n", area);
    }
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "unit_compare: %s\n", ex.what());
    return 1;
  }
  return 0;
}
