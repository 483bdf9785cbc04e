// The engine "improved-rtl": picks the smallest Verilated build of trirast_improved_top that covers the
// run's options (rtl_builds.hpp) and runs it (improved_harness.hpp: the ports; cycle_loop.hpp:
// the cycles).
#include "improved/improved_rtl_engine.hpp"

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

// The smallest build of the widths of cfg that holds its --endpoints and --fifo-depth.
const RtlBuild& pick_build(const RasterConfig& cfg) {
  const std::vector<RtlBuild>& builds = improved_builds();
  const RtlBuild* widths = nullptr;  // a build of these widths (for the message)
  for (const RtlBuild& b : builds) {
    if (!same_widths(b, cfg)) continue;
    widths = &b;
    if (cfg.endpoints >= 1 && cfg.endpoints <= b.endpoints && cfg.fifo_depth >= cfg.endpoints &&
        cfg.fifo_depth <= b.fifo_depth)
      return b;
  }
  const std::string built = built_configuration();
  if (!widths) refuse_widths("improved-rtl", builds, cfg, true, built);
  if (cfg.endpoints < 1 || cfg.endpoints > widths->endpoints)
    refuse_build("improved-rtl", "--endpoints", std::to_string(cfg.endpoints),
                 "at most " + std::to_string(widths->endpoints), built);
  refuse_build("improved-rtl", "--fifo-depth", std::to_string(cfg.fifo_depth),
               "from --endpoints up to " + std::to_string(widths->fifo_depth), built);
}

}  // namespace

std::string built_configuration() { return describe_builds(improved_builds(), true); }

std::string describe_builds(const std::vector<RtlBuild>& builds, bool with_box, bool with_form) {
  std::string s;
  for (const RtlBuild& b : builds) {
    if (!s.empty()) s += ", ";
    s += std::to_string(b.subpixel_bits) + ":" + std::to_string(b.coord_int_bits);
    if (with_box) s += ":" + std::to_string(b.box_bits);
    if (with_box) s += " N<=" + std::to_string(b.endpoints);
    s += " DEPTH<=" + std::to_string(b.fifo_depth);
    if (with_form) s += b.corner_form == 0 ? " dsp" : " radix16";
  }
  return "S:coord" + std::string(with_box ? ":box" : "") + " " + s;
}

void run_rtl(const SetupResult& setup, const RasterConfig& cfg, const RtlRunOptions& opt,
             EngineResult& out) {
  // The sweep's quotient truncation (RasterConfig::divider_quotient_bits, K): the RTL's divider
  // always runs the exact Q (or adaptive) iterations; it has no truncation.
  if (cfg.divider_quotient_bits != 0)
    throw std::invalid_argument(
        "divider_quotient_bits: " + std::to_string(cfg.divider_quotient_bits) +
        " is not covered by the rtl engine (the RTL has no quotient truncation; only 0, the exact "
        "divider, is)");
  const RtlBuild& build = pick_build(cfg);
  run_build(build, setup, cfg, opt.x_seed, out);  // a bad pattern fails before the width check
  out.work["rtl_build_endpoints"] = uint64_t(build.endpoints);
}

}  // namespace rtl

std::unique_ptr<Engine> make_improved_rtl_engine() {
  return make_timed_rtl_engine(
      [](const SetupResult& setup, const RasterConfig& cfg, uint32_t seed, EngineResult& out) {
        rtl::run_rtl(setup, cfg, {seed}, out);
      });
}

}  // namespace trirast
