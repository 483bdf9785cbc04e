// The second-generation improved unit's direct test of a tiny box (rtl/trirast_improved2.f; at most
// 2 x 2 pixel centres, Xmax <= 1 and Ymax <= 1), one cycle. From each edge's corner value E_L
// (bias included) and its steps a = A*u, b = B*u: the 12 sign tests E_L, E_L + a, E_L + b,
// E_L + a + b >= 0, a centre covered when all three edges pass, and per box row the span (a row of
// two centres is one run: a convex triangle) with x0, y0 added. Width W: 50 (EdgeBits, any
// triangle) or narrow (the corner values of g2_corner_narrow's narrow path).
// SW (0: W): the signed bits that hold a and b (|a|, |b| < 2^(SW-1)). With SW + 2 < W each sum's
// sign is taken from SW + 2 bits instead of W + 2: E_L = h * 2^SW + l (l its SW low bits,
// unsigned), t = l + x for x = a, b, a + b lies in (-2^SW, 2^(SW+1)), and E_L + x = (h + c) * 2^SW
// + (t mod 2^SW) with c = floor(t / 2^SW) in {-1, 0, 1}; so E_L + x < 0 exactly when h <= -2, or
// h = 0 and t < 0, or h = -1 and t < 2^SW (two equality tests of h, shared by the three sums).
module trirast_direct_test_2x2 #(
  parameter int W  = trirast_pkg::EdgeBits,
  parameter int SW = 0
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
    assign e = el_i[k*W +: W];
    assign a = a_i[k*W +: W];
    assign b = b_i[k*W +: W];
    assign c00[k] = !e[W-1];
    if (SW != 0 && SW + 2 < W) begin : g_split
      logic [W-SW-1:0] h;
      logic signed [SW+1:0] t10, t01, t11;
      logic h0, hm1;
      assign h   = e[W-1:SW];
      assign h0  = h == '0;
      assign hm1 = &h;
      assign t10 = $signed({2'b00, e[SW-1:0]}) + (SW + 2)'(a);
      assign t01 = $signed({2'b00, e[SW-1:0]}) + (SW + 2)'(b);
      assign t11 = t10 + (SW + 2)'(b);
      // E_L + x < 0 from t = l + x (SW + 2 bits) and h (see the header)
      function automatic logic below_zero(input logic signed [SW+1:0] t);
        below_zero = h0 ? t[SW+1] : hm1 ? (t[SW+1] || !t[SW]) : h[W-SW-1];
      endfunction
      assign c10[k] = !below_zero(t10);
      assign c01[k] = !below_zero(t01);
      assign c11[k] = !below_zero(t11);
      logic unused_hi;   // a and b are SW-bit values sign-extended to W
      assign unused_hi = ^{a[W-1:SW+2], b[W-1:SW+2]};
    end else begin : g_full
      logic signed [W+1:0] e10, e01, e11;
      assign e10 = (W + 2)'(e) + (W + 2)'(a);
      assign e01 = (W + 2)'(e) + (W + 2)'(b);
      assign e11 = (W + 2)'(e) + (W + 2)'(a) + (W + 2)'(b);
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
  assign xe_o = {{1'b0, x0_i} + (PB + 1)'(row1[1] ? 2 : 1),
                 {1'b0, x0_i} + (PB + 1)'(row0[1] ? 2 : 1)};
endmodule
