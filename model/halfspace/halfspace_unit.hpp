// The half-space (Pineda edge-function) tile rasterizer unit (docs/unit.md, "The half-space
// unit"): box and edge setup at the box corner, the tile walker, the stamp tester and the span
// emitter, run for one triangle at a time. It also reports what the timed views need per band:
// the walker's cycles (one per unit test plus one per stamp of a partial tile) and the band's
// span count. make_halfspace_datapath_engine() wraps it as the untimed engine "halfspace-datapath".
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/engine.hpp"
#include "halfspace/halfspace_setup.hpp"
#include "halfspace/halfspace_span_emitter.hpp"
#include "halfspace/halfspace_stamp_tester.hpp"
#include "halfspace/halfspace_tile_walker.hpp"

namespace trirast {

struct HalfspaceBand {
  uint64_t cycles = 0;  // walker cycles: unit tests + stamps of partial tiles (>= 1)
  uint64_t spans = 0;   // spans the band emits (rows with coverage)
};

struct HalfspaceWork {
  uint64_t units_tested = 0, rejected = 0, accepted = 0, partial = 0;
  uint64_t stamps = 0, spans = 0, pixels = 0, bands = 0;

  HalfspaceWork& operator+=(const HalfspaceWork& o) {
    units_tested += o.units_tested;
    rejected += o.rejected;
    accepted += o.accepted;
    partial += o.partial;
    stamps += o.stamps;
    spans += o.spans;
    pixels += o.pixels;
    bands += o.bands;
    return *this;
  }
};

struct HalfspaceTriangleResult {
  HalfspaceSetupOut setup;
  std::vector<HalfspaceBand> bands;  // empty when the box is empty
  HalfspaceWork work;
};

class HalfspaceUnit {
 public:
  explicit HalfspaceUnit(const RasterConfig& cfg);
  // Runs one set-up triangle, appending its spans in row order.
  HalfspaceTriangleResult run_triangle(const TriangleSetup& t, SpanList& out);
  // The two halves the timed views run in different stages: the setup stage's box and edge
  // setup, and the walk stage's tile walker, stamp tester and span emitter (res.setup set).
  HalfspaceSetupOut set_up(const TriangleSetup& t) const { return setup_.run(t); }
  void walk(HalfspaceTriangleResult& res, SpanList& out);

 private:
  HalfspaceParams p_;
  HalfspaceSetupStage setup_;
  HalfspaceTileWalker walker_;
  HalfspaceStampTester tester_;
  HalfspaceSpanEmitter emitter_;
};

// Adds one triangle's work into an engine's work map ("hs_units_tested", "spans", ...).
void add_hs_work(const HalfspaceWork& w, std::map<std::string, uint64_t>& work);

std::unique_ptr<Engine> make_halfspace_datapath_engine();

}  // namespace trirast
