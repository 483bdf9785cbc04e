// The Verilated RTL of the traditional-Bresenham unit (rtl/trad/trirast_trad_*.sv) as an Engine: the
// same transactor as the rtl engine (rtl_engine.hpp): set-up triangles back to back, span_ready_i
// from the run's downstream (--sink-stall, common/span_downstream.hpp), spans and the per-triangle cycles of docs/timing.md ("The
// traditional unit"). Its spans are the C++ trad model's (not the golden rule: exact = false).
#pragma once
#include <cstdint>
#include <memory>

#include "common/engine.hpp"
#include "improved/improved_rtl_engine.hpp"

namespace trirast {

// The engine registered as "trad-rtl".
std::unique_ptr<Engine> make_trad_rtl_engine();

namespace rtl {

// Runs the Verilated trirast_trad_top once (options as for run_rtl; --endpoints does not apply to
// the traditional unit and is ignored, as the trad model ignores it). Throws
// std::invalid_argument (naming the option) for a configuration the built model does not cover,
// WidthError for a vertex that does not fit the widths, std::runtime_error when the simulation
// stops making progress.
void run_rtl_trad(const SetupResult& setup, const RasterConfig& cfg, const RtlRunOptions& opt,
                  EngineResult& out);

}  // namespace rtl
}  // namespace trirast
