// The setup stage of the traditional-Bresenham unit (docs/timing.md, "The traditional unit"):
// FSM StIdle -> StSort -> StLine -> StHold -> StIdle.
//   StIdle : tri_ready_o (the top gates it with the reset); the handshake registers the triangle's vertices (accept_cycle).
//   StSort : the quantizer (integer pixels, collinearity, sort); collinear pixels retire the
//            triangle here (retire_o), else the sorted pixels are registered.
//   StLine : Bresenham set-up of the lines p0->p2 (long), p0->p1, p1->p2, registered.
//   StHold : the set-up triangle waits for the walk stage; hand-off when hand_ready_i.
`include "trirast_assert.svh"
`include "trirast_ports.svh"

module trirast_trad_setup_stage (
  input  logic                                    clk_i,
  input  logic                                    rst_ni,
  // ---- triangle port ----
  `TRIRAST_TRIANGLE_PORT_VERTICES,
  // ---- collinear retirement (StSort) ----
  output logic                                    retire_o,
  output logic [trirast_pkg::TagBits-1:0]         retire_tag_o,
  // ---- hand-off to the walk stage (valid in StHold) ----
  output logic                                    hand_valid_o,
  input  logic                                    hand_ready_i,   // the walk stage is idle
  `TRIRAST_TRAD_HANDOFF(output, _o),
  // ---- observation ----
  output logic [2:0]                              state_o
);
  `TRIRAST_PKG_NAMES
  localparam int DecBits = CoordIntBits + 3;

  // Numbered as in the SystemC model's trace (0, 1, 2, 4).
  typedef enum logic [2:0] {
    StIdle = 3'd0,
    StSort = 3'd1,
    StLine = 3'd2,
    StHold = 3'd4
  } trad_setup_state_e;

  trad_setup_state_e state_q, state_d;
  logic accept, sort_en, line_en, collinear;

  logic [TagBits-1:0] tag_q, tag_d;
  logic [3*VertexBits-1:0] vx_q, vx_d, vy_q, vy_d;
  logic [3*CoordIntBits-1:0] px_q, px_d, py_q, py_d, sort_px, sort_py;
  logic [2:0] sx_neg, x_major, sx_neg_q, sx_neg_d, x_major_q, x_major_d;
  logic [3*CoordIntBits-1:0] dmaj, dmin, dmaj_q, dmaj_d, dmin_q, dmin_d;
  logic [3*DecBits-1:0] d0, d0_q, d0_d;

  trirast_trad_quantizer u_quantizer (
    .vx_i        (vx_q),
    .vy_i        (vy_q),
    .collinear_o (collinear),
    .px_o        (sort_px),
    .py_o        (sort_py)
  );

  // Line e runs from pixel la[e] to pixel lb[e]: p0->p2, p0->p1, p1->p2.
  for (genvar e = 0; e < 3; e++) begin : g_line
    localparam int A = (e == 2) ? 1 : 0;
    localparam int B = (e == 1) ? 1 : 2;
    trirast_trad_line_setup u_line_setup (
      .ax_i      (px_q[A*CoordIntBits +: CoordIntBits]),
      .ay_i      (py_q[A*CoordIntBits +: CoordIntBits]),
      .bx_i      (px_q[B*CoordIntBits +: CoordIntBits]),
      .by_i      (py_q[B*CoordIntBits +: CoordIntBits]),
      .sx_neg_o  (sx_neg[e]),
      .x_major_o (x_major[e]),
      .dmaj_o    (dmaj[e*CoordIntBits +: CoordIntBits]),
      .dmin_o    (dmin[e*CoordIntBits +: CoordIntBits]),
      .d0_o      (d0[e*DecBits +: DecBits])
    );
  end

  always_comb begin
    tri_ready_o  = state_q == StIdle;
    accept       = tri_valid_i && tri_ready_o;
    sort_en      = state_q == StSort;
    line_en      = state_q == StLine;
    retire_o     = sort_en && collinear;
    retire_tag_o = tag_q;
    hand_valid_o = state_q == StHold;
    state_d      = state_q;
    unique case (state_q)
      StIdle:  if (accept) state_d = StSort;
      StSort: begin  // (if/else, not ?:, for Icarus 11's enum casts)
        if (collinear) state_d = StIdle;
        else state_d = StLine;
      end
      StLine:  state_d = StHold;
      StHold:  if (hand_ready_i) state_d = StIdle;
      default: state_d = StIdle;
    endcase
  end

  // Datapath registers, each written in its own state.
  always_comb begin
    tag_d     = accept ? tri_tag_i : tag_q;
    vx_d      = accept ? tri_vx_i : vx_q;
    vy_d      = accept ? tri_vy_i : vy_q;
    px_d      = sort_en ? sort_px : px_q;
    py_d      = sort_en ? sort_py : py_q;
    sx_neg_d  = line_en ? sx_neg : sx_neg_q;
    x_major_d = line_en ? x_major : x_major_q;
    dmaj_d    = line_en ? dmaj : dmaj_q;
    dmin_d    = line_en ? dmin : dmin_q;
    d0_d      = line_en ? d0 : d0_q;
  end

  `TRIRAST_FLOP_AR(state_q, state_d, StIdle)

  // Datapath registers: no reset (written before they are read).
  always_ff @(posedge clk_i) begin
    {tag_q, vx_q, vy_q, px_q, py_q, sx_neg_q, x_major_q, dmaj_q, dmin_q, d0_q} <=
        {tag_d, vx_d, vy_d, px_d, py_d, sx_neg_d, x_major_d, dmaj_d, dmin_d, d0_d};
  end

  assign {hand_tag_o, hand_px_o, hand_py_o, hand_sx_neg_o, hand_x_major_o, hand_dmaj_o,
          hand_dmin_o, hand_d0_o} = {tag_q, px_q, py_q, sx_neg_q, x_major_q, dmaj_q, dmin_q, d0_q};
  assign state_o        = state_q;

  // The triangle port (an input assumption): a triangle offered and not yet taken stays on the
  // port, unchanged, until the handshake.
  `ASSERT_NEXT(TriValidHeld_A, tri_valid_i && !tri_ready_o, tri_valid_i, clk_i, !rst_ni)
  `ASSERT_STABLE(TriDataStable_A, tri_valid_i && !tri_ready_o, {tri_tag_i, tri_vx_i, tri_vy_i},
                 clk_i, !rst_ni)
  // The hand-off (what this stage guarantees the walk stage): held in StHold, unchanged, until
  // the walk stage takes it.
  `ASSERT_NEXT(HandValidHeld_A, hand_valid_o && !hand_ready_i, hand_valid_o, clk_i, !rst_ni)
  `ASSERT_STABLE(HandDataStable_A, hand_valid_o && !hand_ready_i,
                 {hand_tag_o, hand_px_o, hand_py_o, hand_sx_neg_o, hand_x_major_o, hand_dmaj_o,
                  hand_dmin_o, hand_d0_o}, clk_i, !rst_ni)
  `ASSERT(SetupStateLegal_A, state_q == StIdle || state_q == StSort || state_q == StLine ||
          state_q == StHold, clk_i, !rst_ni)

  // Cover points (docs/coverage.md): every state; collinear integer vertices retired in StSort;
  // the triangle port waiting, taking a triangle, and taking the next one as early as the FSM
  // allows (collinear: StIdle -> StSort -> StIdle, two cycles after the previous accept).
  `COVER(SetupStIdle_C, state_q == StIdle, clk_i, !rst_ni)
  `COVER(SetupStSort_C, state_q == StSort, clk_i, !rst_ni)
  `COVER(SetupStLine_C, state_q == StLine, clk_i, !rst_ni)
  `COVER(SetupStHold_C, state_q == StHold, clk_i, !rst_ni)
  `COVER(SetupCollinearRetired_C, retire_o, clk_i, !rst_ni)
  `COVER(SetupHoldWaitsForWalk_C, hand_valid_o && !hand_ready_i, clk_i, !rst_ni)
  `COVER(TriAccept_C, accept, clk_i, !rst_ni)
  `COVER(TriPortStall_C, tri_valid_i && !tri_ready_o, clk_i, !rst_ni)
  `COVER(TriAcceptBackToBack_C, accept && $past(accept, 2), clk_i, !rst_ni)

endmodule
