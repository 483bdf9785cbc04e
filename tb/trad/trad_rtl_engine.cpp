// The engine "trad-rtl": picks the smallest Verilated build of trirast_trad_top that covers the
// run's options (rtl_builds.hpp) and runs it (trad_harness.hpp: the ports; cycle_loop.hpp).
#include "trad/trad_rtl_engine.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/rtl_builds.hpp"
#include "common/sim_clock.hpp"

namespace trirast {
namespace rtl {

namespace {

// The smallest build of the widths of cfg that holds its --fifo-depth (the traditional unit has
// no box bits: any build of S and the coordinate bits serves).
const RtlBuild& pick_build(const RasterConfig& cfg) {
  const std::vector<RtlBuild>& builds = trad_builds();
  const RtlBuild* widths = nullptr;
  for (const RtlBuild& b : builds) {
    if (b.subpixel_bits != cfg.subpixel_bits || b.coord_int_bits != cfg.coord_int_bits) continue;
    widths = &b;
    if (cfg.fifo_depth >= 1 && cfg.fifo_depth <= b.fifo_depth) return b;
  }
  const std::string built = describe_builds(builds, false);
  if (!widths) refuse_widths("trad-rtl", builds, cfg, false, built);
  refuse_build("trad-rtl", "--fifo-depth", std::to_string(cfg.fifo_depth),
               "from 1 up to " + std::to_string(widths->fifo_depth), built);
}

}  // namespace

void run_rtl_trad(const SetupResult& setup, const RasterConfig& cfg, const RtlRunOptions& opt,
                  EngineResult& out) {
  const RtlBuild& build = pick_build(cfg);
  run_build(build, setup, cfg, opt.x_seed, out);
}

}  // namespace rtl

std::unique_ptr<Engine> make_trad_rtl_engine() {
  return make_timed_rtl_engine(
      [](const SetupResult& setup, const RasterConfig& cfg, uint32_t seed, EngineResult& out) {
        rtl::run_rtl_trad(setup, cfg, {seed}, out);
      });
}

}  // namespace trirast
