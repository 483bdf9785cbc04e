// The Verilated RTL of the half-space tile unit (rtl/trirast_halfspace.f, top trirast_hs_top) as
// an Engine ("halfspace-rtl"): the same transactor as the other units (cycle_loop.hpp), the
// improved unit's triangle port. StampSize, TileSize and the walk order are build parameters:
// dv/verilator/CMakeLists.txt Verilates the configurations kHsRtlBuilt lists, and a run picks the
// one matching --stamp, --tile, --hs-walk (or names the built ones).
#pragma once
#include <memory>
#include <string>

#include "core/engine.hpp"

namespace trirast {

std::unique_ptr<Engine> make_rtl_halfspace_engine();

namespace rtl {
// "--stamp 2 --tile 8 --hs-walk zigzag, ..." : the Verilated configurations.
std::string halfspace_built_configurations();
}  // namespace rtl

}  // namespace trirast
