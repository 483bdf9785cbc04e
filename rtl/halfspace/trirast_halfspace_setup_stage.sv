// The half-space unit's setup stage (docs/timing.md "The half-space unit", docs/unit.md): the
// improved unit's interface (bounding box, the edges' A, B), the corner values in one of two
// forms (CornerForm, as the improved2 unit's), and the FSM
// StIdle -> StBox -> StEdge -> StHold -> StIdle.
//   StIdle : tri_ready_o (the top gates it with the reset); the handshake registers the triangle
//            and its box's first and last pixels (trirast_box_stage BoxAtAccept).
//   StBox  : the bounding box; an empty box retires the triangle here (box_retire_o).
//   StEdge : E0, the value at the box corner, and the value at the last unit of band row 0,
//            E_end = E0 + ((Xmax & ~(U-1)) * A) << F.
//            CornerForm 0 (products): one cycle; E0 = the interface's E_L (its multipliers, with
//            C), E_end from one more multiplier per edge (unread with FormEend 0: synthesis
//            removes it); both registered.
//            CornerForm 1 (radix 16): the digit-serial corner unit
//            (rtl/common/trirast_corner_serial.sv, the improved2 unit's iCE40 form: no
//            multipliers), MSB first, CornerDigitBits operand bits per cycle. Run 1 starts in
//            StEdge's first cycle and forms E0 in nL digit cycles (nL: the digits of the
//            operands cx0 - vx, cy0 - vy); E0 is registered in the cycle after. When the box is
//            wider than one unit and FormEend is set (the zig-zag walk), run 2 starts in that
//            cycle and forms E_end at x0 + (Xmax & ~(U-1)) in nR digit cycles; else E_end = E0.
//            StHold follows the cycle whose corner unit holds E_end: StEdge lasts 2 + nL cycles,
//            plus 1 + nR with run 2. The values are vertex-relative (A*(cx - vx) + B*(cy - vy) -
//            bias): C is not read.
//   StHold : the set-up triangle waits for the walk stage; hand-off when hand_ready_i (radix 16:
//            E_end is the corner unit's output, held: nothing starts a run before the next StEdge).
`include "trirast_assert.svh"
`include "trirast_ports.svh"

module trirast_halfspace_setup_stage #(
  parameter int UnitSize = 8,        // U: tile side, or the stamp side without tiles
  parameter int CornerForm = 0,      // 0: products (DSPs on xc7); 1: MSB-first radix 16 (iCE40 HX)
  parameter int CornerDigitBits = 4, // CornerForm 1: the corner unit's digit, 4 bits (radix 16)
  // 1: E_end is formed (the zig-zag walk, whose odd bands start there); 0: the walker does not
  // read hand_eend_o, and CornerForm 1 runs no run 2 (StEdge lasts 2 + nL cycles).
  parameter bit FormEend = 1'b1
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic [trirast_pkg::PixBits-1:0]       vp_xmax_i,
  input  logic [trirast_pkg::PixBits-1:0]       vp_ymax_i,
  // ---- triangle port ----
  `TRIRAST_TRIANGLE_PORT,
  // ---- empty-box retirement (StBox) ----
  output logic                                  box_retire_o,
  output logic [trirast_pkg::TagBits-1:0]       box_retire_tag_o,
  // ---- hand-off to the walk stage (valid in StHold) ----
  output logic                                  hand_valid_o,
  input  logic                                  hand_ready_i,
  `TRIRAST_HANDOFF_BOX(output, _o),
  output logic [3*trirast_pkg::CoefBits-1:0]    hand_a_o,     // A of edge k
  output logic [3*trirast_pkg::CoefBits-1:0]    hand_b_o,     // B of edge k
  output logic [3*trirast_pkg::EdgeBits-1:0]    hand_e0_o,    // E0 of edge k
  output logic [3*trirast_pkg::EdgeBits-1:0]    hand_eend_o,  // E_end of edge k
  output logic [2:0]                            state_o
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES

  typedef enum logic [2:0] {
    StIdle = 3'd0,
    StBox  = 3'd1,
    StEdge = 3'd2,
    StHold = 3'd4
  } hs_setup_state_e;

  hs_setup_state_e state_q, state_d;
  logic accept, box_en, empty, edge_done;  // edge_done: StEdge's last cycle
  logic [3*EdgeBits-1:0] el, er_unused;
  logic [3*VertexBits-1:0] vx, vy;
  logic [2:0] bias;

  assign tri_ready_o = state_q == StIdle;
  assign accept = tri_valid_i && tri_ready_o;

  // CornerForm 1 reads the vertices and the bias, not the products (el_o): synthesis removes them.
  trirast_box_stage #(.BoxAtAccept (1'b1)) u_interface (
    `TRIRAST_CONNECT_BOX_STAGE(accept, box_en, empty),
    .a_o       (hand_a_o),
    .b_o       (hand_b_o),
    .el_o      (el),
    .er_o      (er_unused),
    .vx_o      (vx),
    .vy_o      (vy),
    .bias_o    (bias)
  );

  // The last unit of band row 0, box-relative: Xmax & ~(U-1).
  logic [BoxBits-1:0] xlast;
  // ~(W'(x)), not ~W'(x): Yosys 0.23 reads the latter as W'(x) (docs/formal.md)
  assign xlast = hand_xmax_o & ~(BoxBits'(UnitSize - 1));

  if (CornerForm == 0) begin : g_products
    localparam int ProdBits = CoefBits + BoxBits + 1;  // A * (Xmax & ~(U-1)), signed
    // E_end = E_L + ((Xmax & ~(U-1)) * A) << F: the first unit of a right-to-left band.
    logic [3*EdgeBits-1:0] eend, e0_q, e0_d, eend_q, eend_d;
    always_comb begin
      for (int k = 0; k < 3; k++) begin
        logic [ProdBits-1:0] prod;
        prod = {{(ProdBits - CoefBits){hand_a_o[k*CoefBits + CoefBits-1]}},
                hand_a_o[k*CoefBits +: CoefBits]} * {{(ProdBits - BoxBits){1'b0}}, xlast};
        // E_end fits EdgeBits (a box pixel's value): the sum is exact modulo 2^EdgeBits even
        // where the product is wider than EdgeBits - F (a box wider than the coordinate range).
        eend[k*EdgeBits +: EdgeBits] = el[k*EdgeBits +: EdgeBits] + (EdgeBits'($signed(prod)) << F);
      end
    end
    assign e0_d = (state_q == StEdge) ? el : e0_q;
    assign eend_d = (state_q == StEdge) ? eend : eend_q;
    always_ff @(posedge clk_i) begin
      e0_q <= e0_d;
      eend_q <= eend_d;
    end
    assign edge_done = state_q == StEdge;
    assign hand_e0_o = e0_q;
    assign hand_eend_o = eend_q;
    logic unused_serial;
    assign unused_serial = ^{vx, vy, bias};
  end else begin : g_serial
    // StEdge's runs of the corner unit: 0 run 1 starts, 1 run 1 (E0), 2 run 2 (E_end).
    localparam logic [1:0] RunStart = 2'd0, RunE0 = 2'd1, RunEend = 2'd2;
    logic [1:0] run_q, run_d;
    logic [3*EdgeBits-1:0] corner, e0_q;
    // A + B per edge, the corner unit's multiplicand (read at run 1's start).
    logic [3*(CB+1)-1:0] ab;
    for (genvar k = 0; k < 3; k++) begin : g_ab
      assign ab[k*(CB+1) +: CB+1] = (CB+1)'($signed(hand_a_o[k*CB +: CB])) +
                                    (CB+1)'($signed(hand_b_o[k*CB +: CB]));
    end
    logic start, second, busy, run_done;
    assign run_done = state_q == StEdge && run_q != RunStart && !busy;
    assign second = FormEend && run_done && run_q == RunE0 && xlast != '0;
    assign start = (state_q == StEdge && run_q == RunStart) || second;
    logic [2:0] far_unused, fneg_unused;
    trirast_corner_serial #(.DigitBits (CornerDigitBits)) u_corner (
      .clk_i (clk_i), .rst_ni (rst_ni), .start_i (start), .second_i (second), .run_i (3'b111),
      .vx_i (vx), .vy_i (vy), .a_i (hand_a_o), .b_i (hand_b_o), .p_i (ab), .bias_i (bias),
      .x0_i (hand_x0_o), .y0_i (hand_y0_o), .xmax_i (xlast), .busy_o (busy), .el_o (corner),
      .far_o (far_unused), .fneg_o (fneg_unused));
    always_comb begin
      run_d = run_q;
      if (state_q != StEdge) run_d = RunStart;
      else if (run_q == RunStart) run_d = RunE0;
      else if (second) run_d = RunEend;
    end
    `TRIRAST_FLOP_AR(run_q, run_d, RunStart)
    always_ff @(posedge clk_i) begin
      if (run_done && run_q == RunE0) e0_q <= corner;
    end
    assign edge_done = run_done && !second;
    assign hand_e0_o = e0_q;
    assign hand_eend_o = corner;
    logic unused_products;
    assign unused_products = ^{el, far_unused, fneg_unused};
  end

  always_comb begin
    hs_setup_state_e next;  // one write of state_d (Icarus 11: see trirast_halfspace_stamp_tester.sv)
    box_en = state_q == StBox;
    box_retire_o = state_q == StBox && empty;
    box_retire_tag_o = hand_tag_o;
    hand_valid_o = state_q == StHold;
    next = state_q;
    unique case (state_q)
      StIdle: if (accept) next = StBox;
      StBox: begin
        if (empty) next = StIdle;
        else next = StEdge;
      end
      StEdge: if (edge_done) next = StHold;
      StHold: if (hand_ready_i) next = StIdle;
      default: next = StIdle;
    endcase
    state_d = next;
  end

  assign state_o = state_q;

  `TRIRAST_FLOP_AR(state_q, state_d, StIdle)

  logic unused_er;
  assign unused_er = ^er_unused;

  `ASSERT(HalfspaceSetupStateLegal_A, state_q == StIdle || state_q == StBox || state_q == StEdge ||
          state_q == StHold, clk_i, !rst_ni)
  // The hand-off holds its triangle until the walk stage takes it.
  `ASSERT_NEXT(HalfspaceHandHeld_A, hand_valid_o && !hand_ready_i,
          hand_valid_o && $stable(hand_tag_o), clk_i, !rst_ni)
  `ASSERT_KNOWN(HalfspaceHandValidKnown_A, {tri_ready_o, hand_valid_o, box_retire_o}, clk_i, !rst_ni)
  // Cover points (docs/coverage.md): every state; the empty box retired in StBox; the triangle
  // port waiting, taking a triangle, and taking the next one as early as the FSM allows (an empty
  // box: StIdle -> StBox -> StIdle, two cycles after the previous accept).
  `COVER(SetupStIdle_C, state_q == StIdle, clk_i, !rst_ni)
  `COVER(SetupStBox_C, state_q == StBox, clk_i, !rst_ni)
  `COVER(SetupStEdge_C, state_q == StEdge, clk_i, !rst_ni)
  `COVER(SetupStHold_C, state_q == StHold, clk_i, !rst_ni)
  `COVER(SetupEmptyBoxRetired_C, box_retire_o, clk_i, !rst_ni)
  `COVER(SetupHoldWaitsForWalk_C, hand_valid_o && !hand_ready_i, clk_i, !rst_ni)
  `COVER(TriAccept_C, accept, clk_i, !rst_ni)
  `COVER(TriPortStall_C, tri_valid_i && !tri_ready_o, clk_i, !rst_ni)
  `COVER(TriAcceptBackToBack_C, accept && $past(accept, 2), clk_i, !rst_ni)

endmodule
