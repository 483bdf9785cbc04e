// The engine "halfspace-rtl": picks the Verilated build of trirast_halfspace_top (rtl_builds.hpp,
// cmake/trirast_rtl_builds.cmake) of the run's widths and --stamp/--tile/--hs-walk/--hs-corner-form
// whose FIFO
// holds --fifo-depth, and runs it (halfspace_harness.hpp: the ports; cycle_loop.hpp: the cycles).
#include "halfspace/halfspace_rtl_engine.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/rtl_builds.hpp"
#include "common/sim_clock.hpp"

namespace trirast {
namespace rtl {

namespace {

std::string describe_hs(int stamp, int tile, HalfspaceWalk walk, int corner_form) {
  return "--stamp " + std::to_string(stamp) + " --tile " +
         (tile ? std::to_string(tile) : std::string("none")) + " --hs-walk " +
         halfspace_walk_name(walk) + " --hs-corner-form " + corner_form_name(corner_form);
}

bool same_unit(const RtlBuild& b, const RasterConfig& cfg) {
  return b.stamp == cfg.halfspace.stamp && b.tile == cfg.halfspace.tile &&
         b.walk == int(cfg.halfspace.walk) &&
         b.corner_form == cfg.halfspace.corner_form;
}

const RtlBuild& pick_build(const RasterConfig& cfg) {
  const std::vector<RtlBuild>& builds = halfspace_builds();
  bool widths = false, unit = false;
  for (const RtlBuild& b : builds) {
    widths = widths || same_widths(b, cfg);
    if (!same_widths(b, cfg) || !same_unit(b, cfg)) continue;
    unit = true;
    if (cfg.fifo_depth >= 1 && cfg.fifo_depth <= b.fifo_depth) return b;
  }
  const std::string add = "; built: " + halfspace_built_configurations() +
                          "; add one in cmake/trirast_rtl_builds.cmake)";
  if (!widths)
    throw std::invalid_argument(
        "--subpixel-bits/--coord-bits/--box-bits: " + std::to_string(cfg.subpixel_bits) + ":" +
        std::to_string(cfg.coord_int_bits) + ":" + std::to_string(cfg.box_bits) +
        " is not covered by the halfspace-rtl engine's Verilated models (no build of these widths" +
        add);
  if (!unit)
    throw std::invalid_argument(
        "--stamp/--tile/--hs-walk/--hs-corner-form: " +
        describe_hs(cfg.halfspace.stamp, cfg.halfspace.tile, cfg.halfspace.walk,
                    cfg.halfspace.corner_form) +
        " is not covered by the halfspace-rtl engine's Verilated models (no build of these "
        "parameters at these widths" + add);
  throw std::invalid_argument("--fifo-depth: " + std::to_string(cfg.fifo_depth) +
                              " is not covered by the halfspace-rtl engine's Verilated models "
                              "(too deep" + add);
}

}  // namespace

std::string halfspace_built_configurations() {
  std::string s;
  for (const RtlBuild& b : halfspace_builds())
    s += (s.empty() ? "" : "; ") + std::to_string(b.subpixel_bits) + ":" +
         std::to_string(b.coord_int_bits) + ":" + std::to_string(b.box_bits) + " " +
         describe_hs(b.stamp, b.tile, HalfspaceWalk(b.walk), b.corner_form) + " DEPTH<=" + std::to_string(b.fifo_depth);
  return "S:coord:box " + s;
}

bool halfspace_build_covers(const RasterConfig& cfg) {
  for (const RtlBuild& b : halfspace_builds())
    if (same_widths(b, cfg) && same_unit(b, cfg) && cfg.fifo_depth <= b.fifo_depth) return true;
  return false;
}

std::vector<HalfspaceParams> halfspace_built_params(const RasterConfig& cfg) {
  std::vector<HalfspaceParams> out;
  for (const RtlBuild& b : halfspace_builds())
    if (same_widths(b, cfg) && cfg.fifo_depth <= b.fifo_depth)
      out.push_back({b.stamp, b.tile, HalfspaceWalk(b.walk), b.corner_form});
  return out;
}

void run_rtl_halfspace(const SetupResult& setup, const RasterConfig& cfg, uint32_t x_seed,
                       EngineResult& out) {
  run_build(pick_build(cfg), setup, cfg, x_seed, out);
}

}  // namespace rtl

std::unique_ptr<Engine> make_halfspace_rtl_engine() {
  return make_timed_rtl_engine(
      [](const SetupResult& setup, const RasterConfig& cfg, uint32_t seed, EngineResult& out) {
        rtl::run_rtl_halfspace(setup, cfg, seed, out);
      });
}

}  // namespace trirast
