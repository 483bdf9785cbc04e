// The second-generation improved unit's direct test of a tiny box (rtl/trirast_improved2.f; at most
// 2 x 2 pixel centres, Xmax <= 1 and Ymax <= 1), one cycle. From each edge's corner value E_L
// (bias included) and its steps a = A*u, b = B*u: the 12 sign tests E_L, E_L + a, E_L + b,
// E_L + a + b >= 0, a centre covered when all three edges pass, and per box row the span (a row of
// two centres is one run: a convex triangle) with x0, y0 added. Width W: 50 (EdgeBits, any
// triangle) or narrow (the corner values of g2_corner_narrow's narrow path).
module trirast_direct_test_2x2 #(
  parameter int W = trirast_pkg::EdgeBits
) (
  input  logic [3*W-1:0]                  el_i,
  input  logic [3*W-1:0]                  a_i,
  input  logic [3*W-1:0]                  b_i,
  input  logic                            xmax_i,   // Xmax (0 or 1)
  input  logic                            ymax_i,   // Ymax (0 or 1)
  input  logic [trirast_pkg::PixBits-1:0] x0_i,
  input  logic [trirast_pkg::PixBits-1:0] y0_i,
  output logic [1:0]                      valid_o,  // row j has a span
  output logic [2*trirast_pkg::PixBits-1:0] y_o,
  output logic [2*trirast_pkg::PixBits-1:0] xb_o,
  output logic [2*(trirast_pkg::PixBits+1)-1:0] xe_o
);
  localparam int PB = trirast_pkg::PixBits;
  logic [2:0] c00, c10, c01, c11;   // per edge: centre (i, j) passes
  for (genvar k = 0; k < 3; k++) begin : g_edge
    logic signed [W-1:0] e, a, b;
    logic signed [W+1:0] e10, e01, e11;
    assign e = el_i[k*W +: W];
    assign a = a_i[k*W +: W];
    assign b = b_i[k*W +: W];
    assign e10 = (W + 2)'(e) + (W + 2)'(a);
    assign e01 = (W + 2)'(e) + (W + 2)'(b);
    assign e11 = (W + 2)'(e) + (W + 2)'(a) + (W + 2)'(b);
    assign c00[k] = !e[W-1];
    assign c10[k] = !e10[W+1];
    assign c01[k] = !e01[W+1];
    assign c11[k] = !e11[W+1];
  end
  logic [1:0] row0, row1;   // covered centres of row j: bit i
  assign row0 = {(&c10) && xmax_i, &c00};
  assign row1 = {(&c11) && xmax_i && ymax_i, (&c01) && ymax_i};
  assign valid_o = {row1 != 2'b00, row0 != 2'b00};
  assign y_o  = {y0_i + 1'b1, y0_i};
  assign xb_o = {x0_i + PB'(!row1[0]), x0_i + PB'(!row0[0])};
  assign xe_o = {{1'b0, x0_i} + (PB + 1)'(row1[1] ? 2 : 1),
                 {1'b0, x0_i} + (PB + 1)'(row0[1] ? 2 : 1)};
endmodule
