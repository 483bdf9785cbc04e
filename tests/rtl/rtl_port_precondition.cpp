// Drives one triangle into the triangle port of a Verilated top (built with --assert: the builds
// of trirast_rtl_models at the default widths), for the ctests rtl_port_precondition_* (the
// triangle port's preconditions, docs/port.md, checked by rtl/common/trirast_triangle_port_check.sv):
//   trirast_rtl_port_precondition UNIT CASE
//     UNIT  improved | improved2 | halfspace | trad
//     CASE  good        a triangle as setup forms it (model/common/setup.cpp): must walk its spans
//                       with no assertion firing (exit 0, "N spans")
//           swapped     the same triangle with v1 and v2 swapped and its edges (A, B, C, bias)
//                       formed from the swapped vertices, so that only the orientation is wrong:
//                       TriOrientation_A must stop the run
//           degenerate  three vertices on a line, edges formed from them: TriNonDegenerate_A
//                       must stop the run
// A firing assertion prints "[ASSERT FAILED] [instance] Name" and ends the process with a
// non-zero status (tests/rtl/expect_failure.sh turns that into the test's pass). A broken
// triangle that no assertion stops makes this program print its span count and exit 0: the
// ctest fails.
#include <verilated.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "Vtrirast_halfspace_top_s2t8f.h"
#include "Vtrirast_improved2_top.h"
#include "Vtrirast_improved_top.h"
#include "Vtrirast_trad_top.h"
#include "common/harness_util.hpp"
#include "common/setup.hpp"
#include "default/params.hpp"
#include "rtl_direct_top.hpp"

namespace {

using trirast::TriangleSetup;
using P = trirast::rtl::Params_default;

// Edge k from v[k] to v[k+1] of the vertices as they stand, by the coverage rule
// (docs/coverage-rule.md): for the broken cases, whose vertices setup would not hand on.
void edges_from_vertices(TriangleSetup& t) {
  for (int k = 0; k < 3; ++k) {
    const trirast::Vec2i& a = t.v[k];
    const trirast::Vec2i& b = t.v[(k + 1) % 3];
    trirast::EdgeSetup& e = t.edge[k];
    e.A = a.y - b.y;
    e.B = b.x - a.x;
    e.C = a.x * b.y - a.y * b.x;
    e.bias = (e.A > 0 || (e.A == 0 && e.B > 0)) ? 0 : -1;
  }
}

// Resets the top (rtl_direct_top.hpp), offers t until it is taken, then clocks until the unit is
// idle; returns the spans it sent. cfg sets the unit's own configuration inputs.
template <class Top, class Config, class Offer>
long run(const char* name, const Config& cfg, const Offer& offer) {
  trirast::rtl::DirectTop<Top> top([&](Top& t) {
    cfg(t);
    t.tri_tag_i = 7;
  });
  offer(*top);
  top->tri_valid_i = 1;
  long spans = 0;
  bool taken = false;
  for (int c = 0; c < 400 && !top.finished(); ++c) {
    top->eval();
    const bool take = top->tri_valid_i && top->tri_ready_o;
    if (top->span_valid_o) ++spans;
    top.tick();
    if (take) {
      taken = true;
      top->tri_valid_i = 0;
    }
  }
  if (!taken) {
    std::fprintf(stderr, "trirast_rtl_port_precondition %s: the triangle was never taken\n", name);
    std::exit(3);
  }
  return spans;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string unit = argc > 1 ? argv[1] : "", mode = argc > 2 ? argv[2] : "";
  if (mode != "good" && mode != "swapped" && mode != "degenerate") {
    std::fprintf(stderr, "trirast_rtl_port_precondition: unknown case '%s' (good, swapped, degenerate)\n",
                 mode.c_str());
    return 2;
  }
  // A triangle of a few hundred pixels inside the 64 x 64 viewport, set up as the CLI does.
  trirast::RasterConfig cfg;
  cfg.width = cfg.height = 64;
  trirast::InputTriangle in{{2.25, 40.5, 9.75}, {3.5, 11.0, 50.25}};
  TriangleSetup t{};
  const char* why = nullptr;
  if (!trirast::setup_triangle(in, 0, cfg, t, &why)) {
    std::fprintf(stderr, "trirast_rtl_port_precondition: setup refuses the triangle (%s)\n", why);
    return 2;
  }
  if (mode == "swapped") {
    std::swap(t.v[1], t.v[2]);
    edges_from_vertices(t);
  } else if (mode == "degenerate") {
    t.v[0] = {2 * 256 + 64, 3 * 256};
    t.v[1] = {10 * 256 + 64, 7 * 256};
    t.v[2] = {30 * 256 + 64, 17 * 256};
    edges_from_vertices(t);
  }
  const auto offer_edges = [&](auto& top) { trirast::rtl::drive_edge_triangle<P>(top, t); };
  long spans = 0;
  if (unit == "improved") {
    spans = run<Vtrirast_improved_top>(
        "improved", [](auto& top) {
          top.cfg_divide_i = 0;
          top.cfg_adaptive_i = 1;
          top.cfg_endpoints_i = 1;
        }, offer_edges);
  } else if (unit == "improved2") {
    spans = run<Vtrirast_improved2_top>(
        "improved2", [](auto& top) { top.cfg_endpoints_i = 1; }, offer_edges);
  } else if (unit == "halfspace") {
    spans = run<Vtrirast_halfspace_top_s2t8f>("halfspace", [](auto&) {}, offer_edges);
  } else if (unit == "trad") {
    spans = run<Vtrirast_trad_top>("trad", [](auto&) {}, [&](auto& top) {
      trirast::rtl::Bits<8> vx, vy;
      for (int k = 0; k < 3; ++k) {
        vx.put(k * P::kVertexBits, P::kVertexBits, t.v[k].x);
        vy.put(k * P::kVertexBits, P::kVertexBits, t.v[k].y);
      }
      trirast::rtl::drive(top.tri_vx_i, vx, trirast::rtl::words(3 * P::kVertexBits));
      trirast::rtl::drive(top.tri_vy_i, vy, trirast::rtl::words(3 * P::kVertexBits));
    });
  } else {
    std::fprintf(stderr, "trirast_rtl_port_precondition: unknown unit '%s' (improved, improved2, halfspace, trad)\n",
                 unit.c_str());
    return 2;
  }
  std::printf("trirast_rtl_port_precondition %s %s: no assertion fired; %ld spans\n", unit.c_str(),
              mode.c_str(), spans);
  // A good triangle must walk: a run with no span would not show that the port works.
  return mode == "good" && spans == 0 ? 1 : 0;
}
