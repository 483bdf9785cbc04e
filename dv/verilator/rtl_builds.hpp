// The Verilated builds of the units (cmake/trirast_rtl_builds.cmake): every width configuration
// docs/synth.md names, each at the hardware maximums the runtime options need (NumEndpoints 4,
// FifoDepth 1024), and the default configuration also at its synthesized size (N = 1, DEPTH = 8),
// which simulates several times faster; the half-space unit at the stamp/tile/walk configurations
// that file lists. A run takes the smallest build that covers its options.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/engine.hpp"
#include "core/sink_pattern.hpp"

namespace trirast::rtl {

// One Verilated model with its harness.
struct RtlBuild {
  const char* prefix;  // the Verilator PREFIX (class name), e.g. "Vtrirast_top_n1"
  int subpixel_bits, coord_int_bits, box_bits;  // the widths of its package
  int endpoints, fifo_depth;                    // NumEndpoints, FifoDepth it was verilated with
  // Runs the scene through a fresh instance (cycle_loop.hpp); returns the cycle loop's counts.
  void (*run)(const SetupResult&, const RasterConfig&, uint32_t x_seed, EngineResult&);
  // The half-space unit's build parameters StampSize, TileSize (0: none), WalkZigzag (0 otherwise).
  int stamp, tile;
  bool zigzag;
  // The second-generation unit's CornerForm (RasterConfig::g2_corner_form; 0 otherwise).
  int corner_form;
};

// Smallest first (by FIFO depth, then endpoints). Defined in the generated rtl_builds_list.cpp.
const std::vector<RtlBuild>& improved_builds();
const std::vector<RtlBuild>& trad_builds();
const std::vector<RtlBuild>& halfspace_builds();
const std::vector<RtlBuild>& improved2_builds();

// Runs `build` (every RTL engine's run once it picked its build): a bad --sink-stall pattern fails
// before anything runs; reports the build's FIFO depth (work "rtl_build_fifo_depth").
inline void run_build(const RtlBuild& build, const SetupResult& setup, const RasterConfig& cfg,
                      uint32_t x_seed, EngineResult& out) {
  (void)SinkPattern::parse(cfg.sink_stall);
  build.run(setup, cfg, x_seed, out);
  out.work["rtl_build_fifo_depth"] = uint64_t(build.fifo_depth);
}

// "S:coord:box N<=4 DEPTH<=1024, ..." for error messages.
std::string describe_builds(const std::vector<RtlBuild>& builds, bool with_box);

}  // namespace trirast::rtl
