#include "halfspace/halfspace_unit.hpp"

#include <algorithm>
#include <string>

namespace trirast {

namespace {

const RasterConfig& checked_config(const RasterConfig& cfg) {
  cfg.validate();
  const UnitWidths w = unit_widths(cfg);
  if (w.hs_edge_value > 63)
    throw WidthError("halfspace: " + std::to_string(w.hs_edge_value) +
                     "-bit edge values exceed the 64-bit model; use fewer --coord-bits or --subpixel-bits");
  return cfg;
}

}  // namespace

HalfspaceUnit::HalfspaceUnit(const RasterConfig& cfg)
    : p_(HalfspaceParams::from(checked_config(cfg))),
      setup_(cfg),
      walker_(cfg),
      tester_(cfg),
      emitter_(cfg) {}

HalfspaceTriangleResult HalfspaceUnit::run_triangle(const TriangleSetup& t, SpanList& out) {
  HalfspaceTriangleResult res;
  res.setup = setup_.run(t);
  if (!res.setup.empty) walk(res, out);
  return res;
}

void HalfspaceUnit::walk(HalfspaceTriangleResult& res, SpanList& out) {
  const HalfspaceSetupOut& s = res.setup;
  const int64_t U = p_.unit();
  const int64_t S = p_.stamp;
  HalfspaceWork& w = res.work;
  for (int64_t k = 0; k < s.bands; ++k) {
    emitter_.begin_band(k * U, walker_.backward(k));
    HalfspaceBand band;
    auto stamp = [&](int64_t i0, int64_t j0, unsigned edges_inside) {
      const HalfspaceStampOut st = tester_.test(s, i0, j0, edges_inside);
      ++w.stamps;
      ++band.cycles;
      for (int dj = 0; dj < S; ++dj)
        if (st.row[dj].any) emitter_.merge(j0 + dj, st.row[dj].first, st.row[dj].last);
    };
    const int64_t tested = walker_.walk_band(s, k, [&](int64_t i0, int64_t j0, const HalfspaceUnitTest& t) {
      emitter_.begin_unit();
      if (t.cls == HalfspaceClass::Reject) {
        ++w.rejected;
        return;
      }
      if (p_.tile == 0) {  // the unit is a stamp: its test is the stamp test
        ++w.partial;
        const HalfspaceStampOut st = tester_.test(s, i0, j0, 0u);  // nothing masked
        for (int dj = 0; dj < S; ++dj)
          if (st.row[dj].any) emitter_.merge(j0 + dj, st.row[dj].first, st.row[dj].last);
        return;
      }
      const int64_t i1 = std::min(i0 + U - 1, s.Xmax), j1 = std::min(j0 + U - 1, s.Ymax);
      if (t.cls == HalfspaceClass::Accept) {
        ++w.accepted;
        for (int64_t j = j0; j <= j1; ++j) emitter_.merge(j, i0, i1);
        return;
      }
      ++w.partial;
      // The stamps of the tile inside the box, row by row.
      for (int64_t sj = j0; sj <= j1; sj += S)
        for (int64_t si = i0; si <= i1; si += S) stamp(si, sj, t.edges_inside);
    });
    w.units_tested += uint64_t(tested);
    band.cycles += uint64_t(tested);
    const size_t first = out.size();
    band.spans = emitter_.end_band(s, out);
    for (size_t i = first; i < out.size(); ++i) w.pixels += uint64_t(out[i].pixels());
    w.spans += band.spans;
    ++w.bands;
    res.bands.push_back(band);
  }
}

void add_hs_work(const HalfspaceWork& w, std::map<std::string, uint64_t>& work) {
  work["hs_units_tested"] += w.units_tested;
  work["hs_units_rejected"] += w.rejected;
  work["hs_tiles_accepted"] += w.accepted;
  work["hs_units_partial"] += w.partial;
  work["hs_stamps"] += w.stamps;
  work["hs_bands"] += w.bands;
  work["spans"] += w.spans;
  work["pixels"] += w.pixels;
}

std::unique_ptr<Engine> make_halfspace_datapath_engine() {
  return make_datapath_engine<HalfspaceUnit>(
      [](const HalfspaceTriangleResult& r, std::map<std::string, uint64_t>& work) {
        add_hs_work(r.work, work);
      });
}

}  // namespace trirast
