// Stage 4 of the unit, `edge_walker` (x3): boundary traversal to the row where the edge enters
// the box, the entry x, then Bresenham stepping one row at a time with adders only
// (docs/unit.md, section 4). Per row the edge is out, bound at X', or clear.
#pragma once
#include <cstdint>

#include "improved/improved_adder_divider.hpp"
#include "improved/improved_edge_normalizer.hpp"
#include "common/unit_widths.hpp"

namespace trirast {

// What one edge says about the current row.
enum class EdgeRowState : uint8_t {
  Out,    // the row is empty
  Bound,  // the span is limited at X' (its end, or its begin when mirrored)
  Clear,  // the edge does not limit the row
};

// One edge's output to the span generator for the current row.
struct WalkerRow {
  EdgeRowState state;
  int64_t X;  // X' when Bound (Q + 2 signed), else don't care
};

// Work of one edge, for the timing model.
struct EdgeWork {
  uint64_t divisions = 0;           // divider uses: slope, entry row (divide mode), entry x
  uint64_t divider_iterations = 0;  // their iterations (Q each)
  uint64_t boundary_steps = 0;      // column steps of the boundary traversal (step mode)
  uint64_t rows_stepped = 0;        // Bresenham steps (rows moved while bound)
};

// The walker's registers, as the RTL holds them.
struct WalkerState {
  int64_t j;                 // current row (box-relative)
  EdgeRowState state;        // the current row's state
  int64_t X;                 // X' of the current row (when bound)
  int64_t e;                 // Bresenham error: X'*D + e = T + j*b, 0 <= e < D   (p + F unsigned)
  int64_t q_s, r_s;          // slope s / D: quotient (Q bits) and remainder (p + F bits)
  bool slope_saturated;      // s >= D * 2^Q: one step leaves the bound state
  bool enters;               // the edge enters the box at some row 0..Ymax
  int64_t j_entry;           // that row (Ymax + 1 when it never enters)
  EdgeRowState entry_state;  // the state at j_entry
  int64_t entry_X, entry_e;  // X' and e at j_entry (when entry_state is Bound)
};

class ImprovedEdgeWalker {
 public:
  ImprovedEdgeWalker(const RasterConfig& cfg, const ImprovedAdderDivider& divider);

  // Loads one normalized edge of a box (Xmax + 1) x (Ymax + 1): slope division, boundary
  // traversal (cfg.boundary), entry x. Afterwards the walker presents row 0.
  void start(const NormalizedEdge& n, int64_t Xmax, int64_t Ymax, uint32_t tri);
  // The current row's output.
  WalkerRow row() const { return WalkerRow{st_.state, st_.X}; }
  // Moves to the next row: the entry state at j_entry, a Bresenham step while bound.
  void advance();

  const WalkerState& state() const { return st_; }
  const EdgeWork& work() const { return work_; }

 private:
  // Fills j_entry/enters and returns the edge value at the entry row, column 0 (dir +) or
  // column Xmax (dir -).
  int64_t traverse_step();
  int64_t traverse_divide();
  // Sets entry_state / entry_X / entry_e from the entry-row value.
  void entry_x(int64_t value);
  // One Bresenham step of X' and e.
  void bresenham_step();
  // `along` says which box dimension bounds the quotient: 'x' (slope, entry x) or 'y' (entry
  // row); in DividerMode::Adaptive the division runs only the bits that dimension needs.
  DivideResult divide(int64_t n, int64_t d, const char* what, char along);

  RasterConfig cfg_;
  UnitWidths w_;
  const ImprovedAdderDivider& divider_;
  NormalizedEdge n_{};
  int64_t Xmax_ = 0, Ymax_ = 0;
  uint32_t tri_ = 0;
  WalkerState st_{};
  EdgeWork work_{};
};

}  // namespace trirast
