// The transactor between the engine interface and the Verilated trirast_top (docs/rtl.md): the
// improved unit's configuration and triangle ports; the per-cycle loop (cycle sampling, trace
// window, counters) is cycle_loop.hpp, shared with the traditional unit's harness.
#include "rtl_engine.hpp"

#include <verilated.h>
#include <verilated_fst_c.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "Vtrirast_top.h"
#include "core/sink_pattern.hpp"
#include "cycle_loop.hpp"
#include "harness_util.hpp"
#include "trirast_rtl_params.hpp"
#include "unit/improved_unit.hpp"

namespace trirast {
namespace rtl {

namespace {

// The hardware maximums the model was verilated with (rtl/CMakeLists.txt -G...).
#ifndef TRIRAST_RTL_ENDPOINTS
#define TRIRAST_RTL_ENDPOINTS 4
#endif
#ifndef TRIRAST_RTL_FIFO_DEPTH
#define TRIRAST_RTL_FIFO_DEPTH 1024
#endif
constexpr int kHwEndpoints = TRIRAST_RTL_ENDPOINTS;
constexpr int kHwFifoDepth = TRIRAST_RTL_FIFO_DEPTH;

using PortBits = Bits<8>;  // up to 256-bit ports

void check_config(const RasterConfig& cfg) {
  auto need = [](bool ok, const std::string& opt, int got, int built, const char* how) {
    if (!ok)
      throw std::invalid_argument(opt + ": " + std::to_string(got) +
                                  " is not covered by the rtl engine's Verilated model (" + how +
                                  " " + std::to_string(built) + "; built configuration: " +
                                  built_configuration() +
                                  "; build another with scripts/gen_params.py)");
  };
  need(cfg.subpixel_bits == kSubpixelBits, "--subpixel-bits", cfg.subpixel_bits, kSubpixelBits,
       "built for");
  need(cfg.coord_int_bits == kCoordIntBits, "--coord-bits", cfg.coord_int_bits, kCoordIntBits,
       "built for");
  need(cfg.box_bits == kBoxBits, "--box-bits", cfg.box_bits, kBoxBits, "built for");
  need(cfg.endpoints >= 1 && cfg.endpoints <= kHwEndpoints, "--endpoints", cfg.endpoints,
       kHwEndpoints, "at most");
  need(cfg.fifo_depth >= cfg.endpoints && cfg.fifo_depth <= kHwFifoDepth, "--fifo-depth",
       cfg.fifo_depth, kHwFifoDepth, "at most");
  // The sweep's quotient truncation (RasterConfig::divider_quotient_bits, K): the RTL's divider
  // always runs the exact Q (or adaptive) iterations; it has no truncation.
  if (cfg.divider_quotient_bits != 0)
    throw std::invalid_argument(
        "divider_quotient_bits: " + std::to_string(cfg.divider_quotient_bits) +
        " is not covered by the rtl engine (the RTL has no quotient truncation; only 0, the exact "
        "divider, is)");
}

// The improved unit's own ports for the cycle loop (cycle_loop.hpp).
struct ImprovedPorts {
  void configure(Vtrirast_top& top, const RasterConfig& cfg) const {
    top.cfg_divide_i = cfg.boundary == BoundaryMode::Divide;
    top.cfg_adaptive_i = cfg.divider == DividerMode::Adaptive;
    top.cfg_endpoints_i = uint32_t(cfg.endpoints);
  }
  void offer(Vtrirast_top& top, const TriangleSetup& t) const {
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
  // A box that clips to nothing retires in the box stage.
  bool early_retire(const Vtrirast_top& top, size_t& tag) const {
    if (!top.box_retire_o) return false;
    tag = top.box_retire_tag_o;
    return true;
  }
};

}  // namespace

std::string built_configuration() {
  return "--subpixel-bits " + std::to_string(kSubpixelBits) + " --coord-bits " +
         std::to_string(kCoordIntBits) + " --box-bits " + std::to_string(kBoxBits) +
         ", --endpoints 1.." + std::to_string(kHwEndpoints) + ", --fifo-depth up to " +
         std::to_string(kHwFifoDepth);
}

void run_rtl(const SetupResult& setup, const RasterConfig& cfg, const RtlRunOptions& opt,
             EngineResult& out) {
  check_config(cfg);
  (void)SinkPattern::parse(cfg.sink_stall);  // a bad pattern fails before the width check's run
  const std::vector<TriangleSetup>& tris = setup.tris;

  // The RTL assumes its inputs fit its widths: check every triangle with the bit-accurate model
  // first, so an overflowing triangle raises the model's WidthError naming it.
  {
    ImprovedUnit unit(cfg);
    SpanList scratch;
    for (const TriangleSetup& t : tris) {
      scratch.clear();
      unit.run_triangle(t, scratch);
      for (int k = 0; k < 3; ++k) check_signed(t.edge[k].C, kEdgeBits, t.index, "C", "edge value");
    }
  }

  ImprovedPorts ports;
  run_cycles<Vtrirast_top>(setup, cfg, opt.x_seed, "improved-rtl", "trirast_top", ports, out);
}

}  // namespace rtl

namespace {

class RtlEngine : public Engine {
 public:
  void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) override {
    rtl::RtlRunOptions opt;
    if (const char* s = std::getenv("TRIRAST_RTL_SEED")) opt.x_seed = uint32_t(std::strtoul(s, nullptr, 0));
    rtl::run_rtl(setup, cfg, opt, out);
  }
};

}  // namespace

std::unique_ptr<Engine> make_rtl_engine() { return std::make_unique<RtlEngine>(); }

}  // namespace trirast
