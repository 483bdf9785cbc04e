// Pieces shared by the Verilator harnesses (rtl_engine.cpp, rtl_trad_engine.cpp): wide-port
// packing and the FST -> VCD conversion of a trace.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace trirast {
namespace rtl {

constexpr int words(int bits) { return (bits + 31) / 32; }

// A little-endian bit buffer of Words 32-bit words for the wide ports.
template <int Words>
struct Bits {
  uint32_t w[Words] = {};
  void put(int lsb, int width, int64_t v) {
    const uint64_t u = uint64_t(v);
    for (int b = 0; b < width; ++b) {
      const int pos = lsb + b;
      const uint32_t bit = b < 64 ? uint32_t((u >> b) & 1u) : uint32_t(u >> 63);
      w[pos / 32] = (w[pos / 32] & ~(1u << (pos % 32))) | (bit << (pos % 32));
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

inline bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The harnesses record FST; a .vcd trace is recorded to FILE.vcd.tmp.fst and converted.
inline std::string fst_recording_path(const std::string& trace_path) {
  return ends_with(trace_path, ".vcd") ? trace_path + ".tmp.fst" : trace_path;
}

// Converts the recording to the requested VCD (when one was asked for) and removes it.
inline void finish_trace(const std::string& fst_path, const std::string& trace_path,
                         const char* engine) {
  if (fst_path == trace_path) return;
  const std::string cmd = "fst2vcd -f '" + fst_path + "' -o '" + trace_path + "' >/dev/null";
  const int rc = std::system(cmd.c_str());
  std::remove(fst_path.c_str());
  if (rc != 0)
    throw std::runtime_error("--trace " + trace_path + ": fst2vcd failed (the " +
                             std::string(engine) + " engine records FST and converts)");
}

}  // namespace rtl
}  // namespace trirast
