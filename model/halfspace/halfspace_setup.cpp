#include "halfspace/halfspace_setup.hpp"

#include <stdexcept>
#include <string>

#include "common/corner_serial.hpp"

namespace trirast {

HalfspaceSetupStage::HalfspaceSetupStage(const RasterConfig& cfg)
    : cfg_(cfg), p_(HalfspaceParams::from(cfg)), w_(unit_widths(cfg)), interface_(cfg) {}

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
  const int64_t xlast = (o.units - 1) * U;  // the last unit of band row 0: Xmax & ~(U - 1)
  for (int k = 0; k < 3; ++k) {
    HalfspaceEdge& e = o.edge[k];
    e.a = in.edge[k].a;
    e.b = in.edge[k].b;
    e.E0 = in.edge[k].E_L;
    e.Eend = e.E0 + xlast * e.a;
    check_signed(e.Eend, w_.edge_value, t.index, "E_end", "edge value");
    // The corner unit's vertex-relative values are the interface's: a difference is a model bug.
    if (cfg_.halfspace.corner_form == 1 &&
        (corner_serial_value(t, k, o.x0, o.y0, cfg_) != e.E0 ||
         corner_serial_value(t, k, o.x0 + xlast, o.y0, cfg_) != e.Eend))
      throw std::logic_error("triangle " + std::to_string(t.index) + ": edge " + std::to_string(k) +
                             ": vertex-relative corner values differ from the interface's");
  }
  if (cfg_.halfspace.corner_form == 0) return o;
  o.corner_digits_e0 = corner_serial_digits(t, o.x0, o.y0, cfg_);
  // Run 2 (E_end) only for the zig-zag walk, whose odd bands start there.
  if (xlast > 0 && p_.walk == HalfspaceWalk::Zigzag) o.corner_digits_eend = corner_serial_digits(t, o.x0 + xlast, o.y0, cfg_);
  return o;
}

}  // namespace trirast
