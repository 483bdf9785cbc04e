// The half-space unit, stage 2: the tile walker. It walks the box in bands of U rows (U = T, or S
// without tiles) and each band in units of U x U pixels (docs/unit.md, "The half-space unit"),
// one unit test per cycle: the edge values at the unit's four corner pixel centres (the unit
// unclipped, so every unit of a band has the same shape) reject it (all four outside one edge),
// accept it (all inside every edge: a tile only) or leave it partial (its stamps are tested).
// Row walk: every unit, left to right. Zig-zag walk: even bands left to right, odd bands right to
// left; the first unit rejected after a unit that was not ends the band (the units a band does
// not reject are contiguous, so the rest of the band is rejected). Forward walk: every band left
// to right, with the zig-zag walk's early band end.
#pragma once
#include <cstdint>

#include "halfspace/halfspace_setup.hpp"

namespace trirast {

enum class HalfspaceClass { Reject, Accept, Partial };

// A unit test's outcome, and which edges hold all four of the unit's corners inside them (bit k:
// edge k), which a partial tile's stamps mask (HalfspaceStampTester::test).
struct HalfspaceUnitTest {
  HalfspaceClass cls;
  unsigned edges_inside;
};

class HalfspaceTileWalker {
 public:
  HalfspaceTileWalker(const RasterConfig& cfg);
  // Corner test of the U x U unit at box pixel (i0, j0). Tiles may accept; stamps never do
  // (a stamp's pixels are tested one by one).
  HalfspaceUnitTest classify(const HalfspaceSetupOut& s, int64_t i0, int64_t j0) const;

  // Band `band` runs right to left (zig-zag's odd bands).
  bool backward(int64_t band) const { return p_.walk == HalfspaceWalk::Zigzag && (band & 1); }
  // Walks band `band` of s: calls visit(i0, j0, test) for each unit tested, in order; returns
  // the number of units tested.
  template <class Visit>
  int64_t walk_band(const HalfspaceSetupOut& s, int64_t band, Visit&& visit) const {
    const int64_t U = p_.unit();
    const int64_t j0 = band * U;
    const bool early_end = p_.walk != HalfspaceWalk::Row;
    const bool back = backward(band);
    bool seen = false;
    int64_t tested = 0;
    for (int64_t n = 0; n < s.units; ++n) {
      const int64_t col = back ? s.units - 1 - n : n;
      const HalfspaceUnitTest t = classify(s, col * U, j0);
      ++tested;
      visit(col * U, j0, t);
      if (t.cls != HalfspaceClass::Reject) {
        seen = true;
      } else if (early_end && seen) {
        break;
      }
    }
    return tested;
  }

 private:
  HalfspaceParams p_;
  UnitWidths w_;
};

}  // namespace trirast
