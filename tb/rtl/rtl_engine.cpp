// The transactor between the engine interface and the Verilated trirast_top (docs/rtl.md).
//
// Cycle c (docs/timing.md, "Cycles and handshakes"): with clk_i low the inputs of cycle c are
// applied (the triangle on the port, span_ready_i = pattern.ready(c)) and the model is evaluated,
// so the handshakes and the observation outputs of cycle c can be sampled; then the rising edge
// c is evaluated. Cycle 0 is the first rising edge after rst_ni went high.
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

// Per-triangle progress, by setup position.
struct TriState {
  bool accepted = false;
  bool walked = false;  // its last group went (or it retired)
  bool done = false;
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
  const SinkPattern sink = SinkPattern::parse(cfg.sink_stall);
  const std::vector<TriangleSetup>& tris = setup.tris;
  const size_t n = tris.size();

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

  out.cycles.assign(n, TriangleCycles{});
  for (size_t p = 0; p < n; ++p) out.cycles[p].tri = tris[p].index;
  std::vector<TriState> st(n);

  // ---- the model ----
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->randReset(2);  // --x-initial unique: random initial values from the seed below
  ctx->randSeed(int(opt.x_seed));
  const bool tracing = !cfg.trace_path.empty();
  if (tracing) ctx->traceEverOn(true);
  auto top = std::make_unique<Vtrirast_top>(ctx.get(), "trirast_top");
  std::unique_ptr<VerilatedFstC> fst;
  std::string fst_path;
  if (tracing) {
    fst = std::make_unique<VerilatedFstC>();
    top->trace(fst.get(), 99);
    fst_path = fst_recording_path(cfg.trace_path);
  }
  // The trace window: setup positions of triangles trace_first..trace_last (scene indices).
  size_t win_a = n, win_b = 0;
  for (size_t p = 0; p < n; ++p) {
    const int64_t idx = tris[p].index;
    if (idx >= cfg.trace_first && (cfg.trace_last < 0 || idx <= cfg.trace_last)) {
      win_a = std::min(win_a, p);
      win_b = std::max(win_b, p);
    }
  }
  bool trace_open = false, trace_over = false;

  // ---- configuration and reset ----
  top->cfg_vp_xmax_i = uint32_t(cfg.width - 1);
  top->cfg_vp_ymax_i = uint32_t(cfg.height - 1);
  top->cfg_divide_i = cfg.boundary == BoundaryMode::Divide;
  top->cfg_adaptive_i = cfg.divider == DividerMode::Adaptive;
  top->cfg_endpoints_i = uint32_t(cfg.endpoints);
  top->cfg_fifo_depth_i = uint32_t(cfg.fifo_depth);
  top->tri_valid_i = 0;
  top->span_ready_i = 0;
  top->clk_i = 0;
  top->rst_ni = 1;
  top->eval();
  top->rst_ni = 0;
  top->eval();
  for (int i = 0; i < 2; ++i) {
    top->clk_i = 1;
    top->eval();
    top->clk_i = 0;
    top->eval();
  }
  top->rst_ni = 1;
  top->eval();

  // Puts triangle p on the port.
  auto offer = [&](size_t p) {
    if (p >= n) {
      top->tri_valid_i = 0;
      return;
    }
    const TriangleSetup& t = tris[p];
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
    top->tri_valid_i = 1;
    top->tri_tag_i = uint32_t(p);
    drive(top->tri_vx_i, vx, words(3 * kVertexBits));
    drive(top->tri_vy_i, vy, words(3 * kVertexBits));
    drive(top->tri_a_i, a, words(3 * kCoefBits));
    drive(top->tri_b_i, b, words(3 * kCoefBits));
    drive(top->tri_c_i, c, words(3 * kEdgeBits));
    top->tri_bias_i = bias;
  };

  size_t next = 0;  // the triangle on the port
  offer(next);
  uint64_t stalls = 0, last_progress = 0;
  const uint64_t watchdog = uint64_t(1) << 22;  // cycles without any handshake or retirement
  uint64_t c = 0;
  for (;; ++c) {
    top->span_ready_i = sink.ready(c);
    top->eval();
    // Stop once every triangle went in and the unit is empty (cycle c is not part of the run).
    if (next == n && top->tri_ready_o && !top->walk_busy_o && !top->span_valid_o) break;

    // Trace window: from the cycle the first triangle is on the port to the cycle after the last
    // one is done.
    if (tracing && !trace_open && !trace_over && next >= win_a && win_a < n) {
      fst->open(fst_path.c_str());
      trace_open = true;
    }

    bool progress = false;
    const bool accept = top->tri_valid_i && top->tri_ready_o;
    if (accept) {
      out.cycles[next].accept_cycle = c;
      st[next].accepted = true;
      progress = true;
    }
    if (top->box_retire_o) {
      const size_t p = top->box_retire_tag_o;
      out.cycles[p].first_span_cycle = out.cycles[p].done_cycle = c;
      st[p].walked = st[p].done = true;
      progress = true;
    }
    if (top->walk_stall_o) {
      ++out.cycles[top->walk_tag_o].stall_cycles;
      ++stalls;
    }
    if (top->walk_last_o) {
      const size_t p = top->walk_tag_o;
      st[p].walked = true;
      if (top->walk_retire_o) {
        out.cycles[p].first_span_cycle = out.cycles[p].done_cycle = c;
        st[p].done = true;
      }
      progress = true;
    }
    if (top->span_valid_o && top->span_ready_i) {
      const size_t p = top->span_tag_o;
      if (p >= n) throw std::logic_error("rtl: span with an unknown tag " + std::to_string(p));
      TriangleCycles& tc = out.cycles[p];
      if (tc.spans == 0) tc.first_span_cycle = c;
      tc.done_cycle = c;
      ++tc.spans;
      const Span s{tris[p].index, int32_t(top->span_y_o), int32_t(top->span_x_begin_o),
                   int32_t(top->span_x_end_o)};
      tc.pixels += uint64_t(s.pixels());
      out.spans.push_back(s);
      progress = true;
    }
    if (progress) last_progress = c;
    if (c - last_progress > watchdog)
      throw std::runtime_error("rtl: no handshake for " + std::to_string(watchdog) +
                               " cycles at cycle " + std::to_string(c) +
                               " (does --sink-stall ever let spans out?)");

    // Rising edge c.
    if (trace_open) fst->dump(2 * c);
    top->clk_i = 1;
    top->eval();
    if (trace_open) fst->dump(2 * c + 1);
    top->clk_i = 0;
    if (accept) offer(++next);

    // The window's last triangle is done when it went through the walk stage (or retired) and
    // its spans left the FIFO (in order: the head is a later triangle's, or the FIFO is empty).
    if (trace_open && win_b < n && st[win_b].walked) {
      top->eval();
      const bool drained = !top->span_valid_o || top->span_tag_o > win_b;
      if (st[win_b].done || drained) {
        fst->dump(2 * c + 2);
        fst->close();
        trace_open = false;
        trace_over = true;
      }
    }
  }
  if (trace_open) {
    fst->dump(2 * c);
    fst->close();
  }
  if (tracing && !trace_over && !trace_open && win_a >= n) {
    fst->open(fst_path.c_str());  // an empty window: a trace with the signals and no cycles
    fst->close();
  }
  top->final();
  if (tracing) finish_trace(fst_path, cfg.trace_path, "rtl");

  uint64_t total = 0, spans = 0, pixels = 0;
  for (const TriangleCycles& tc : out.cycles) {
    total = std::max(total, tc.done_cycle + 1);
    spans += tc.spans;
    pixels += tc.pixels;
  }
  out.total_cycles = n ? total : 0;
  out.work["triangles"] += n;
  out.work["spans"] += spans;
  out.work["pixels"] += pixels;
  out.work["walk_stall_cycles"] += stalls;
  out.work["rtl_x_seed"] = opt.x_seed;
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
