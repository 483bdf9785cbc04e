// Pieces shared by the Verilator harnesses (rtl_engine.cpp, rtl_trad_engine.cpp): wide-port
// packing and the FST -> VCD conversion of a trace.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "common/engine.hpp"
#include "common/setup.hpp"
#include "common/span.hpp"
#include "common/unit_widths.hpp"
#include "common/temporary_files.hpp"

namespace trirast {
namespace rtl {

constexpr int words(int bits) { return (bits + 31) / 32; }

// Set bits of a 3-bit lane mask (no popcount instruction is assumed).
constexpr unsigned ones3(unsigned v) { return (v & 1u) + ((v >> 1) & 1u) + ((v >> 2) & 1u); }

// A little-endian bit buffer of Words 32-bit words for the wide ports.
template <int Words>
struct Bits {
  uint32_t w[Words] = {};
  // Writes the low `width` bits of v (sign-extended beyond 64) at bit lsb, a word at a time.
  void put(int lsb, int width, int64_t v) {
    int b = 0;
    while (b < width) {
      const int pos = lsb + b, word = pos / 32, shift = pos % 32;
      const int n = std::min(width - b, 32 - shift);
      const uint64_t chunk = b < 64 ? uint64_t(v) >> b | (b > 0 && v < 0 ? ~uint64_t(0) << (64 - b) : 0)
                                    : (v < 0 ? ~uint64_t(0) : 0);
      const uint32_t mask = (n == 32 ? ~0u : ((1u << n) - 1u)) << shift;
      w[word] = (w[word] & ~mask) | ((uint32_t(chunk) << shift) & mask);
      b += n;
    }
  }
};

// A port of up to 64 bits is a scalar in the Verilated model (narrow configurations), a wider
// one an array of 32-bit words.
template <class Port, int Words>
void drive(Port& port, const Bits<Words>& b, int n_words) {
  if constexpr (std::is_integral_v<Port>) {
    uint64_t v = b.w[0];
    if (n_words > 1) v |= uint64_t(b.w[1]) << 32;
    port = Port(v);
  } else {
    for (int i = 0; i < n_words; ++i) port[i] = b.w[i];
  }
}

// The triangle ports of a unit that takes the set-up's edge functions (trirast_improved_top,
// trirast_halfspace_top): packed vertices, A, B, C and the bias bits, at the widths P of its build.
template <class P, class Top>
void drive_edge_triangle(Top& top, const TriangleSetup& t) {
  static_assert(words(3 * P::kEdgeBits) <= 8, "Bits<8> holds up to 256 bits");
  Bits<8> vx, vy, a, b, c;
  uint32_t bias = 0;
  for (int k = 0; k < 3; ++k) {
    vx.put(k * P::kVertexBits, P::kVertexBits, t.v[k].x);
    vy.put(k * P::kVertexBits, P::kVertexBits, t.v[k].y);
    a.put(k * P::kCoefBits, P::kCoefBits, t.edge[k].A);
    b.put(k * P::kCoefBits, P::kCoefBits, t.edge[k].B);
    c.put(k * P::kEdgeBits, P::kEdgeBits, t.edge[k].C);
    if (t.edge[k].bias != 0) bias |= 1u << k;
  }
  drive(top.tri_vx_i, vx, words(3 * P::kVertexBits));
  drive(top.tri_vy_i, vy, words(3 * P::kVertexBits));
  drive(top.tri_a_i, a, words(3 * P::kCoefBits));
  drive(top.tri_b_i, b, words(3 * P::kCoefBits));
  drive(top.tri_c_i, c, words(3 * P::kEdgeBits));
  top.tri_bias_i = bias;
}

// The ports of a unit whose box stage comes first and may retire a triangle (trirast_improved_top,
// trirast_halfspace_top), as the cycle loop (cycle_loop.hpp) reads them: the triangle port at
// the widths P, the box the walk stage takes at the hand-off, and a box that clips to nothing
// retiring in the box stage.
template <class Top, class P>
struct BoxStagePorts {
  void offer(Top& top, const TriangleSetup& t) const { drive_edge_triangle<P>(top, t); }
  void observe_handoff(const Top& top, TriangleCycles& tc) const {
    tc.box_width = uint64_t(top.box_xmax_o) + 1;
    tc.box_height = uint64_t(top.box_ymax_o) + 1;
  }
  bool early_retire(const Top& top, size_t& tag) const {
    if (!top.box_retire_o) return false;
    tag = top.box_retire_tag_o;
    return true;
  }
};

// Before a run of a unit with edge-function ports: runs its bit-accurate model Unit on every
// triangle, so that one the widths P do not hold raises the model's WidthError naming it (the RTL
// assumes fitting inputs), and checks each edge's C against the port.
// Output is what Unit::run_triangle writes (the first generation's spans; the second's triangle
// record, which it reuses between calls).
template <class Unit, class P, class Output = SpanList>
void check_widths(const SetupResult& setup, const RasterConfig& cfg) {
  Unit unit(cfg);
  Output scratch;
  for (const TriangleSetup& t : setup.tris) {
    if constexpr (std::is_same_v<Output, SpanList>) scratch.clear();
    unit.run_triangle(t, scratch);
    for (int k = 0; k < 3; ++k) check_signed(t.edge[k].C, P::kEdgeBits, t.index, "C", "edge value");
  }
}

inline bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The harnesses record FST to FILE.tmp.fst (and fstapi's FILE.tmp.fst.hier / .pak beside it),
// registered as temporaries (core/temporary_files.hpp): removed on failure and on SIGINT /
// SIGTERM. finish_trace() renames the recording to a .fst trace or converts it to a .vcd one.
inline std::string fst_recording_path(const std::string& trace_path) {
  return trace_path + ".tmp.fst";
}

// The temporaries of one recording, registered while it is written.
struct RecordingTemporaries {
  TemporaryPath fst, hier, pak;
  void track(const std::string& fst_path) {
    fst.reset(fst_path);
    hier.reset(fst_path + ".hier");
    pak.reset(fst_path + ".pak");
  }
};

// Renames the recording to the requested FST, or converts it to the requested VCD (through a
// temporary name) and removes it.
inline void finish_trace(const std::string& fst_path, const std::string& trace_path,
                         const char* engine) {
  if (!ends_with(trace_path, ".vcd")) {
    if (std::rename(fst_path.c_str(), trace_path.c_str()) != 0)
      throw std::runtime_error("--trace " + trace_path + ": cannot rename the recording");
    return;
  }
  const std::string vcd_tmp = trace_path + ".tmp.vcd";
  TemporaryPath vcd_guard(vcd_tmp);
  const std::string cmd = "fst2vcd -f '" + fst_path + "' -o '" + vcd_tmp + "' >/dev/null";
  const int rc = std::system(cmd.c_str());
  std::remove(fst_path.c_str());
  if (rc != 0 || std::rename(vcd_tmp.c_str(), trace_path.c_str()) != 0)
    throw std::runtime_error("--trace " + trace_path + ": fst2vcd failed (the " +
                             std::string(engine) + " engine records FST and converts)");
  vcd_guard.release();
}

}  // namespace rtl
}  // namespace trirast
