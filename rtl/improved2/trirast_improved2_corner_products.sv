// The second-generation improved unit's corner unit, CornerForm 0 (rtl/improved2/trirast_improved2.f, the
// xc7 form): vertex-relative E_L with full-width
// products written as `*`, one cycle (combinational; the wrapper registers both sides): the
// form for devices with multipliers (xc7 maps each 25 x 26 product onto DSP48E1 slices).
//   E_L = A*(cx0 - vx) + B*(cy0 - vy) - bias   per edge (no C: E vanishes at the edge's vertex),
// or, for an edge whose x1sel_i bit is set, the same at the column x1_i (E_R for x1 = x0 + Xmax).
`include "trirast_ports.svh"

module trirast_improved2_corner_products (
  input  logic [3*trirast_pkg::VertexBits-1:0] vx_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] vy_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]   a_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]   b_i,
  input  logic [2:0]                           bias_i,
  input  logic [trirast_pkg::PixBits-1:0]      x0_i,
  input  logic [trirast_pkg::PixBits-1:0]      x1_i,
  input  logic [2:0]                           x1sel_i,   // per edge: the value at x1_i
  input  logic [trirast_pkg::PixBits-1:0]      y0_i,
  output logic [3*trirast_pkg::EdgeBits-1:0]   el_o
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  localparam int DW = P + 2;

  logic signed [DW-1:0] cx0, cx1, cy;
  assign cx0 = $signed(DW'({x0_i, 1'b1}) << (F - 1));
  assign cx1 = $signed(DW'({x1_i, 1'b1}) << (F - 1));
  assign cy = $signed(DW'({y0_i, 1'b1}) << (F - 1));
  for (genvar k = 0; k < 3; k++) begin : g_edge
    logic signed [DW-1:0] dx, dy;
    logic signed [CB-1:0] ak, bk;
    logic signed [EB-1:0] px, py;
    assign dx = (x1sel_i[k] ? cx1 : cx0) - DW'($signed(vx_i[k*P +: P]));
    assign dy = cy - DW'($signed(vy_i[k*P +: P]));
    assign ak = $signed(a_i[k*CB +: CB]);
    assign bk = $signed(b_i[k*CB +: CB]);
    assign px = EB'(ak * dx);
    assign py = EB'(bk * dy);
    assign el_o[k*EB +: EB] = px + py - EB'(bias_i[k]);
  end
endmodule
