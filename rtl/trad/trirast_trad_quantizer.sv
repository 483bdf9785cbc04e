// Stage 1 of the traditional-Bresenham unit, TradVertexQuantizer (model/trad_bresenham.*),
// combinational: each snapped vertex becomes its integer pixel floor(v / 2^F) (an arithmetic
// shift: the fraction is dropped), the integer area tells collinear pixels (the triangle draws
// nothing), and a three-comparator sorting network orders the pixels by (y, x): p0 top, p2
// bottom. Two (c+1) x (c+1) multipliers for the area, three comparators for the sort.
`include "trirast_ports.svh"

module trirast_trad_quantizer (
  input  logic [3*trirast_pkg::VertexBits-1:0]    vx_i,        // vertex k: [k*p +: p] signed
  input  logic [3*trirast_pkg::VertexBits-1:0]    vy_i,
  output logic                                    collinear_o, // integer area 0
  output logic [3*trirast_pkg::CoordIntBits-1:0]  px_o,        // sorted pixel k: [k*c +: c] signed
  output logic [3*trirast_pkg::CoordIntBits-1:0]  py_o
);
  `TRIRAST_PKG_NAMES
  localparam int DiffBits = CoordIntBits + 1;               // a difference of two pixels
  localparam int AreaBits = 2 * DiffBits + 1;        // the cross product

  logic signed [CoordIntBits-1:0] qx [3];
  logic signed [CoordIntBits-1:0] qy [3];

  // floor(v / 2^F): the upper bits of the two's-complement vertex.
  for (genvar k = 0; k < 3; k++) begin : g_quant
    assign qx[k] = vx_i[k*VertexBits + FracBits +: CoordIntBits];
    assign qy[k] = vy_i[k*VertexBits + FracBits +: CoordIntBits];
  end

  // Collinearity: (p1 - p0) x (p2 - p0) == 0 on the unsorted pixels, as the model computes it.
  logic signed [DiffBits-1:0] dx1, dy1, dx2, dy2;
  logic signed [AreaBits-1:0] area;
  always_comb begin
    dx1  = DiffBits'(qx[1]) - DiffBits'(qx[0]);
    dy1  = DiffBits'(qy[1]) - DiffBits'(qy[0]);
    dx2  = DiffBits'(qx[2]) - DiffBits'(qx[0]);
    dy2  = DiffBits'(qy[2]) - DiffBits'(qy[0]);
    area = AreaBits'(dx1) * AreaBits'(dy2) - AreaBits'(dy1) * AreaBits'(dx2);
  end
  assign collinear_o = area == '0;

  // (y, x) order: b strictly above a (smaller y, or equal y and smaller x).
  function automatic logic above(input logic signed [CoordIntBits-1:0] bx,
                                 input logic signed [CoordIntBits-1:0] by,
                                 input logic signed [CoordIntBits-1:0] ax,
                                 input logic signed [CoordIntBits-1:0] ay);
    above = (by < ay) || ((by == ay) && (bx < ax));
  endfunction

  // The network: (0,1), (1,2), (0,1). Each layer is its own set of wires (no reassignment, so
  // an event-driven simulator never sees a half-sorted intermediate as a final value).
  logic signed [CoordIntBits-1:0] ax [3];
  logic signed [CoordIntBits-1:0] ay [3];
  logic signed [CoordIntBits-1:0] bx [3];
  logic signed [CoordIntBits-1:0] by [3];
  logic signed [CoordIntBits-1:0] cx [3];
  logic signed [CoordIntBits-1:0] cy [3];
  logic swap_a, swap_b, swap_c;

  assign swap_a = above(qx[1], qy[1], qx[0], qy[0]);
  assign ax[0]  = swap_a ? qx[1] : qx[0];
  assign ay[0]  = swap_a ? qy[1] : qy[0];
  assign ax[1]  = swap_a ? qx[0] : qx[1];
  assign ay[1]  = swap_a ? qy[0] : qy[1];
  assign ax[2]  = qx[2];
  assign ay[2]  = qy[2];

  assign swap_b = above(ax[2], ay[2], ax[1], ay[1]);
  assign bx[0]  = ax[0];
  assign by[0]  = ay[0];
  assign bx[1]  = swap_b ? ax[2] : ax[1];
  assign by[1]  = swap_b ? ay[2] : ay[1];
  assign bx[2]  = swap_b ? ax[1] : ax[2];
  assign by[2]  = swap_b ? ay[1] : ay[2];

  assign swap_c = above(bx[1], by[1], bx[0], by[0]);
  assign cx[0]  = swap_c ? bx[1] : bx[0];
  assign cy[0]  = swap_c ? by[1] : by[0];
  assign cx[1]  = swap_c ? bx[0] : bx[1];
  assign cy[1]  = swap_c ? by[0] : by[1];
  assign cx[2]  = bx[2];
  assign cy[2]  = by[2];

  assign px_o = {cx[2], cx[1], cx[0]};
  assign py_o = {cy[2], cy[1], cy[0]};

  // The fraction bits do not matter after quantization (the integer bits are read above).
  logic unused_frac;
  assign unused_frac = ^{vx_i, vy_i};

endmodule
