// The engine "improved2-rtl": picks the Verilated build of trirast_improved2_top of the run's
// corner form with the smallest FIFO and N that cover its --fifo-depth and --endpoints
// (rtl_builds.hpp; cfg_endpoints_i sets the run's N within the build's) and runs it
// (improved2_harness.hpp: the ports; cycle_loop.hpp: the cycles).
#include "improved2/improved2_rtl_engine.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/rtl_builds.hpp"
#include "common/sim_clock.hpp"

namespace trirast {
namespace rtl {

namespace {

const char* form_name(int form) { return form == 0 ? "products (dsp)" : "radix16"; }

const RtlBuild& pick_build(const RasterConfig& cfg) {
  const std::vector<RtlBuild>& builds = improved2_builds();
  const std::string built = describe_builds(builds, true, true);
  const std::string engine = "improved2-rtl";
  const RtlBuild* widths = nullptr;
  for (const RtlBuild& b : builds) {
    if (!same_widths(b, cfg)) continue;
    widths = &b;
    if (b.corner_form == cfg.improved2.corner_form && cfg.fifo_depth >= cfg.endpoints &&
        cfg.fifo_depth <= b.fifo_depth && cfg.endpoints >= 1 && cfg.endpoints <= b.endpoints)
      return b;
  }
  if (!widths) refuse_widths(engine, builds, cfg, true, built);
  int max_n = 0, max_depth = 0;  // the largest N and depth of these widths and this form
  for (const RtlBuild& b : builds)
    if (same_widths(b, cfg) && b.corner_form == cfg.improved2.corner_form) {
      max_n = std::max(max_n, b.endpoints);
      max_depth = std::max(max_depth, b.fifo_depth);
    }
  if (max_n > 0 && cfg.endpoints > max_n)
    refuse_build(engine, "--endpoints", std::to_string(cfg.endpoints),
                 "up to " + std::to_string(max_n), built);
  if (max_n > 0)
    refuse_build(engine, "--fifo-depth", std::to_string(cfg.fifo_depth),
                 "from --endpoints up to " + std::to_string(max_depth), built);
  refuse_build(engine, "--corner-form", form_name(cfg.improved2.corner_form),
               "no build of this form at these widths", built);
}

}  // namespace

void run_rtl_improved2(const SetupResult& setup, const RasterConfig& cfg,
                       const RtlRunOptions& opt, EngineResult& out) {
  cfg.validate();
  const RtlBuild& build = pick_build(cfg);
  run_build(build, setup, cfg, opt.x_seed, out);
}

}  // namespace rtl

std::unique_ptr<Engine> make_improved2_rtl_engine() {
  return make_timed_rtl_engine(
      [](const SetupResult& setup, const RasterConfig& cfg, uint32_t seed, EngineResult& out) {
        rtl::run_rtl_improved2(setup, cfg, {seed}, out);
      });
}

}  // namespace trirast
