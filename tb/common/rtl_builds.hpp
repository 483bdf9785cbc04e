// The Verilated builds of the units (cmake/trirast_rtl_builds.cmake): every width configuration
// docs/synth.md names, each at the hardware maximums the runtime options need (NumEndpoints 4,
// FifoDepth 1024), and the default configuration also at its synthesized size (N = 1, DEPTH = 8),
// which simulates several times faster; the half-space unit at the stamp/tile/walk configurations
// that file lists. A run takes the smallest build that covers its options.
// Each is a checked build (assertions, cover points, trace support); the builds a default run
// picks also have a speed build, the same RTL without them, which a run takes unless it asks for
// the checked one (RasterConfig::rtl_checked) or a trace (run_build).
#pragma once
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/engine.hpp"
#include "common/span_downstream.hpp"

namespace trirast::rtl {

// One Verilated model with its harness.
struct RtlBuild {
  const char* prefix;  // the Verilator PREFIX (class name), e.g. "Vtrirast_improved_top_n1"
  int subpixel_bits, coord_int_bits, box_bits;  // the widths of its package
  int endpoints, fifo_depth;                    // NumEndpoints, FifoDepth it was verilated with
  // Runs the scene through a fresh instance (cycle_loop.hpp); returns the cycle loop's counts.
  void (*run)(const SetupResult&, const RasterConfig&, uint32_t x_seed, EngineResult&);
  // The half-space unit's build parameters StampSize, TileSize (0: none), WalkMode (the value of
  // HalfspaceWalk; 0 otherwise).
  int stamp, tile;
  int walk;
  // The CornerForm of the second-generation and half-space units (RasterConfig::improved2 /
  // halfspace.corner_form; 0 otherwise).
  int corner_form;
  // The run of its speed build (no assertions, cover points or trace support); nullptr: none.
  void (*run_speed)(const SetupResult&, const RasterConfig&, uint32_t x_seed, EngineResult&);
};

// Smallest first (by FIFO depth, then endpoints). Defined in the generated rtl_builds_list.cpp.
const std::vector<RtlBuild>& improved_builds();
const std::vector<RtlBuild>& trad_builds();
const std::vector<RtlBuild>& halfspace_builds();
const std::vector<RtlBuild>& improved2_builds();

// Runs `build` (every RTL engine's run once it picked its build), its speed build when it has one
// and the run asks neither for the checked build (cfg.rtl_checked) nor for a trace: a bad
// --sink-stall (a pattern or queue:RATE:CAPACITY; span_downstream.hpp) fails before anything
// runs; reports the build's FIFO depth and whether it was the checked one (work
// "rtl_build_fifo_depth", "rtl_build_checked").
inline void run_build(const RtlBuild& build, const SetupResult& setup, const RasterConfig& cfg,
                      uint32_t x_seed, EngineResult& out) {
  (void)make_span_downstream(cfg.sink_stall);  // parsed only: a program's factory is not called
  const bool speed = build.run_speed && !cfg.rtl_checked && cfg.trace_path.empty();
  (speed ? build.run_speed : build.run)(setup, cfg, x_seed, out);
  out.work["rtl_build_fifo_depth"] = uint64_t(build.fifo_depth);
  out.work["rtl_build_checked"] = speed ? 0 : 1;
}

// Whether build b has the widths of cfg (S, coordinate and box bits).
inline bool same_widths(const RtlBuild& b, const RasterConfig& cfg) {
  return b.subpixel_bits == cfg.subpixel_bits && b.coord_int_bits == cfg.coord_int_bits &&
         b.box_bits == cfg.box_bits;
}

// An engine's refusal of a run no build covers, naming the option: "OPT: GOT is not covered by
// the ENGINE engine's Verilated models (HOW; built: BUILT; add one in ...)".
[[noreturn]] inline void refuse_build(const std::string& engine, const std::string& opt,
                                      const std::string& got, const std::string& how,
                                      const std::string& built) {
  throw std::invalid_argument(opt + ": " + got + " is not covered by the " + engine +
                              " engine's Verilated models (" + how + "; built: " + built +
                              "; add one in cmake/trirast_rtl_builds.cmake)");
}

// The refusal of widths no build has, naming the first option no build of the others' values has
// (with_box: the box bits count; the traditional unit has none).
[[noreturn]] inline void refuse_widths(const std::string& engine,
                                       const std::vector<RtlBuild>& builds,
                                       const RasterConfig& cfg, bool with_box,
                                       const std::string& built) {
  bool s = false, c = false;
  for (const RtlBuild& b : builds) {
    s = s || b.subpixel_bits == cfg.subpixel_bits;
    c = c || (b.subpixel_bits == cfg.subpixel_bits && b.coord_int_bits == cfg.coord_int_bits);
  }
  if (!s)
    refuse_build(engine, "--subpixel-bits", std::to_string(cfg.subpixel_bits), "no build of this S",
                 built);
  if (!c || !with_box)
    refuse_build(engine, "--coord-bits", std::to_string(cfg.coord_int_bits),
                 "no build of these S and coordinate bits", built);
  refuse_build(engine, "--box-bits", std::to_string(cfg.box_bits),
               "no build of these S, coordinate and box bits", built);
}

// "S:coord:box N<=4 DEPTH<=1024, ..." for error messages; with_form: each build's corner form
// (the second-generation unit), "... DEPTH<=1024 radix16".
std::string describe_builds(const std::vector<RtlBuild>& builds, bool with_box,
                            bool with_form = false);

}  // namespace trirast::rtl
