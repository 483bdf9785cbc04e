// The second-generation improved unit's direct test of a tiny box (rtl/improved2/trirast_improved2.f; at most
// 2 x 2 pixel centres, Xmax <= 1 and Ymax <= 1), one cycle. From each edge's corner value E_L
// (bias included) and its steps a = A*u, b = B*u and their sum ab = a + b (given, so that no sum
// waits for another): the 12 sign tests E_L, E_L + a, E_L + b, E_L + ab >= 0, a centre covered
// when all three edges pass, and per box row the span (a row of
// two centres is one run: a convex triangle) with x0, y0 added. Width W: 50 (EdgeBits, any
// triangle) or narrower (trirast_improved2_top's TestHi: E_L >> F, with SW below).
// SW (0: W): the signed bits that hold a and b (|a|, |b| < 2^(SW-1), |ab| < 2^SW). With SW + 5 < W
// each sign is taken from SW + 5 low bits of E_L instead of all W, and E_L's high bits are not
// read: the caller says per edge whether E_L is far from 0 (far_i: |E_L| >= 2^SW, so that no x
// changes its sign, which is fneg_i), and otherwise |E_L| < 2^(SW+3), so that E_L + x fits SW + 5
// signed bits. (The unit's corner unit knows that from its accumulator before E_L's carry chain
// ends.)
`include "trirast_ports.svh"

module trirast_improved2_direct_test_2x2 #(
  parameter int W  = trirast_pkg::EdgeBits,
  parameter int SW = 0
) (
  input  logic [3*W-1:0]                  el_i,
  input  logic [3*W-1:0]                  a_i,
  input  logic [3*W-1:0]                  b_i,
  input  logic [3*W-1:0]                  ab_i,     // a + b
  input  logic [2:0]                      far_i,    // split form: |E_L| >= 2^SW (else < 2^(SW+3))
  input  logic [2:0]                      fneg_i,   // ... and E_L < 0
  input  logic                            xmax_i,   // Xmax (0 or 1)
  input  logic                            ymax_i,   // Ymax (0 or 1)
  input  logic [trirast_pkg::PixBits-1:0] x0_i,
  input  logic [trirast_pkg::PixBits-1:0] y0_i,
  output logic [1:0]                      valid_o,  // row j has a span
  output logic [2*trirast_pkg::PixBits-1:0] y_o,
  output logic [2*trirast_pkg::PixBits-1:0] xb_o,
  output logic [2*(trirast_pkg::PixBits+1)-1:0] xe_o
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  logic [2:0] c00, c10, c01, c11;   // per edge: centre (i, j) passes
  for (genvar k = 0; k < 3; k++) begin : g_edge
    logic signed [W-1:0] e, a, b, ab;
    assign e = el_i[k*W +: W];
    assign a = a_i[k*W +: W];
    assign b = b_i[k*W +: W];
    assign ab = ab_i[k*W +: W];
    if (SW != 0 && SW + 5 < W) begin : g_split
      localparam int LW = SW + 5;
      logic signed [LW-1:0] el, t10, t01, t11;
      assign el  = e[LW-1:0];
      assign t10 = el + LW'(a);
      assign t01 = el + LW'(b);
      assign t11 = el + LW'(ab);
      assign c00[k] = far_i[k] ? !fneg_i[k] : !el[LW-1];
      assign c10[k] = far_i[k] ? !fneg_i[k] : !t10[LW-1];
      assign c01[k] = far_i[k] ? !fneg_i[k] : !t01[LW-1];
      assign c11[k] = far_i[k] ? !fneg_i[k] : !t11[LW-1];
      logic unused_hi;   // E_L's high bits; a, b and ab are SW-bit values sign-extended to W
      assign unused_hi = ^{e[W-1:LW], a[W-1:LW], b[W-1:LW], ab[W-1:LW]};
    end else begin : g_full
      assign c00[k] = !e[W-1];
      logic unused_far;   // the split form's
      assign unused_far = ^{far_i[k], fneg_i[k]};
      logic signed [W+1:0] e10, e01, e11;
      assign e10 = (W + 2)'(e) + (W + 2)'(a);
      assign e01 = (W + 2)'(e) + (W + 2)'(b);
      assign e11 = (W + 2)'(e) + (W + 2)'(ab);
      assign c10[k] = !e10[W+1];
      assign c01[k] = !e01[W+1];
      assign c11[k] = !e11[W+1];
    end
  end
  logic [1:0] row0, row1;   // covered centres of row j: bit i
  assign row0 = {(&c10) && xmax_i, &c00};
  assign row1 = {(&c11) && xmax_i && ymax_i, (&c01) && ymax_i};
  assign valid_o = {row1 != 2'b00, row0 != 2'b00};
  assign y_o  = {y0_i + 1'b1, y0_i};
  assign xb_o = {x0_i + PB'(!row1[0]), x0_i + PB'(!row0[0])};
  // Each element's constant sized as a whole: Yosys 0.23 reads (PB + 1)'(c ? 2 : 1) inside a
  // concatenation as 0 (docs/formal.md, "Yosys 0.23's reading of size casts").
  assign xe_o = {{1'b0, x0_i} + (row1[1] ? (PB + 1)'(2) : (PB + 1)'(1)),
                 {1'b0, x0_i} + (row0[1] ? (PB + 1)'(2) : (PB + 1)'(1))};
endmodule
