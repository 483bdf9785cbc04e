// The improved-Bresenham unit (docs/unit.md): the stages in hardware order, run for one
// triangle at a time, with the per-stage registers and work counters kept for comparison with
// the SystemC model and the RTL. make_improved_datapath_engine() wraps it as an Engine.
#pragma once
#include <cstdint>
#include <memory>

#include "common/engine.hpp"
#include "improved/improved_adder_divider.hpp"
#include "improved/improved_edge_normalizer.hpp"
#include "improved/improved_edge_walker.hpp"
#include "common/box_stage.hpp"
#include "improved/improved_span_generator.hpp"
#include "common/unit_widths.hpp"

namespace trirast {

// Work of one triangle: per edge, and per row for the span generator.
struct TriangleWork {
  EdgeWork edge[3];
  uint64_t rows_visited = 0;  // rows the walkers and the generator went through (Ymax + 1)
  uint64_t spans = 0;         // spans that left
  uint64_t pixels = 0;        // pixels in them

  uint64_t divisions() const;
  uint64_t divider_iterations() const;
  uint64_t boundary_steps() const;
  uint64_t rows_stepped() const;
};

// Everything the unit computed for one triangle, stage by stage.
struct UnitTriangleResult {
  BoxStageOut iface;           // stage 1 output
  NormalizedEdge norm[3];       // stage 2 outputs (valid when !iface.empty)
  WalkerState walker_entry[3];  // stage 4 registers after start() (row 0)
  TriangleWork work;
};

class ImprovedUnit {
 public:
  // Throws WidthError when the configuration's widths exceed what the 64-bit model holds.
  explicit ImprovedUnit(const RasterConfig& cfg);
  // Runs one set-up triangle through the stages, appending its spans in row order.
  UnitTriangleResult run_triangle(const TriangleSetup& t, SpanList& out);

  ImprovedUnit(const ImprovedUnit&) = delete;  // the walkers hold a reference to the divider
  ImprovedUnit& operator=(const ImprovedUnit&) = delete;

 private:
  RasterConfig cfg_;
  BoxStage interface_;
  ImprovedEdgeNormalizer normalizer_;
  ImprovedAdderDivider divider_;
  ImprovedEdgeWalker walker_[3];
};

// Adds one triangle's work into an engine's work map ("divider_iterations", "spans", ...).
void add_work(const TriangleWork& w, std::map<std::string, uint64_t>& work);

// The unit as an engine (register as "improved-datapath" in app/engines.cpp).
std::unique_ptr<Engine> make_improved_datapath_engine();

}  // namespace trirast
