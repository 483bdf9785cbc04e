#include "halfspace/halfspace_setup.hpp"

namespace trirast {

HalfspaceSetupStage::HalfspaceSetupStage(const RasterConfig& cfg)
    : p_(HalfspaceParams::from(cfg)), w_(unit_widths(cfg)), interface_(cfg) {}

HalfspaceSetupOut HalfspaceSetupStage::run(const TriangleSetup& t) const {
  // The interface computes the box, checks the widths and the corner values (docs/unit.md, 1).
  const BoxStageOut in = interface_.run(t);
  HalfspaceSetupOut o;
  o.tri = in.tri;
  o.empty = in.empty;
  if (in.empty) return o;
  o.x0 = in.x0;
  o.y0 = in.y0;
  o.Xmax = in.Xmax;
  o.Ymax = in.Ymax;
  const int64_t U = p_.unit();
  o.units = (in.Xmax + U) / U;
  o.bands = (in.Ymax + U) / U;
  for (int k = 0; k < 3; ++k) {
    HalfspaceEdge& e = o.edge[k];
    e.a = in.edge[k].a;
    e.b = in.edge[k].b;
    e.E0 = in.edge[k].E_L;
    e.Eend = e.E0 + (o.units - 1) * U * e.a;
    check_signed(e.Eend, w_.edge_value, t.index, "E_end", "edge value");
  }
  return o;
}

}  // namespace trirast
