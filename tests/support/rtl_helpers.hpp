// What the RTL engines' tests (tests/rtl) share: a scene's set-up triangles from its spec, and one
// run of a Verilated unit with a chosen seed for its undefined initial values. Header only.
#pragma once
#include <cstdint>
#include <string>

#include "common/engine.hpp"
#include "common/setup.hpp"
#include "improved/improved_rtl_engine.hpp"
#include "scene/scene.hpp"

namespace trirast::test {

// The set-up triangles of the scene `spec` (builtin:..., a mesh file) under `cfg`, default camera.
inline SetupResult scene(const std::string& spec, const RasterConfig& cfg) {
  return setup_scene(load_scene(spec, cfg, CameraOptions{}).tris, cfg);
}

// A Verilated unit's run function (rtl::run_rtl, rtl::run_rtl_trad, rtl::run_rtl_improved2).
using RtlRunFunction = void (*)(const SetupResult&, const RasterConfig&, const rtl::RtlRunOptions&,
                                EngineResult&);

// One run of `run` on the scene, --x-initial / --x-assign seeded `seed`.
inline EngineResult run_verilated(RtlRunFunction run, const SetupResult& setup,
                                  const RasterConfig& cfg, uint32_t seed) {
  EngineResult r;
  rtl::RtlRunOptions opt;
  opt.x_seed = seed;
  run(setup, cfg, opt, r);
  return r;
}

}  // namespace trirast::test
