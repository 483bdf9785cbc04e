// Writes the vectors of the Icarus testbench (tb/icarus/tb_trirast.sv): the set-up triangles of a
// scene, and the spans with their pop cycles and the accept cycles that the Verilated model
// produces for them at the default hardware (N = 1, DEPTH = 8) with a periodic sink.
//   trirast_rtl_vectors SCENE OUTDIR READY STALL [halfspace[:STAMP:TILE:WALK] | improved2:FORM]
// READY and STALL are cycle counts: --sink-stall periodic:READY:STALL, the fixed pattern
// tb_trirast.sv drives from +ready/+stall. A downstream that reacts to the spans it takes
// (--sink-stall queue:RATE:CAPACITY) cannot be replayed there and is refused.
// (the half-space unit's vectors from the halfspace-rtl engine, at --stamp STAMP --tile TILE
// (0: none) --hs-walk WALK (row | zigzag); default 2:8:zigzag, trirast_halfspace_top's defaults; the
// second-generation unit's from the improved2-rtl engine in corner form FORM, 1 radix 16, 0
// products)
// OUTDIR gets tris.hex, spans.hex, accept.hex, done.hex and plusargs.txt.
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <iostream>
#include <string>

#include "common/setup.hpp"
#include "improved/improved_rtl_engine.hpp"
#include "halfspace/halfspace_rtl_engine.hpp"
#include "improved2/improved2_rtl_engine.hpp"
#include "scene/scene.hpp"
#include "common/trirast_rtl_params.hpp"

using namespace trirast;

namespace {

// Hex of a little-endian bit vector of `bits` bits (MSB first, as $readmemh reads it).
struct HexBits {
  std::string bitsv;  // bit i at index i
  void put(int width, int64_t v) {
    for (int b = 0; b < width; ++b) bitsv.push_back(((uint64_t(v) >> (b < 64 ? b : 63)) & 1) ? '1' : '0');
  }
  std::string hex() const {
    std::string out;
    const int n = int(bitsv.size());
    const int digits = (n + 3) / 4;
    for (int d = digits - 1; d >= 0; --d) {
      int v = 0;
      for (int b = 3; b >= 0; --b) {
        const int i = d * 4 + b;
        v = v * 2 + (i < n && bitsv[size_t(i)] == '1' ? 1 : 0);
      }
      out.push_back("0123456789abcdef"[v]);
    }
    return out;
  }
};

}  // namespace

int main(int argc, char** argv) {
  const std::string unit = argc == 6 ? argv[5] : "";
  const bool halfspace = unit.rfind("halfspace", 0) == 0, improved2 = unit.rfind("improved2:", 0) == 0;
  if (argc != 5 && !(argc == 6 && (halfspace || improved2))) {
    std::cerr << "usage: trirast_rtl_vectors SCENE OUTDIR READY STALL [halfspace[:STAMP:TILE:WALK] | "
                 "improved2:FORM]\n";
    return 2;
  }
  try {
    const std::string spec = argv[1], dir = argv[2];
    for (const std::string arg : {argv[3], argv[4]}) {
      if (arg.rfind("queue:", 0) == 0)
        throw std::invalid_argument(
            "READY STALL: '" + arg + "': the Icarus bench drives a fixed periodic sink "
            "(--sink-stall periodic:READY:STALL); --sink-stall queue:RATE:CAPACITY, a downstream "
            "that reacts to the spans it takes, is not supported there");
      if (arg.empty() || arg.find_first_not_of("0123456789") != std::string::npos)
        throw std::invalid_argument("READY STALL: '" + arg + "' is not a cycle count (the Icarus "
                                    "bench drives --sink-stall periodic:READY:STALL)");
    }
    const int ready = std::stoi(argv[3]), stall = std::stoi(argv[4]);
    RasterConfig cfg;
    cfg.width = 256;
    cfg.height = 192;
    cfg.endpoints = 1;
    cfg.fifo_depth = 8;
    cfg.sink_stall = "periodic:" + std::to_string(ready) + ":" + std::to_string(stall);
    if (improved2) {  // improved2:FORM
      const std::string form = unit.substr(10);
      if (form != "0" && form != "1")
        throw std::invalid_argument("improved2:FORM: '" + unit + "': FORM is 0 or 1");
      cfg.improved2.corner_form = std::stoi(form);
    } else if (unit.size() > 9) {  // halfspace:STAMP:TILE:WALK
      std::istringstream in(unit.substr(10));
      std::string stamp, tile, walk;
      if (unit[9] != ':' || !std::getline(in, stamp, ':') || !std::getline(in, tile, ':') ||
          !std::getline(in, walk))
        throw std::invalid_argument("halfspace[:STAMP:TILE:WALK]: '" + unit + "' is malformed");
      cfg.halfspace.stamp = std::stoi(stamp);
      cfg.halfspace.tile = std::stoi(tile);
      cfg.halfspace.walk = parse_halfspace_walk(walk);
    }
    cfg.validate();
    const Scene scene = spec.rfind("builtin:", 0) == 0
                            ? make_builtin(spec.substr(8), cfg, CameraOptions{})
                            : read_tri_file(spec);
    const SetupResult setup = setup_scene(scene.tris, cfg);
    EngineResult res;
    if (improved2)
      rtl::run_rtl_improved2(setup, cfg, rtl::RtlRunOptions{}, res);
    else if (halfspace)  // the half-space unit at the build parameters above
      rtl::run_rtl_halfspace(setup, cfg, 1, res);
    else
      rtl::run_rtl(setup, cfg, rtl::RtlRunOptions{}, res);

    std::ofstream tris(dir + "/tris.hex"), spans(dir + "/spans.hex"), acc(dir + "/accept.hex"),
        args(dir + "/plusargs.txt");
    for (size_t p = 0; p < setup.tris.size(); ++p) {
      const TriangleSetup& t = setup.tris[p];
      // {bias, c, b, a, vy, vx, tag}, tag in the low bits.
      HexBits h;
      h.put(rtl::kTagBits, int64_t(p));
      for (int k = 0; k < 3; ++k) h.put(rtl::kVertexBits, t.v[k].x);
      for (int k = 0; k < 3; ++k) h.put(rtl::kVertexBits, t.v[k].y);
      for (int k = 0; k < 3; ++k) h.put(rtl::kCoefBits, t.edge[k].A);
      for (int k = 0; k < 3; ++k) h.put(rtl::kCoefBits, t.edge[k].B);
      for (int k = 0; k < 3; ++k) h.put(rtl::kEdgeBits, t.edge[k].C);
      for (int k = 0; k < 3; ++k) h.put(1, t.edge[k].bias != 0);
      tris << h.hex() << "\n";
      HexBits a;
      a.put(32, int64_t(res.cycles[p].accept_cycle));
      acc << a.hex() << "\n";
    }
    // Per triangle: first_span_cycle and done_cycle.
    std::ofstream done_f(dir + "/done.hex");
    for (const TriangleCycles& tc : res.cycles) {
      HexBits h;
      h.put(32, int64_t(tc.done_cycle));
      h.put(32, int64_t(tc.first_span_cycle));
      done_f << h.hex() << "\n";
    }
    // Spans in pop order (the engine appends them as they are popped), tagged by setup position.
    std::map<uint32_t, size_t> pos_of;
    for (size_t p = 0; p < setup.tris.size(); ++p) pos_of[setup.tris[p].index] = p;
    for (const Span& s : res.spans) {
      HexBits h;
      h.put(rtl::kPixBits + 1, s.x_end);
      h.put(rtl::kPixBits, s.x_begin);
      h.put(rtl::kPixBits, s.y);
      h.put(rtl::kTagBits, int64_t(pos_of.at(s.tri)));
      spans << h.hex() << "\n";
    }
    uint64_t done = 0;
    for (const TriangleCycles& tc : res.cycles) done = std::max(done, tc.done_cycle);
    args << "+ntris=" << setup.tris.size() << " +nspans=" << res.spans.size()
         << " +vpx=" << cfg.width - 1 << " +vpy=" << cfg.height - 1 << " +ready=" << ready
         << " +stall=" << stall << " +last=" << done << "\n";
    std::cout << "vectors: " << setup.tris.size() << " triangles, " << res.spans.size()
              << " spans, last pop in cycle " << done << "\n";
  } catch (const std::exception& e) {
    std::cerr << "trirast_rtl_vectors: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
