// Pieces shared by the Verilator harnesses (rtl_engine.cpp, rtl_trad_engine.cpp): wide-port
// packing and the FST -> VCD conversion of a trace.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "core/temporary_files.hpp"

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
