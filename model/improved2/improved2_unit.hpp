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
  // cross_check: per triangle, compare the gen2 parts with gen1's, which compute the same values
  // (std::logic_error on a difference, a model bug): the corner stage's E_L, E_R with the box
  // stage's, and each lane's own traversal (Improved2EdgeLane::traverse) with gen1's walker's
  // steps and entry. Without it the lanes' cycles take the walker's steps
  // (Improved2EdgeLane::from_traversal) and the corner values are the box stage's: the same
  // results whenever the check would pass. The untimed engine improved2-datapath (and so
  // test_improved2_unit's scenes) runs with it; the SystemC model improved2-sc without it
  // unless TRIRAST_IMPROVED2_CHECK=1 is set in the environment (improved2_sc.cpp).
  explicit Improved2Unit(const RasterConfig& cfg, bool cross_check = true);
  // Runs one set-up triangle through the stages into r (r.rows reused between calls):
  // set_up(), then every walk_row() of a lane job into r.rows, and r.rows_stepped.
  void run_triangle(const TriangleSetup& t, Improved2Triangle& r);
  // B, C and L (or T: a tiny job's rows into r.rows; a lane job's r.rows is left empty).
  void set_up(const TriangleSetup& t, Improved2Triangle& r);
  // Row j of the lane job set up last (j = 0, 1, .., Ymax, in order): the span generator on the
  // walkers' rows, which then step to row j + 1; counts r.spans and r.pixels.
  Improved2Row walk_row(const TriangleSetup& t, Improved2Triangle& r, int64_t j);

  Improved2Unit(const Improved2Unit&) = delete;  // the walkers hold a reference to the divider
  Improved2Unit& operator=(const Improved2Unit&) = delete;

  // The configuration of the gen1 parts the unit reuses: step, adaptive, no truncation.
  static RasterConfig gen2_config(const RasterConfig& cfg);

 private:
  RasterConfig cfg_;
  bool cross_check_;
  NormalizedEdge norm_[3];
  BoxStage box_stage_;
  Improved2CornerUnit corner_;
  ImprovedEdgeNormalizer normalizer_;
  ImprovedAdderDivider divider_;
  ImprovedEdgeWalker walker_[3];
};

// The unit as an engine (register as "improved2-datapath" in app/engines.cpp).
std::unique_ptr<Engine> make_improved2_datapath_engine();

}  // namespace trirast
