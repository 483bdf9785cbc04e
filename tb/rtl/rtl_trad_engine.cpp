// The transactor between the engine interface and the Verilated trirast_trad_top (docs/rtl.md,
// "The traditional unit's RTL"). Cycle sampling as in rtl_engine.cpp: in cycle c, with clk_i low,
// the inputs of cycle c are applied (the triangle on the port, span_ready_i = pattern.ready(c))
// and the model is evaluated, so the handshakes and the observation outputs of cycle c are
// sampled; then the rising edge c is evaluated. Cycle 0 is the first rising edge after reset.
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

struct TriState {
  bool walked = false;  // its last row ended (or it retired in setup)
  bool done = false;
};

}  // namespace

void run_rtl_trad(const SetupResult& setup, const RasterConfig& cfg, const RtlRunOptions& opt,
                  EngineResult& out) {
  check_config(cfg);
  const SinkPattern sink = SinkPattern::parse(cfg.sink_stall);
  const std::vector<TriangleSetup>& tris = setup.tris;
  const size_t n = tris.size();

  // The RTL assumes its inputs fit its widths: the vertices are the only input.
  for (const TriangleSetup& t : tris)
    for (int k = 0; k < 3; ++k) {
      check_signed(t.v[k].x, kVertexBits, t.index, "x", "vertex coordinate");
      check_signed(t.v[k].y, kVertexBits, t.index, "y", "vertex coordinate");
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
  auto top = std::make_unique<Vtrirast_trad_top>(ctx.get(), "trirast_trad_top");
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
    PortBits vx, vy;
    for (int k = 0; k < 3; ++k) {
      vx.put(k * kVertexBits, kVertexBits, t.v[k].x);
      vy.put(k * kVertexBits, kVertexBits, t.v[k].y);
    }
    top->tri_valid_i = 1;
    top->tri_tag_i = uint32_t(p);
    drive(top->tri_vx_i, vx, words(3 * kVertexBits));
    drive(top->tri_vy_i, vy, words(3 * kVertexBits));
  };

  size_t next = 0;  // the triangle on the port
  offer(next);
  uint64_t stalls = 0, collinear = 0, last_progress = 0;
  // Cycles without a handshake, a retirement or a triangle's last row. A triangle walks at most
  // 2^c rows and 3 * 2^c steps (c = CoordIntBits), so well under 2^22 cycles; its stalls wait for
  // pops, which are handshakes. A walk stage that never ends its triangle trips this.
  const uint64_t watchdog = uint64_t(1) << 22;
  uint64_t c = 0;
  for (;; ++c) {
    top->span_ready_i = sink.ready(c);
    top->eval();
    // Stop once every triangle went in and the unit is empty (cycle c is not part of the run).
    if (next == n && top->tri_ready_o && !top->walk_busy_o && !top->span_valid_o) break;

    if (tracing && !trace_open && !trace_over && next >= win_a && win_a < n) {
      fst->open(fst_path.c_str());
      trace_open = true;
    }

    bool progress = false;
    const bool accept = top->tri_valid_i && top->tri_ready_o;
    if (accept) {
      out.cycles[next].accept_cycle = c;
      progress = true;
    }
    if (top->setup_retire_o) {
      const size_t p = top->setup_retire_tag_o;
      if (p >= n) throw std::logic_error("rtl-trad: retirement of an unknown tag " + std::to_string(p));
      out.cycles[p].first_span_cycle = out.cycles[p].done_cycle = c;
      st[p].walked = st[p].done = true;
      ++collinear;
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
      if (p >= n) throw std::logic_error("rtl-trad: span with an unknown tag " + std::to_string(p));
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
      throw std::runtime_error("rtl-trad: no progress for " + std::to_string(watchdog) +
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
  if (tracing) finish_trace(fst_path, cfg.trace_path, "rtl-trad");

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
  out.work["trad_collinear"] += collinear;
  out.work["walk_stall_cycles"] += stalls;
  out.work["total_cycles"] = out.total_cycles;
  out.work["rtl_x_seed"] = opt.x_seed;
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
