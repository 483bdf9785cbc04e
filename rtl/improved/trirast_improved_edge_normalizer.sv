// Stage 2, edge_normalizer (x3, combinational; docs/unit.md, section 2): turns a box-relative edge
// into the one form f(i', j) = T - i'*D + j*b >= 0 with D > 0 by mirroring x, and splits the
// signs off into flags, so the divider only sees non-negative numerators and positive divisors.
`include "trirast_ports.svh"

module trirast_improved_edge_normalizer (
  input  logic signed [trirast_pkg::CoefBits-1:0]  a_i,       // A (a = A*u)
  input  logic signed [trirast_pkg::CoefBits-1:0]  b_i,       // B (b = B*u)
  input  logic signed [trirast_pkg::EdgeBits-1:0]  el_i,      // E_L
  input  logic signed [trirast_pkg::EdgeBits-1:0]  er_i,      // E_R
  output logic                                     horiz_o,   // a == 0: no x bound
  output logic                                     mirror_o,  // a > 0: i' = Xmax - i
  output logic                                     dir_down_o,  // b >= 0
  output logic signed [trirast_pkg::EdgeBits-1:0]  t_o,       // f at i' = 0, row 0
  output logic signed [trirast_pkg::EdgeBits-1:0]  t1_o,      // f at i' = Xmax, row 0
  output logic [trirast_pkg::StepBits-1:0]         d_o,       // D = |a|
  output logic [trirast_pkg::StepBits-1:0]         s_o        // s = |b|
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES

  // |A| < 2^p, so |A|*u fits p + F bits.
  logic [CoefBits-1:0] abs_a, abs_b;

  assign abs_a      = a_i[CoefBits-1] ? CoefBits'(-a_i) : CoefBits'(a_i);
  assign abs_b      = b_i[CoefBits-1] ? CoefBits'(-b_i) : CoefBits'(b_i);
  assign horiz_o    = a_i == '0;
  assign mirror_o   = !a_i[CoefBits-1] && (a_i != '0);
  assign dir_down_o = !b_i[CoefBits-1];
  // Left edge (a > 0): mirrored, T = E_R, T1 = E_L. Right or horizontal: T = E_L, T1 = E_R.
  assign t_o        = mirror_o ? er_i : el_i;
  assign t1_o       = mirror_o ? el_i : er_i;
  assign d_o        = StepBits'(abs_a) << F;
  assign s_o        = StepBits'(abs_b) << F;

endmodule
