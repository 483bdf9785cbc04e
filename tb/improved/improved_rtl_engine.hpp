// The Verilated RTL of the improved unit (rtl/) as an Engine: the transactor feeds set-up
// triangles back to back, drives span_ready_i from the run's downstream (--sink-stall,
// common/span_downstream.hpp), collects spans and the per-triangle cycles of docs/timing.md
// (docs/rtl.md, "Harness").
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "common/engine.hpp"

namespace trirast {

// The engine registered as "improved-rtl".
std::unique_ptr<Engine> make_improved_rtl_engine();

namespace rtl {

// Options beyond RasterConfig, for tests.
struct RtlRunOptions {
  uint32_t x_seed = 1;  // seed of --x-initial unique / --x-assign unique (0: Verilator picks)
};

// Runs the Verilated model once. Throws std::invalid_argument (naming the option) for a
// configuration the built model does not cover, WidthError / std::logic_error for a triangle
// the unit cannot hold (checked with the bit-accurate model before simulation), and
// std::runtime_error when the simulation stops making progress.
void run_rtl(const SetupResult& setup, const RasterConfig& cfg, const RtlRunOptions& opt,
             EngineResult& out);

// The configuration the Verilated model was built for (rtl/CMakeLists.txt), as text.
std::string built_configuration();

}  // namespace rtl
}  // namespace trirast
