// The transactor between the engine interface and the Verilated trirast_hs_top (one Verilated
// model per built configuration): the improved unit's triangle port, the per-cycle loop of
// cycle_loop.hpp (cycle sampling, trace window, counters) shared with the other units.
#include "rtl_hs_engine.hpp"

#include <verilated.h>
#include <verilated_fst_c.h>

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "Vtrirast_hs_s1t0z.h"
#include "Vtrirast_hs_s2t8z.h"
#include "Vtrirast_hs_s4t16r.h"
#include "core/sink_pattern.hpp"
#include "cycle_loop.hpp"
#include "harness_util.hpp"
#include "rtl_engine.hpp"
#include "trirast_rtl_params.hpp"
#include "unit/halfspace_unit.hpp"
#include "unit/unit_widths.hpp"

namespace trirast {
namespace rtl {

namespace {

#ifndef TRIRAST_RTL_FIFO_DEPTH
#define TRIRAST_RTL_FIFO_DEPTH 1024
#endif
constexpr int kHwFifoDepth = TRIRAST_RTL_FIFO_DEPTH;

using PortBits = Bits<8>;

struct Built {
  int stamp, tile;
  HsWalk walk;
};
// Keep in step with dv/verilator/CMakeLists.txt's verilate() calls.
constexpr Built kBuilt[] = {{2, 8, HsWalk::Zigzag}, {4, 16, HsWalk::Row}, {1, 0, HsWalk::Zigzag}};

std::string describe(const Built& b) {
  return "--stamp " + std::to_string(b.stamp) + " --tile " +
         (b.tile ? std::to_string(b.tile) : std::string("none")) + " --hs-walk " +
         hs_walk_name(b.walk);
}

// The improved unit's triangle port (trirast_hs_top has the same).
struct HsPorts {
  template <class Top>
  void configure(Top&, const RasterConfig&) const {}
  template <class Top>
  void offer(Top& top, const TriangleSetup& t) const {
    PortBits vx, vy, a, b, c;
    uint32_t bias = 0;
    for (int k = 0; k < 3; ++k) {
      vx.put(k * kVertexBits, kVertexBits, t.v[k].x);
      vy.put(k * kVertexBits, kVertexBits, t.v[k].y);
      a.put(k * kCoefBits, kCoefBits, t.edge[k].A);
      b.put(k * kCoefBits, kCoefBits, t.edge[k].B);
      c.put(k * kEdgeBits, kEdgeBits, t.edge[k].C);
      if (t.edge[k].bias != 0) bias |= 1u << k;
    }
    drive(top.tri_vx_i, vx, words(3 * kVertexBits));
    drive(top.tri_vy_i, vy, words(3 * kVertexBits));
    drive(top.tri_a_i, a, words(3 * kCoefBits));
    drive(top.tri_b_i, b, words(3 * kCoefBits));
    drive(top.tri_c_i, c, words(3 * kEdgeBits));
    top.tri_bias_i = bias;
  }
  template <class Top>
  bool early_retire(const Top& top, size_t& tag) const {
    if (!top.box_retire_o) return false;
    tag = top.box_retire_tag_o;
    return true;
  }
};

}  // namespace

std::string halfspace_built_configurations() {
  std::string s;
  for (const Built& b : kBuilt) s += (s.empty() ? "" : "; ") + describe(b);
  return s;
}

void run_rtl_halfspace(const SetupResult& setup, const RasterConfig& cfg, uint32_t x_seed,
                       EngineResult& out) {
  auto need = [](bool ok, const std::string& opt, int got, int built) {
    if (!ok)
      throw std::invalid_argument(opt + ": " + std::to_string(got) +
                                  " is not covered by the halfspace-rtl engine's Verilated models "
                                  "(built for " + std::to_string(built) + ")");
  };
  need(cfg.subpixel_bits == kSubpixelBits, "--subpixel-bits", cfg.subpixel_bits, kSubpixelBits);
  need(cfg.coord_int_bits == kCoordIntBits, "--coord-bits", cfg.coord_int_bits, kCoordIntBits);
  need(cfg.box_bits == kBoxBits, "--box-bits", cfg.box_bits, kBoxBits);
  need(cfg.fifo_depth >= 1 && cfg.fifo_depth <= kHwFifoDepth, "--fifo-depth", cfg.fifo_depth,
       kHwFifoDepth);
  (void)SinkPattern::parse(cfg.sink_stall);
  // The RTL assumes its values fit its widths: the bit-accurate model checks every triangle first.
  {
    HalfspaceUnit unit(cfg);
    SpanList scratch;
    for (const TriangleSetup& t : setup.tris) {
      scratch.clear();
      unit.run_triangle(t, scratch);
      for (int k = 0; k < 3; ++k) check_signed(t.edge[k].C, kEdgeBits, t.index, "C", "edge value");
    }
  }
  HsPorts ports;
  int which = -1;
  for (int i = 0; i < int(sizeof kBuilt / sizeof kBuilt[0]); ++i)
    if (kBuilt[i].stamp == cfg.hs_stamp && kBuilt[i].tile == cfg.hs_tile &&
        kBuilt[i].walk == cfg.hs_walk)
      which = i;
  CycleCounts counts;
  switch (which) {
    case 0:
      counts = run_cycles<Vtrirast_hs_s2t8z>(setup, cfg, x_seed, "halfspace-rtl", "trirast_hs_top",
                                             ports, out);
      break;
    case 1:
      counts = run_cycles<Vtrirast_hs_s4t16r>(setup, cfg, x_seed, "halfspace-rtl",
                                              "trirast_hs_top", ports, out);
      break;
    case 2:
      counts = run_cycles<Vtrirast_hs_s1t0z>(setup, cfg, x_seed, "halfspace-rtl", "trirast_hs_top",
                                             ports, out);
      break;
    default: {
      Built want{cfg.hs_stamp, cfg.hs_tile, cfg.hs_walk};
      throw std::invalid_argument("--stamp/--tile/--hs-walk: " + describe(want) +
                                  " is not covered by the halfspace-rtl engine's Verilated models "
                                  "(built: " + halfspace_built_configurations() +
                                  "; add a verilate() call in dv/verilator/CMakeLists.txt)");
    }
  }
  (void)counts;
}

}  // namespace rtl

namespace {

class RtlHalfspaceEngine : public Engine {
 public:
  void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) override {
    uint32_t seed = 1;
    if (const char* s = std::getenv("TRIRAST_RTL_SEED")) seed = uint32_t(std::strtoul(s, nullptr, 0));
    rtl::run_rtl_halfspace(setup, cfg, seed, out);
  }
};

}  // namespace

std::unique_ptr<Engine> make_rtl_halfspace_engine() { return std::make_unique<RtlHalfspaceEngine>(); }

}  // namespace trirast
