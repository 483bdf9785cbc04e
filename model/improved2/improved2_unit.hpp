// The second-generation improved unit (docs/improved2.md, "Architecture"), bit-accurate, untimed:
// the unit's RTL rtl/improved2/trirast_improved2.f stage by stage.
//
//   [B] box stage: the box, clipped, and the empty test (gen1's interface computes the same box);
//       an empty box retires
//   [C] corner stage: vertex-relative E_L, E_R (Improved2CornerUnit; gen1's values)
//   [T] a box of at most 2 x 2 pixel centres: the direct test (Improved2DirectTest2x2), up to two spans
//   [L] otherwise three redesigned lanes (Improved2EdgeLane: their cycles; their results are gen1's
//       normalizer + lane's where the walker reads them, so gen1's ImprovedEdgeNormalizer and ImprovedEdgeWalker
//       give them)
//   [W] the walk stage, one row per step: gen1's walkers and span generator (the retimed walkers
//       and the parallel span generator give the same rows), or the direct test's row spans
//
// The unit is built for boundary mode step and the adaptive divider only: the gen1 options
// --boundary, --divider (and the sweep's quotient truncation) do not apply to it.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "common/engine.hpp"
#include "improved/improved_adder_divider.hpp"
#include "improved2/improved2_corner_unit.hpp"
#include "improved2/improved2_direct_test_2x2.hpp"
#include "improved/improved_edge_normalizer.hpp"
#include "improved/improved_edge_walker.hpp"
#include "improved2/improved2_edge_lane.hpp"
#include "common/box_stage.hpp"
#include "improved/improved_span_generator.hpp"

namespace trirast {

// One row of a walked job: its box-relative row and, when valid, its span.
struct Improved2Row {
  int64_t row;
  bool valid;
  Span span;
};

// Everything the gen2 unit computed for one triangle.
struct Improved2Triangle {
  BoxStageOut box;                // B and C: the box, E_L, E_R
  bool tiny = false;               // the direct 2x2 test took it (no lanes)
  int corner_digits_l = 0;         // digit-serial corner unit: run length for E_L (at x0)
  int corner_digits_r = 0;         // and for E_R (at x0 + Xmax; lane boxes only)
  Improved2LaneWork lane[3];            // lane boxes: each lane's work and cycles
  uint64_t lane_cycles = 0;        // max of the three lanes' cycles
  std::vector<Improved2Row> rows;  // the rows the walk stage goes through, in order
  uint64_t spans = 0, pixels = 0, rows_stepped = 0;
};

class Improved2Unit {
 public:
  // Throws WidthError when the configuration's widths exceed what the 64-bit model holds.
  explicit Improved2Unit(const RasterConfig& cfg);
  // Runs one set-up triangle through the stages into r (r.rows reused between calls).
  void run_triangle(const TriangleSetup& t, Improved2Triangle& r);

  Improved2Unit(const Improved2Unit&) = delete;  // the walkers hold a reference to the divider
  Improved2Unit& operator=(const Improved2Unit&) = delete;

  // The configuration of the gen1 parts the unit reuses: step, adaptive, no truncation.
  static RasterConfig gen2_config(const RasterConfig& cfg);

 private:
  RasterConfig cfg_;
  BoxStage box_stage_;
  Improved2CornerUnit corner_;
  ImprovedEdgeNormalizer normalizer_;
  ImprovedAdderDivider divider_;
  ImprovedEdgeWalker walker_[3];
};

// The unit as an engine (register as "improved2-datapath" in app/engines.cpp).
std::unique_ptr<Engine> make_improved2_datapath_engine();

}  // namespace trirast
