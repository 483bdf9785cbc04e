// Stage 2 set-up of one BresenhamLine (model/trad_bresenham.*), combinational: the line from
// pixel a to pixel b, drawn downward (b.y >= a.y: the vertices are sorted): x step direction,
// major axis (|dx| >= |dy|: x), the major and minor deltas and the classic initial decision
// variable D = 2*dmin - dmaj. Used x3 in the setup stage's StLine cycle.
`include "trirast_ports.svh"

module trirast_trad_line_setup (
  input  logic signed [trirast_pkg::CoordIntBits-1:0]  ax_i,
  input  logic signed [trirast_pkg::CoordIntBits-1:0]  ay_i,
  input  logic signed [trirast_pkg::CoordIntBits-1:0]  bx_i,
  input  logic signed [trirast_pkg::CoordIntBits-1:0]  by_i,
  output logic                                         sx_neg_o,   // x steps by -1
  output logic                                         x_major_o,  // |dx| >= |dy|
  output logic [trirast_pkg::CoordIntBits-1:0]         dmaj_o,     // steps of the line
  output logic [trirast_pkg::CoordIntBits-1:0]         dmin_o,
  output logic signed [trirast_pkg::CoordIntBits+2:0]  d0_o        // 2*dmin - dmaj
);
  `TRIRAST_PKG_NAMES
  localparam int DiffBits = CoordIntBits + 1;
  localparam int DecBits = CoordIntBits + 3;

  logic signed [DiffBits-1:0] dx, dy;
  logic [CoordIntBits-1:0] adx, ady;

  always_comb begin
    dx = DiffBits'(bx_i) - DiffBits'(ax_i);
    dy = DiffBits'(by_i) - DiffBits'(ay_i);
    // |dx| <= 2^c - 1 fits c bits unsigned; dy >= 0 (the line runs downward).
    adx = dx[DiffBits-1] ? CoordIntBits'(-dx) : CoordIntBits'(dx);
    ady = CoordIntBits'(dy);
  end

  assign sx_neg_o  = dx[DiffBits-1];
  assign x_major_o = adx >= ady;
  assign dmaj_o    = x_major_o ? adx : ady;
  assign dmin_o    = x_major_o ? ady : adx;
  assign d0_o      = DecBits'({dmin_o, 1'b0}) - DecBits'(dmaj_o);

  // dy's sign bit is always 0 here (sorted vertices).
  logic unused_dy_sign;
  assign unused_dy_sign = dy[DiffBits-1];

endmodule
