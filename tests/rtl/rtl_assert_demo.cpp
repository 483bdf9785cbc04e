// Drives the Verilated trirast_improved_top (built with --assert, NumEndpoints = 4) against its protocol on
// purpose, so that one of the RTL's assertions (rtl/common/trirast_assert.svh) must stop the run:
//   trirast_rtl_assert_demo endpoints   cfg_endpoints_i = 5 > NumEndpoints (CfgEndpointsInRange_A)
//   trirast_rtl_assert_demo tri-data    the triangle changes while tri_valid_i && !tri_ready_o
//                                       (TriDataStable_A)
// A firing assertion prints "[ASSERT FAILED] [instance] Name" and ends the process with a
// non-zero status. If none fires within the cycles below, this program says so and exits 0, which
// the ctests rtl_assert_* (tests/rtl/expect_failure.sh) count as a failure.
#include <verilated.h>

#include <cstdio>
#include <cstring>

#include "Vtrirast_improved_top.h"
#include "common/harness_util.hpp"
#include "common/setup.hpp"
#include "default/params.hpp"
#include "rtl_direct_top.hpp"

int main(int argc, char** argv) {
  const char* mode = argc > 1 ? argv[1] : "";
  const bool endpoints = std::strcmp(mode, "endpoints") == 0;
  const bool tri_data = std::strcmp(mode, "tri-data") == 0;
  if (!endpoints && !tri_data) {
    std::fprintf(stderr, "trirast_rtl_assert_demo: unknown mode '%s' (endpoints, tri-data)\n",
                 mode);
    return 2;
  }
  // A legal configuration but for the broken input of the mode.
  trirast::rtl::DirectTop<Vtrirast_improved_top> top([&](Vtrirast_improved_top& t) {
    t.cfg_divide_i = 0;
    t.cfg_adaptive_i = 1;
    t.cfg_endpoints_i = endpoints ? 5 : 1;
  });

  // tri-data: a triangle is offered from cycle 0 and taken then; the next one is offered from
  // cycle 1 (the setup stage is busy, tri_ready_o low) and changes in cycle 2 before its handshake.
  // The triangle is one setup forms (the port's preconditions hold: only the tag breaks the rule).
  trirast::RasterConfig cfg;
  cfg.width = cfg.height = 64;
  trirast::InputTriangle in{{2.25, 40.5, 9.75}, {3.5, 11.0, 50.25}};
  trirast::TriangleSetup t{};
  const char* why = nullptr;
  if (!trirast::setup_triangle(in, 0, cfg, t, &why)) return 2;
  trirast::rtl::drive_edge_triangle<trirast::rtl::Params_default>(*top, t);
  const int cycles = 20;
  for (int c = 0; c < cycles && !top.finished(); ++c) {
    if (tri_data) {
      top->tri_valid_i = 1;
      top->tri_tag_i = uint32_t(c < 2 ? c : 2);
    }
    top->eval();
    top.tick();
  }
  std::printf("trirast_rtl_assert_demo %s: no assertion fired in %d cycles\n", mode, cycles);
  return 0;
}
