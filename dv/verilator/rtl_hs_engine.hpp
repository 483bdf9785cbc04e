// The Verilated RTL of the half-space tile unit (rtl/trirast_halfspace.f, top trirast_hs_top) as
// an Engine ("halfspace-rtl"): the same transactor as the other units (cycle_loop.hpp), the
// improved unit's triangle port. StampSize, TileSize and the walk order are build parameters:
// dv/verilator/CMakeLists.txt Verilates the configurations kHsRtlBuilt lists, and a run picks the
// one matching --stamp, --tile, --hs-walk (or names the built ones).
#pragma once
#include <memory>
#include <string>

#include "core/engine.hpp"
#include "core/setup.hpp"

namespace trirast {

std::unique_ptr<Engine> make_rtl_halfspace_engine();

namespace rtl {
// "--stamp 2 --tile 8 --hs-walk zigzag, ..." : the Verilated configurations.
std::string halfspace_built_configurations();
// Runs the Verilated model matching cfg's --stamp/--tile/--hs-walk once (x_seed as
// RtlRunOptions::x_seed). Throws std::invalid_argument naming the option when no built model
// covers cfg, WidthError for a triangle that does not fit the widths.
void run_rtl_halfspace(const SetupResult& setup, const RasterConfig& cfg, uint32_t x_seed,
                       EngineResult& out);
}  // namespace rtl

}  // namespace trirast
