// One Bresenham walker of the traditional unit's walk stage (BresenhamLine::step of
// model/trad_bresenham.*): one step, i.e. one pixel, per cycle along the major axis; the
// minor axis moves when the decision variable D > 0, then D += 2*dmin - (moved ? 2*dmaj : 0).
// Lines run downward, so a step moves y by 0 or +1.
//
// The walk stage works row by row: has_step_o says the line still has a step and that step lands
// on row row_i; more_o says the same of the state after this cycle (its step or load applied), so
// the stage knows combinationally whether the row ends in this cycle. Used x2: the long-edge
// walker (p0->p2) and the short-side walker (p0->p1, reloaded with p1->p2 by the walk stage in
// the cycle of the first line's last step, so no cycle is lost between the two).
`include "trirast_ports.svh"

module trirast_trad_walker #(
  parameter int WBits = 18  // signed bits of a pixel coordinate and of the row
) (
  input  logic                                        clk_i,
  // ---- load a line: its start pixel and BresenhamLine::start's state ----
  input  logic                                        load_i,
  input  logic signed [trirast_pkg::CoordIntBits-1:0] load_x_i,
  input  logic signed [trirast_pkg::CoordIntBits-1:0] load_y_i,
  input  logic                                        load_sx_neg_i,
  input  logic                                        load_x_major_i,
  input  logic [trirast_pkg::CoordIntBits-1:0]        load_dmaj_i,
  input  logic [trirast_pkg::CoordIntBits-1:0]        load_dmin_i,
  input  logic signed [trirast_pkg::CoordIntBits+2:0] load_d0_i,
  // ---- stepping ----
  input  logic signed [WBits-1:0]                     row_i,        // the row being walked
  input  logic                                        step_i,       // take the step (has_step_o)
  output logic                                        has_step_o,   // a step lands on row_i
  output logic                                        last_step_o,  // it is the line's last
  output logic signed [WBits-1:0]                     dest_x_o,     // x of its pixel
  output logic                                        more_o        // after this cycle: another
);
  `TRIRAST_PKG_NAMES
  localparam int DecBits = CoordIntBits + 3;

  logic signed [WBits-1:0] x_q, x_d, y_q, y_d;
  logic signed [DecBits-1:0] d_q, d_d, d_step;
  logic [CoordIntBits-1:0] rem_q, rem_d;  // steps left
  logic sx_neg_q, sx_neg_d, x_major_q, x_major_d;
  logic [CoordIntBits-1:0] dmaj_q, dmaj_d, dmin_q, dmin_d;

  // The step from the current state.
  logic moves_minor, moves_x, moves_y;
  logic signed [WBits-1:0] dest_y;
  assign moves_minor = d_q > DecBits'(0);
  assign moves_x     = x_major_q || moves_minor;
  assign moves_y     = !x_major_q || moves_minor;
  assign dest_x_o    = moves_x ? (sx_neg_q ? x_q - WBits'(1) : x_q + WBits'(1)) : x_q;
  assign dest_y      = moves_y ? y_q + WBits'(1) : y_q;
  assign d_step      = d_q + DecBits'({dmin_q, 1'b0}) -
                       (moves_minor ? DecBits'({dmaj_q, 1'b0}) : DecBits'(0));
  assign has_step_o  = (rem_q != '0) && (dest_y == row_i);
  assign last_step_o = rem_q == CoordIntBits'(1);

  // Next state: a load wins over a step (the short walker's switch to its second line).
  assign x_d       = load_i ? WBits'(load_x_i) : (step_i ? dest_x_o : x_q);
  assign y_d       = load_i ? WBits'(load_y_i) : (step_i ? dest_y : y_q);
  assign d_d       = load_i ? load_d0_i : (step_i ? d_step : d_q);
  assign rem_d     = load_i ? load_dmaj_i : (step_i ? rem_q - CoordIntBits'(1) : rem_q);
  assign sx_neg_d  = load_i ? load_sx_neg_i : sx_neg_q;
  assign x_major_d = load_i ? load_x_major_i : x_major_q;
  assign dmaj_d    = load_i ? load_dmaj_i : dmaj_q;
  assign dmin_d    = load_i ? load_dmin_i : dmin_q;

  // Whether the next state still has a step on row_i.
  logic next_moves_y;
  assign next_moves_y = !x_major_d || (d_d > DecBits'(0));
  assign more_o = (rem_d != '0) && ((next_moves_y ? y_d + WBits'(1) : y_d) == row_i);

  // Datapath registers: no reset (loaded at the hand-off before they are read).
  always_ff @(posedge clk_i) begin
    {x_q, y_q, d_q, rem_q, sx_neg_q, x_major_q, dmaj_q, dmin_q} <=
        {x_d, y_d, d_d, rem_d, sx_neg_d, x_major_d, dmaj_d, dmin_d};
  end

endmodule
