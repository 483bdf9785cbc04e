// The setup stage (docs/timing.md, "Setup stage"): the interface, three edge normalizers and
// three edge lanes, with the FSM StIdle -> StBox -> StEdge -> StLanes -> StHold -> StIdle.
//   StIdle : tri_ready_o (the top gates it with the reset); the handshake registers the triangle (accept_cycle).
//   StBox  : the bounding box; an empty box retires the triangle here (box_retire_o).
//   StEdge : corner values and normalizers; the lanes load their edges.
//   StLanes: the lanes run (L = max L_k cycles).
//   StHold : the set-up triangle waits for the walk stage; hand-off when hand_ready_i.
`include "trirast_assert.svh"
`include "trirast_ports.svh"

module trirast_improved_setup_stage (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  // ---- configuration ----
  input  logic [trirast_pkg::PixBits-1:0]       vp_xmax_i,
  input  logic [trirast_pkg::PixBits-1:0]       vp_ymax_i,
  input  logic                                  divide_i,     // boundary mode divide
  input  logic                                  adaptive_i,   // divider adaptive (else fixed)
  // ---- triangle port ----
  `TRIRAST_TRIANGLE_PORT,
  // ---- empty-box retirement (StBox) ----
  output logic                                  box_retire_o,
  output logic [trirast_pkg::TagBits-1:0]       box_retire_tag_o,
  // ---- hand-off to the walk stage (valid in StHold) ----
  output logic                                  hand_valid_o,
  input  logic                                  hand_ready_i,  // the walk stage is idle
  `TRIRAST_HANDOFF_BOX(output, _o),
  `TRIRAST_IMPROVED_HANDOFF_EDGES(output, _o),
  output logic [3*trirast_pkg::RemBits-1:0]     hand_entry_e_o,
  // ---- observation ----
  output logic [2:0]                            state_o,
  output logic [2:0]                            lane_busy_o,
  output logic [2:0]                            lane_div_o    // lane k's divider iterates
);
  `TRIRAST_PKG_NAMES

  typedef enum logic [2:0] {
    StIdle  = 3'd0,
    StBox   = 3'd1,
    StEdge  = 3'd2,
    StLanes = 3'd3,
    StHold  = 3'd4
  } setup_state_e;

  setup_state_e state_q, state_d;
  logic accept, empty, lanes_load, box_en;
  logic [2:0] lane_done_next;
  // Iterations per division (docs/unit.md, section 3): fixed Q, or adaptive
  // Qx = bits(Xmax) + 1 and Qy = bits(Ymax) + 1 (bits(0) = 1).
  localparam int IterBits = $clog2(trirast_pkg::QuotBits + 1);
  logic [IterBits-1:0] qx, qy;

  function automatic logic [IterBits-1:0] bits_plus_one(
      input logic [trirast_pkg::BoxBits-1:0] v);
    logic [IterBits-1:0] b;
    b = IterBits'(1);
    for (int i = 0; i < trirast_pkg::BoxBits; i++) begin
      if (v[i]) b = IterBits'(i + 1);
    end
    bits_plus_one = b + 1'b1;
  endfunction

  always_comb begin
    qx = adaptive_i ? bits_plus_one(hand_xmax_o) : IterBits'(trirast_pkg::QuotBits);
    qy = adaptive_i ? bits_plus_one(hand_ymax_o) : IterBits'(trirast_pkg::QuotBits);
  end

  logic [3*CoefBits-1:0] a_all, b_all;
  logic [3*EdgeBits-1:0] el_all, er_all;
  logic [3*VertexBits-1:0] vx_unused, vy_unused;  // read by the digit-serial corner unit only
  logic [2:0] bias_unused;

  trirast_box_stage u_interface (
    `TRIRAST_CONNECT_BOX_STAGE(accept, box_en, empty),
    .a_o       (a_all),
    .b_o       (b_all),
    .el_o      (el_all),
    .er_o      (er_all),
    .vx_o      (vx_unused),
    .vy_o      (vy_unused),
    .bias_o    (bias_unused)
  );
  logic unused_vertices;
  assign unused_vertices = ^{vx_unused, vy_unused, bias_unused};

  for (genvar k = 0; k < 3; k++) begin : g_edge
    logic horiz, mirror, dir_down;
    logic signed [EdgeBits-1:0] t, t1;
    logic [StepBits-1:0] d, s;
    logic horiz_unused;

    trirast_improved_edge_normalizer u_normalizer (
      .a_i        (a_all[k*CoefBits +: CoefBits]),
      .b_i        (b_all[k*CoefBits +: CoefBits]),
      .el_i       (el_all[k*EdgeBits +: EdgeBits]),
      .er_i       (er_all[k*EdgeBits +: EdgeBits]),
      .horiz_o    (horiz),
      .mirror_o   (mirror),
      .dir_down_o (dir_down),
      .t_o        (t),
      .t1_o       (t1),
      .d_o        (d),
      .s_o        (s)
    );

    trirast_improved_edge_lane u_lane (
      .clk_i         (clk_i),
      .rst_ni        (rst_ni),
      .divide_i      (divide_i),
      .qx_i          (qx),
      .qy_i          (qy),
      .load_i        (lanes_load),
      .horiz_i       (horiz),
      .mirror_i      (mirror),
      .dir_down_i    (dir_down),
      .t_i           (t),
      .t1_i          (t1),
      .d_i           (d),
      .s_i           (s),
      .xmax_i        (hand_xmax_o),
      .ymax_i        (hand_ymax_o),
      .busy_o        (lane_busy_o[k]),
      .div_o         (lane_div_o[k]),
      .done_next_o   (lane_done_next[k]),
      .horiz_o       (horiz_unused),
      .mirror_o      (hand_mirror_o[k]),
      .dir_down_o    (hand_dir_down_o[k]),
      .d_o           (hand_d_o[k*StepBits +: StepBits]),
      .qs_o          (hand_qs_o[k*QuotBits +: QuotBits]),
      .rs_o          (hand_rs_o[k*RemBits +: RemBits]),
      .ssat_o        (hand_ssat_o[k]),
      .enters_o      (hand_enters_o[k]),
      .j_entry_o     (hand_j_entry_o[k*RowBits +: RowBits]),
      .entry_state_o (hand_entry_state_o[2*k +: 2]),
      .entry_x_o     (hand_entry_x_o[k*WalkerXBits +: WalkerXBits]),
      .entry_e_o     (hand_entry_e_o[k*RemBits +: RemBits])
    );
  end

  always_comb begin
    tri_ready_o      = state_q == StIdle;
    accept           = tri_valid_i && tri_ready_o;
    box_en           = state_q == StBox;
    box_retire_o     = box_en && empty;
    box_retire_tag_o = hand_tag_o;
    lanes_load       = state_q == StEdge;
    hand_valid_o     = state_q == StHold;
    state_d          = state_q;
    unique case (state_q)
      StIdle: begin
        if (accept) state_d = StBox;
      end
      StBox: begin
        if (empty) state_d = StIdle;
        else state_d = StEdge;
      end
      StEdge:  state_d = StLanes;
      // The lanes' last cycle: hold from the next one (docs/timing.md: from a + 3 + L).
      StLanes: if (&lane_done_next) state_d = StHold;
      StHold:  if (hand_ready_i) state_d = StIdle;
      default: state_d = StIdle;
    endcase
  end

  `TRIRAST_FLOP_AR(state_q, state_d, StIdle)

  assign state_o = state_q;

  // The triangle port (an input assumption): a triangle offered and not yet taken stays on the
  // port, unchanged, until the handshake.
  `ASSERT_NEXT(TriValidHeld_A, tri_valid_i && !tri_ready_o, tri_valid_i, clk_i, !rst_ni)
  `ASSERT_STABLE(TriDataStable_A, tri_valid_i && !tri_ready_o,
                 {tri_tag_i, tri_vx_i, tri_vy_i, tri_a_i, tri_b_i, tri_c_i, tri_bias_i}, clk_i,
                 !rst_ni)
  // The hand-off (what this stage guarantees the walk stage): the set-up triangle is held in
  // StHold, unchanged, until the walk stage takes it.
  `ASSERT_NEXT(HandValidHeld_A, hand_valid_o && !hand_ready_i, hand_valid_o, clk_i, !rst_ni)
  `ASSERT_STABLE(HandDataStable_A, hand_valid_o && !hand_ready_i,
                 {hand_tag_o, hand_x0_o, hand_y0_o, hand_xmax_o, hand_ymax_o, hand_mirror_o,
                  hand_dir_down_o, hand_d_o, hand_qs_o, hand_rs_o, hand_ssat_o, hand_enters_o,
                  hand_j_entry_o, hand_entry_state_o, hand_entry_x_o, hand_entry_e_o}, clk_i,
                 !rst_ni)
  `ASSERT(SetupStateLegal_A, state_q == StIdle || state_q == StBox || state_q == StEdge ||
          state_q == StLanes || state_q == StHold, clk_i, !rst_ni)

  // Cover points (docs/coverage.md): every state; the empty box retired in StBox; the triangle
  // port waiting (valid, not ready), taking a triangle, and taking the next one as early as the
  // FSM allows (an empty box: StIdle -> StBox -> StIdle, two cycles after the previous accept).
  `COVER(SetupStIdle_C, state_q == StIdle, clk_i, !rst_ni)
  `COVER(SetupStBox_C, state_q == StBox, clk_i, !rst_ni)
  `COVER(SetupStEdge_C, state_q == StEdge, clk_i, !rst_ni)
  `COVER(SetupStLanes_C, state_q == StLanes, clk_i, !rst_ni)
  `COVER(SetupStHold_C, state_q == StHold, clk_i, !rst_ni)
  `COVER(SetupEmptyBoxRetired_C, box_retire_o, clk_i, !rst_ni)
  `COVER(SetupHoldWaitsForWalk_C, hand_valid_o && !hand_ready_i, clk_i, !rst_ni)
  `COVER(TriAccept_C, accept, clk_i, !rst_ni)
  `COVER(TriPortStall_C, tri_valid_i && !tri_ready_o, clk_i, !rst_ni)
  `COVER(TriAcceptBackToBack_C, accept && $past(accept, 2), clk_i, !rst_ni)

endmodule
