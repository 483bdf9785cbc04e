// The Verilated RTL of the half-space tile unit (rtl/halfspace/trirast_halfspace.f, top trirast_halfspace_top) as
// an Engine ("halfspace-rtl"): the same transactor as the other units (cycle_loop.hpp), the
// improved unit's triangle port. StampSize, TileSize and the walk order are build parameters:
// cmake/trirast_rtl_builds.cmake declares the Verilated configurations (widths and stamp / tile /
// walk), and a run picks the one matching its options (or names the built ones).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "common/engine.hpp"
#include "common/setup.hpp"
#include "halfspace/halfspace_setup.hpp"

namespace trirast {

std::unique_ptr<Engine> make_halfspace_rtl_engine();

namespace rtl {
// "S:coord:box 8:16:14 --stamp 2 --tile 8 --hs-walk forward DEPTH<=1024; ...": the builds.
std::string halfspace_built_configurations();
// Whether a Verilated build covers cfg's widths, --stamp/--tile/--hs-walk and --fifo-depth.
bool halfspace_build_covers(const RasterConfig& cfg);
// The --stamp/--tile/--hs-walk of the builds of cfg's widths whose FIFO holds --fifo-depth
// (trirast fuzz draws among them).
std::vector<HalfspaceParams> halfspace_built_params(const RasterConfig& cfg);
// Runs the Verilated model matching cfg's widths and --stamp/--tile/--hs-walk once (x_seed as
// RtlRunOptions::x_seed). Throws std::invalid_argument naming the option when no built model
// covers cfg, WidthError for a triangle that does not fit the widths.
void run_rtl_halfspace(const SetupResult& setup, const RasterConfig& cfg, uint32_t x_seed,
                       EngineResult& out);
}  // namespace rtl

}  // namespace trirast
