// The walk stage of the traditional unit (docs/timing.md, "The traditional unit", "Walk stage"):
// the long-edge walker (p0->p2), the short-side walker (p0->p1, then p1->p2 with no cycle in
// between) and the span filler, FSM StWalkIdle -> StWalk. Loaded at the hand-off in cycle h, it
// walks rows p0.y .. p2.y from h + 1. A row starts only when the FIFO held at most DEPTH - 1
// spans at the start of its first cycle (else that cycle is a stall); in each of its cycles each
// walker takes the step that lands on the row, if it has one; the row ends in the cycle after
// which neither walker has one (at least one cycle), and its span, if any, is pushed then.
// So row y takes max(1, s_long(y), s_short(y)) cycles.
`include "trirast_ports.svh"

`include "trirast_assert.svh"
module trirast_trad_walk_stage #(
  parameter int CountBits = 4,  // bits of the FIFO occupancy and of the runtime depth
  parameter int EntryBits = 8,  // bits of one FIFO entry {tag, y, x_begin, x_end}
  // Derived, do not override: signed bits of pixel coordinates and rows, with room for p2.y + 1
  // and for the viewport's W.
  parameter int WBits = ((trirast_pkg::CoordIntBits > trirast_pkg::PixBits + 1) ?
                         trirast_pkg::CoordIntBits : trirast_pkg::PixBits + 1) + 2
) (
  input  logic                                     clk_i,
  input  logic                                     rst_ni,
  // ---- configuration ----
  input  logic [trirast_pkg::PixBits-1:0]          vp_xmax_i,
  input  logic [trirast_pkg::PixBits-1:0]          vp_ymax_i,
  input  logic [CountBits-1:0]                     fifo_depth_i,  // DEPTH (1..FifoDepth)
  // ---- hand-off from the setup stage ----
  input  logic                                     hand_valid_i,
  output logic                                     hand_ready_o,  // StWalkIdle
  `TRIRAST_TRAD_HANDOFF(input, _i),
  // ---- pushes into the span FIFO ----
  input  logic [CountBits-1:0]                     fifo_count_i,  // occupancy at cycle start
  output logic                                     push_o,
  output logic [EntryBits-1:0]                     push_data_o,   // {tag, y, x_begin, x_end}
  // ---- observation ----
  output logic                                     busy_o,        // StWalk
  output logic                                     stall_o,       // a stall cycle
  output logic                                     last_o,        // the last row ends
  output logic                                     retire_o,      // ... and no span at all
  output logic [trirast_pkg::TagBits-1:0]          tag_o,         // the walked triangle
  output logic [WBits-1:0]                         row_o          // the row being walked
);
  `TRIRAST_PKG_NAMES
  localparam int DecBits = CoordIntBits + 3;

  typedef enum logic {
    StWalkIdle = 1'b0,
    StWalk     = 1'b1
  } trad_walk_state_e;

  trad_walk_state_e state_q, state_d;
  logic [TagBits-1:0] tag_q, tag_d;
  logic signed [WBits-1:0] row_q, row_d, last_row_q, last_row_d;
  logic first_q, first_d;    // this cycle would start a row (the FIFO test applies)
  logic second_q, second_d;  // the short walker is on p1->p2
  logic any_q, any_d;        // the triangle pushed a span already
  // p1->p2, held for the short walker's switch.
  logic signed [CoordIntBits-1:0] l2_x_q, l2_x_d, l2_y_q, l2_y_d;
  logic l2_sx_neg_q, l2_sx_neg_d, l2_x_major_q, l2_x_major_d;
  logic [CoordIntBits-1:0] l2_dmaj_q, l2_dmaj_d, l2_dmin_q, l2_dmin_d;
  logic signed [DecBits-1:0] l2_d0_q, l2_d0_d;

  logic load, walking, room, stall, go, row_end;
  logic long_has, long_more, long_last_unused;
  logic short_has, short_more, short_last, short_switch, short_load;
  logic long_step /* verilator public_flat_rd */;   // counted by the harness: walker busy
  logic short_step /* verilator public_flat_rd */;
  logic signed [WBits-1:0] long_x, short_x;

  // The short walker's load: p0->p1 at the hand-off, p1->p2 at the switch.
  logic signed [CoordIntBits-1:0] sh_x, sh_y;
  logic sh_sx_neg, sh_x_major;
  logic [CoordIntBits-1:0] sh_dmaj, sh_dmin;
  logic signed [DecBits-1:0] sh_d0;

  trirast_trad_walker #(
    .WBits (WBits)
  ) u_long_walker (
    .clk_i          (clk_i),
    .load_i         (load),
    .load_x_i       (hand_px_i[0 +: CoordIntBits]),
    .load_y_i       (hand_py_i[0 +: CoordIntBits]),
    .load_sx_neg_i  (hand_sx_neg_i[0]),
    .load_x_major_i (hand_x_major_i[0]),
    .load_dmaj_i    (hand_dmaj_i[0 +: CoordIntBits]),
    .load_dmin_i    (hand_dmin_i[0 +: CoordIntBits]),
    .load_d0_i      (hand_d0_i[0 +: DecBits]),
    .row_i          (row_q),
    .step_i         (long_step),
    .has_step_o     (long_has),
    .last_step_o    (long_last_unused),
    .dest_x_o       (long_x),
    .more_o         (long_more)
  );

  trirast_trad_walker #(
    .WBits (WBits)
  ) u_short_walker (
    .clk_i          (clk_i),
    .load_i         (short_load),
    .load_x_i       (sh_x),
    .load_y_i       (sh_y),
    .load_sx_neg_i  (sh_sx_neg),
    .load_x_major_i (sh_x_major),
    .load_dmaj_i    (sh_dmaj),
    .load_dmin_i    (sh_dmin),
    .load_d0_i      (sh_d0),
    .row_i          (row_q),
    .step_i         (short_step),
    .has_step_o     (short_has),
    .last_step_o    (short_last),
    .dest_x_o       (short_x),
    .more_o         (short_more)
  );

  logic span_valid;
  logic [PixBits-1:0] span_y, span_xb;
  logic [PixBits:0] span_xe;

  trirast_trad_span_filler #(
    .WBits (WBits)
  ) u_span_filler (
    .clk_i     (clk_i),
    .vp_xmax_i (vp_xmax_i),
    .vp_ymax_i (vp_ymax_i),
    .load_i    (load),
    .load_x_i  (WBits'($signed(hand_px_i[0 +: CoordIntBits]))),
    .a_step_i  (long_step),
    .a_x_i     (long_x),
    .b_step_i  (short_step),
    .b_x_i     (short_x),
    .row_end_i (row_end),
    .row_i     (row_q),
    .valid_o   (span_valid),
    .y_o       (span_y),
    .begin_o   (span_xb),
    .end_o     (span_xe)
  );

  assign walking      = state_q == StWalk;
  assign load         = (state_q == StWalkIdle) && hand_valid_i;
  // Room for one span: count <= DEPTH - 1 (count at the start of the cycle).
  assign room         = fifo_count_i < fifo_depth_i;
  assign stall        = walking && first_q && !room;
  assign go           = walking && !stall;
  assign long_step    = go && long_has;
  assign short_step   = go && short_has;
  assign short_switch = short_step && short_last && !second_q;
  assign short_load   = load || short_switch;
  assign row_end      = go && !long_more && !short_more;
  assign last_o       = row_end && (row_q == last_row_q);
  assign push_o       = span_valid;
  assign push_data_o  = {tag_q, span_y, span_xb, span_xe};
  assign retire_o     = last_o && !any_q && !span_valid;

  assign sh_x       = load ? hand_px_i[0 +: CoordIntBits] : l2_x_q;
  assign sh_y       = load ? hand_py_i[0 +: CoordIntBits] : l2_y_q;
  assign sh_sx_neg  = load ? hand_sx_neg_i[1] : l2_sx_neg_q;
  assign sh_x_major = load ? hand_x_major_i[1] : l2_x_major_q;
  assign sh_dmaj    = load ? hand_dmaj_i[CoordIntBits +: CoordIntBits] : l2_dmaj_q;
  assign sh_dmin    = load ? hand_dmin_i[CoordIntBits +: CoordIntBits] : l2_dmin_q;
  assign sh_d0      = load ? hand_d0_i[DecBits +: DecBits] : l2_d0_q;

  always_comb begin
    state_d      = state_q;
    {tag_d, row_d, last_row_d, first_d, second_d, any_d, l2_x_d, l2_y_d, l2_sx_neg_d, l2_x_major_d,
     l2_dmaj_d, l2_dmin_d, l2_d0_d} =
        {tag_q, row_q, last_row_q, first_q, second_q, any_q, l2_x_q, l2_y_q, l2_sx_neg_q,
         l2_x_major_q, l2_dmaj_q, l2_dmin_q, l2_d0_q};
    unique case (state_q)
      StWalkIdle: begin
        if (load) begin
          state_d      = StWalk;
          tag_d        = hand_tag_i;
          row_d        = WBits'($signed(hand_py_i[0 +: CoordIntBits]));
          last_row_d   = WBits'($signed(hand_py_i[2*CoordIntBits +: CoordIntBits]));
          first_d      = 1'b1;
          second_d     = 1'b0;
          any_d        = 1'b0;
          l2_x_d       = hand_px_i[CoordIntBits +: CoordIntBits];
          l2_y_d       = hand_py_i[CoordIntBits +: CoordIntBits];
          l2_sx_neg_d  = hand_sx_neg_i[2];
          l2_x_major_d = hand_x_major_i[2];
          l2_dmaj_d    = hand_dmaj_i[2*CoordIntBits +: CoordIntBits];
          l2_dmin_d    = hand_dmin_i[2*CoordIntBits +: CoordIntBits];
          l2_d0_d      = hand_d0_i[2*DecBits +: DecBits];
        end
      end
      StWalk: begin
        if (go) begin
          first_d  = row_end;
          second_d = second_q || short_switch;
          any_d    = any_q || span_valid;
          if (row_end) row_d = row_q + WBits'(1);
          if (last_o) state_d = StWalkIdle;
        end
      end
      default: state_d = StWalkIdle;
    endcase
  end

  `TRIRAST_FLOP_AR(state_q, state_d, StWalkIdle)

  // Datapath registers: no reset (loaded at the hand-off).
  always_ff @(posedge clk_i) begin
    {tag_q, row_q, last_row_q, first_q, second_q, any_q, l2_x_q, l2_y_q, l2_sx_neg_q, l2_x_major_q,
     l2_dmaj_q, l2_dmin_q, l2_d0_q} <=
        {tag_d, row_d, last_row_d, first_d, second_d, any_d, l2_x_d, l2_y_d, l2_sx_neg_d,
         l2_x_major_d, l2_dmaj_d, l2_dmin_d, l2_d0_d};
  end

  assign hand_ready_o = state_q == StWalkIdle;
  assign busy_o       = walking;
  assign stall_o      = stall;
  assign tag_o        = tag_q;
  assign row_o        = row_q;

  // p2.x is not needed: the lines' deltas lead the walkers there. (long_last_unused: the long
  // walker's last step needs no action, its line ends with the triangle's last row.)
  logic unused_p2x;
  assign unused_p2x = ^hand_px_i[2*CoordIntBits +: CoordIntBits];

  // Cover points (docs/coverage.md): both states, a stall (no room in the FIFO), each walker
  // stepping, the short walker's switch to p1 -> p2, and a triangle retired without a span.
  `COVER(WalkStWalkIdle_C, state_q == StWalkIdle, clk_i, !rst_ni)
  `COVER(WalkStWalk_C, state_q == StWalk, clk_i, !rst_ni)
  `COVER(WalkStall_C, stall, clk_i, !rst_ni)
  `COVER(WalkLongStep_C, long_step, clk_i, !rst_ni)
  `COVER(WalkShortStep_C, short_step, clk_i, !rst_ni)
  `COVER(WalkShortSwitch_C, short_switch, clk_i, !rst_ni)
  `COVER(WalkRetireNoSpan_C, retire_o, clk_i, !rst_ni)

endmodule
