#include "improved/improved_edge_walker.hpp"

#include <algorithm>

#include "common/fixed_point.hpp"

namespace trirast {

ImprovedEdgeWalker::ImprovedEdgeWalker(const RasterConfig& cfg, const ImprovedAdderDivider& divider)
    : cfg_(cfg), w_(unit_widths(cfg)), divider_(divider) {}

DivideResult ImprovedEdgeWalker::divide(int64_t n, int64_t d, const char* what, char along) {
  // Adaptive: a quotient of 2^bits > the box's extent already means "beyond the box", so
  // bits(extent) + 1 quotient bits give the same result as the full Q (docs/unit.md, section 3).
  int bits = 0;
  if (cfg_.divider == DividerMode::Adaptive)
    bits = unsigned_bits(uint64_t(along == 'x' ? Xmax_ : Ymax_)) + 1;
  // Truncation: a K-bit divider saturates above 2^K - 1 (inexact unless the box fits K bits).
  const int cap = cfg_.divider_quotient_bits;
  if (cap > 0 && (bits == 0 || bits > cap)) bits = std::min(cap, divider_.quotient_bits());
  const DivideResult r = divider_.divide(n, d, tri_, what, bits);
  ++work_.divisions;
  work_.divider_iterations += uint64_t(r.iterations);
  return r;
}

void ImprovedEdgeWalker::start(const NormalizedEdge& n, int64_t Xmax, int64_t Ymax, uint32_t tri) {
  // Load the edge and clear the registers and counters.
  n_ = n;
  Xmax_ = Xmax;
  Ymax_ = Ymax;
  tri_ = tri;
  st_ = WalkerState{};
  work_ = EdgeWork{};
  // 1. Slope s / D (not for a horizontal edge: it has no x bound to step).
  if (!n_.horizontal) {
    const DivideResult slope = divide(n_.s, n_.D, "slope s", 'x');
    st_.q_s = slope.quotient;
    st_.r_s = slope.remainder;
    st_.slope_saturated = slope.saturated;
  }
  // 2. Boundary traversal: the entry row and the edge value on the box's side column there.
  const int64_t value = cfg_.boundary == BoundaryMode::Step ? traverse_step() : traverse_divide();
  // 3. Entry x at the entry row.
  if (st_.enters) entry_x(value);
  // Row 0: before the entry the edge is out (dir +) or clear (dir -).
  const EdgeRowState before = n_.dir_down ? EdgeRowState::Out : EdgeRowState::Clear;
  st_.j = 0;
  st_.state = before;
  if (st_.enters && st_.j_entry == 0) {
    st_.state = st_.entry_state;
    st_.X = st_.entry_X;
    st_.e = st_.entry_e;
  }
}

int64_t ImprovedEdgeWalker::traverse_step() {
  // dir +: column i' = 0 from T, adding s, until f >= 0.
  // dir -: column i' = Xmax from T1, subtracting s, until f < 0.
  int64_t v = n_.dir_down ? n_.T : n_.T1;
  auto entered = [&](int64_t f) { return n_.dir_down ? f >= 0 : f < 0; };
  int64_t j = 0;
  while (!entered(v) && j <= Ymax_) {  // at most Ymax + 1 steps
    v = n_.dir_down ? v + n_.s : v - n_.s;
    check_signed(v, w_.edge_value, tri_, "boundary value", "edge value");
    ++j;
    ++work_.boundary_steps;
  }
  st_.enters = j <= Ymax_;
  st_.j_entry = j;
  return v;
}

int64_t ImprovedEdgeWalker::traverse_divide() {
  st_.enters = false;
  st_.j_entry = Ymax_ + 1;
  int64_t j = 0, v = 0;
  if (n_.dir_down) {
    if (n_.T >= 0) {
      j = 0;  // inside at row 0
      v = n_.T;
    } else {
      if (n_.s == 0) return 0;  // vertical and outside: never enters
      // First j with T + j*s >= 0: -T = q*s + r, j = q + (r != 0).
      const DivideResult d = divide(-n_.T, n_.s, "entry row -T", 'y');
      if (d.saturated) return 0;
      j = d.quotient + (d.remainder != 0 ? 1 : 0);
      v = d.remainder == 0 ? 0 : n_.s - d.remainder;
    }
  } else {
    if (n_.T1 < 0) {
      j = 0;  // already past the far column at row 0
      v = n_.T1;
    } else {
      if (n_.s == 0) return 0;  // cannot happen for dir -, kept for safety
      // First j with T1 - j*s < 0: T1 = q*s + r, j = q + 1, value r - s.
      const DivideResult d = divide(n_.T1, n_.s, "entry row T1", 'y');
      if (d.saturated) return 0;
      j = d.quotient + 1;
      v = d.remainder - n_.s;
    }
  }
  if (j > Ymax_) return 0;  // enters below the box
  st_.enters = true;
  st_.j_entry = j;
  return v;
}

void ImprovedEdgeWalker::entry_x(int64_t value) {
  check_unsigned(st_.j_entry, w_.box, tri_, "entry row", "box-relative coordinate");
  // A horizontal edge has no bound: past its entry it is clear (dir +) or out (dir -).
  if (n_.horizontal) {
    st_.entry_state = n_.dir_down ? EdgeRowState::Clear : EdgeRowState::Out;
    return;
  }
  if (n_.dir_down) {
    // dir +: N >= 0 on column 0; X' = floor(N / D), e = N mod D.
    const DivideResult d = divide(value, n_.D, "entry x N", 'x');
    if (d.saturated) {
      st_.entry_state = EdgeRowState::Clear;  // beyond the box: already clear
      return;
    }
    st_.entry_X = d.quotient;
    st_.entry_e = d.remainder;
    st_.entry_state = st_.entry_X >= Xmax_ ? EdgeRowState::Clear : EdgeRowState::Bound;
  } else {
    // dir -: G < 0 on column Xmax; X'' = floor(G / D) by dividing -G and restoring the sign.
    const DivideResult d = divide(-value, n_.D, "entry x -G", 'x');
    if (d.saturated) {
      st_.entry_state = EdgeRowState::Out;  // far beyond the box's left: already out
      return;
    }
    const bool carry = d.remainder != 0;
    const int64_t Xpp = -d.quotient - (carry ? 1 : 0);
    st_.entry_e = carry ? n_.D - d.remainder : 0;
    st_.entry_X = Xmax_ + Xpp;
    st_.entry_state = st_.entry_X < 0 ? EdgeRowState::Out : EdgeRowState::Bound;
  }
  check_signed(st_.entry_X, w_.walker_x, tri_, "entry X'", "walker bound");
  check_unsigned(st_.entry_e, w_.remainder, tri_, "entry e", "Bresenham error");
}

void ImprovedEdgeWalker::advance() {
  ++st_.j;
  if (st_.enters && st_.j == st_.j_entry) {
    // The entry row: load the entry state.
    st_.state = st_.entry_state;
    st_.X = st_.entry_X;
    st_.e = st_.entry_e;
  } else if (st_.state == EdgeRowState::Bound) {
    bresenham_step();  // only bound edges move; out and clear are final past the entry
  }
}

void ImprovedEdgeWalker::bresenham_step() {
  ++work_.rows_stepped;
  if (n_.dir_down) {
    // dir +: X' += q_s, e += r_s, carry one when e reaches D; clear once X' >= Xmax.
    if (st_.slope_saturated) {
      st_.state = EdgeRowState::Clear;
      return;
    }
    st_.X += st_.q_s;
    st_.e += st_.r_s;
    if (st_.e >= n_.D) {
      st_.e -= n_.D;
      st_.X += 1;
    }
    if (st_.X >= Xmax_) st_.state = EdgeRowState::Clear;
  } else {
    // dir -: X' -= q_s, e -= r_s, borrow one when e goes negative; out once X' < 0.
    if (st_.slope_saturated) {
      st_.state = EdgeRowState::Out;
      return;
    }
    st_.X -= st_.q_s;
    st_.e -= st_.r_s;
    if (st_.e < 0) {
      st_.e += n_.D;
      st_.X -= 1;
    }
    if (st_.X < 0) st_.state = EdgeRowState::Out;
  }
  check_signed(st_.X, w_.walker_x, tri_, "X'", "walker bound");
  check_unsigned(st_.e, w_.remainder, tri_, "e", "Bresenham error");
}

}  // namespace trirast
