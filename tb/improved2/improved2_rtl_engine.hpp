// The Verilated RTL of the second-generation improved unit (rtl/improved2/trirast_improved2.f) as an Engine:
// the transactor of the other RTL engines (cycle_loop.hpp) with the unit's ports
// (improved2_harness.hpp): set-up triangles back to back, span_ready_i from the run's downstream
// (--sink-stall, common/span_downstream.hpp), spans and the per-triangle cycles of the SystemC model improved2-sc's contract
// (docs/timing.md, "The second-generation improved unit").
#pragma once
#include <cstdint>
#include <memory>

#include "common/engine.hpp"
#include "improved/improved_rtl_engine.hpp"

namespace trirast {

// The engine registered as "improved2-rtl".
std::unique_ptr<Engine> make_improved2_rtl_engine();

namespace rtl {

// Runs the Verilated trirast_improved2_top once: the build of --corner-form
// (RasterConfig::improved2.corner_form) with the smallest FIFO that holds --fifo-depth. Throws
// std::invalid_argument (naming the option) for a configuration no build covers (N other than 1,
// other widths), WidthError for a triangle the widths do not hold, std::runtime_error when the
// simulation stops making progress.
void run_rtl_improved2(const SetupResult& setup, const RasterConfig& cfg,
                       const RtlRunOptions& opt, EngineResult& out);

}  // namespace rtl
}  // namespace trirast
