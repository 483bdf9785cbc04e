// gen2 study prototype (not a unit; scripts/gen2_study.sh): vertex-relative corner values with
// narrow multipliers, one cycle (combinational; the study's wrapper registers both sides).
// Edge k's function vanishes at its own vertex v_k, so E(c) = A*(cx - vx) + B*(cy - vy) needs
// neither C nor the screen position: for a non-empty box every box pixel centre lies inside the
// vertices' extent, so |cx - vx| and |A| = |dy of the edge| are both below the triangle's extent
// (subpixels). With NarrowBits = N signed bits, triangles whose extent is below 2^(N-1) subpixels
// (N = 13, F = 8: 16 pixels) take this path; fits_o = 0 says the operands do not fit (a big
// triangle), and the unit would use its multi-cycle fallback (g2_corner_digit) instead.
//   E_L = A*(cx0 - vx) + B*(cy0 - vy) - bias,   E_R = E_L + (A*Xmax) << F  (Xmax < 2^(N-1-F)).
module g2_corner_narrow #(
  parameter int NarrowBits = 13
) (
  input  logic [3*trirast_pkg::VertexBits-1:0] vx_i,    // reference vertex of edge k
  input  logic [3*trirast_pkg::VertexBits-1:0] vy_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]   a_i,     // A of edge k (signed)
  input  logic [3*trirast_pkg::CoefBits-1:0]   b_i,     // B of edge k (signed)
  input  logic [2:0]                           bias_i,  // 1 = bias -1
  input  logic [trirast_pkg::PixBits-1:0]      x0_i,
  input  logic [trirast_pkg::PixBits-1:0]      y0_i,
  input  logic [trirast_pkg::BoxBits-1:0]      xmax_i,
  output logic                                 fits_o,  // all operands narrow: el_o/er_o valid
  output logic [3*trirast_pkg::EdgeBits-1:0]   el_o,
  output logic [3*trirast_pkg::EdgeBits-1:0]   er_o
);
  localparam int F = trirast_pkg::FracBits;
  localparam int P = trirast_pkg::VertexBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int PB = trirast_pkg::PixBits;
  localparam int BB = trirast_pkg::BoxBits;
  localparam int NW = NarrowBits;
  localparam int DW = P + 2;              // cx - vx, signed
  localparam int XW = NW - 1 - F;         // unsigned bits of a narrow Xmax
  localparam int PW = 2 * NW + 2;         // E_L, E_R of a narrow triangle

  function automatic logic fits_s(input logic [DW-1:0] v);  // v (signed DW) fits NW signed
    fits_s = (v[DW-1:NW-1] == '0) || (v[DW-1:NW-1] == '1);
  endfunction

  logic signed [DW-1:0] cx, cy;
  assign cx = $signed(DW'({x0_i, 1'b1, (F - 1)'(0)}));
  assign cy = $signed(DW'({y0_i, 1'b1, (F - 1)'(0)}));

  logic [2:0] fit_k;
  for (genvar k = 0; k < 3; k++) begin : g_edge
    logic signed [DW-1:0] dx, dy, ae, be;
    logic signed [NW-1:0] an, bn, dxn, dyn;
    logic signed [XW:0] xm;
    logic signed [PW-1:0] el, er;
    assign dx = cx - DW'($signed(vx_i[k*P +: P]));
    assign dy = cy - DW'($signed(vy_i[k*P +: P]));
    assign ae = DW'($signed(a_i[k*CB +: CB]));
    assign be = DW'($signed(b_i[k*CB +: CB]));
    assign fit_k[k] = fits_s(dx) && fits_s(dy) && fits_s(ae) && fits_s(be);
    assign an  = ae[NW-1:0];
    assign bn  = be[NW-1:0];
    assign dxn = dx[NW-1:0];
    assign dyn = dy[NW-1:0];
    assign xm  = $signed({1'b0, xmax_i[XW-1:0]});
    assign el = PW'(an * dxn) + PW'(bn * dyn) - PW'(bias_i[k]);
    assign er = el + (PW'(an * xm) <<< F);
    assign el_o[k*EB +: EB] = EB'(el);
    assign er_o[k*EB +: EB] = EB'(er);
  end
  assign fits_o = (&fit_k) && (xmax_i[BB-1:XW] == '0);

endmodule
