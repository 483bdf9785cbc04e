// The transactor between the engine interface and the Verilated trirast_trad_top (docs/rtl.md,
// "The traditional unit's RTL"): the traditional unit's configuration and triangle ports; the
// per-cycle loop (cycle sampling, trace window, counters) is cycle_loop.hpp, shared with the
// improved unit's harness.
#include "rtl_trad_engine.hpp"

#include <verilated.h>
#include <verilated_fst_c.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "Vtrirast_trad_top.h"
#include "core/sink_pattern.hpp"
#include "cycle_loop.hpp"
#include "harness_util.hpp"
#include "trirast_rtl_params.hpp"
#include "unit/unit_widths.hpp"

namespace trirast {
namespace rtl {

namespace {

// The FIFO depth the model was verilated with (rtl/CMakeLists.txt -GFifoDepth=...).
#ifndef TRIRAST_RTL_FIFO_DEPTH
#define TRIRAST_RTL_FIFO_DEPTH 1024
#endif
constexpr int kHwFifoDepth = TRIRAST_RTL_FIFO_DEPTH;

using PortBits = Bits<4>;  // up to 128-bit ports
static_assert(words(3 * kVertexBits) <= 4, "Bits holds up to 128 bits");

std::string trad_configuration() {
  return "--subpixel-bits " + std::to_string(kSubpixelBits) + " --coord-bits " +
         std::to_string(kCoordIntBits) + ", --fifo-depth up to " + std::to_string(kHwFifoDepth);
}

void check_config(const RasterConfig& cfg) {
  auto need = [](bool ok, const std::string& opt, int got, int built, const char* how) {
    if (!ok)
      throw std::invalid_argument(opt + ": " + std::to_string(got) +
                                  " is not covered by the rtl-trad engine's Verilated model (" +
                                  how + " " + std::to_string(built) + "; built configuration: " +
                                  trad_configuration() + "; build another with scripts/gen_params.py)");
  };
  need(cfg.subpixel_bits == kSubpixelBits, "--subpixel-bits", cfg.subpixel_bits, kSubpixelBits,
       "built for");
  need(cfg.coord_int_bits == kCoordIntBits, "--coord-bits", cfg.coord_int_bits, kCoordIntBits,
       "built for");
  need(cfg.fifo_depth >= 1 && cfg.fifo_depth <= kHwFifoDepth, "--fifo-depth", cfg.fifo_depth,
       kHwFifoDepth, "at most");
}

// The traditional unit's own ports for the cycle loop (cycle_loop.hpp).
struct TradPorts {
  void configure(Vtrirast_trad_top&, const RasterConfig&) const {}  // viewport and FIFO only
  void offer(Vtrirast_trad_top& top, const TriangleSetup& t) const {
    PortBits vx, vy;
    for (int k = 0; k < 3; ++k) {
      vx.put(k * kVertexBits, kVertexBits, t.v[k].x);
      vy.put(k * kVertexBits, kVertexBits, t.v[k].y);
    }
    drive(top.tri_vx_i, vx, words(3 * kVertexBits));
    drive(top.tri_vy_i, vy, words(3 * kVertexBits));
  }
  // A collinear triangle retires in the setup stage.
  bool early_retire(const Vtrirast_trad_top& top, size_t& tag) const {
    if (!top.setup_retire_o) return false;
    tag = top.setup_retire_tag_o;
    return true;
  }
};

}  // namespace

void run_rtl_trad(const SetupResult& setup, const RasterConfig& cfg, const RtlRunOptions& opt,
                  EngineResult& out) {
  check_config(cfg);
  (void)SinkPattern::parse(cfg.sink_stall);  // a bad pattern fails before anything runs
  const std::vector<TriangleSetup>& tris = setup.tris;

  // The RTL assumes its inputs fit its widths: the vertices are the only input.
  for (const TriangleSetup& t : tris)
    for (int k = 0; k < 3; ++k) {
      check_signed(t.v[k].x, kVertexBits, t.index, "x", "vertex coordinate");
      check_signed(t.v[k].y, kVertexBits, t.index, "y", "vertex coordinate");
    }

  TradPorts ports;
  const CycleCounts counts = run_cycles<Vtrirast_trad_top>(setup, cfg, opt.x_seed, "trad-rtl",
                                                           "trirast_trad_top", ports, out);
  out.work["trad_collinear"] += counts.early_retirements;
}

}  // namespace rtl

namespace {

class RtlTradEngine : public Engine {
 public:
  void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) override {
    rtl::RtlRunOptions opt;
    if (const char* s = std::getenv("TRIRAST_RTL_SEED")) opt.x_seed = uint32_t(std::strtoul(s, nullptr, 0));
    rtl::run_rtl_trad(setup, cfg, opt, out);
  }
};

}  // namespace

std::unique_ptr<Engine> make_rtl_trad_engine() { return std::make_unique<RtlTradEngine>(); }

}  // namespace trirast
