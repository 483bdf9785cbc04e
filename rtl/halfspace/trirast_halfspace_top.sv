// The half-space (Pineda edge-function) tile unit (model/halfspace_*, docs/unit.md "The
// half-space unit", docs/timing.md "The half-space unit"):
//   setup stage (interface: box; edge values at the box corner: CornerForm 0 from the
//   interface's products, CornerForm 1 from the digit-serial corner unit, vertex-relative, C not
//   read) -> tile walker (unit tests, stamp tester) -> span
//   emitter (band buffers, one span per cycle) -> span FIFO (trirast_span_fifo_ram: block RAM,
//   behind a registered push) and span port.
// The triangle port is trirast_improved_top's; the span port's checks are trirast_span_port's
// (TRIRAST_SPAN_PORT_CHECKS).
// Build parameters: StampSize (1, 2, 4), TileSize (8, 16; 0 = no tiles), WalkMode (0 row,
// 1 zig-zag, 2 forward: trirast_halfspace_tile_walker.sv), CornerForm.
// Every boundary is a valid/ready handshake: triangle port, hand-off, band hand-over to the
// emitter, FIFO push (admitted by the occupancy test count + pending <= DEPTH - 1), span port.
`include "trirast_assert.svh"
`include "trirast_ports.svh"

module trirast_halfspace_top #(
  parameter int StampSize = 2,
  parameter int TileSize = 8,
  parameter int WalkMode = 2,    // 0: row; 1: zig-zag; 2: forward (the CLI's --hs-walk)
  parameter int CornerForm = 0,  // 0: products (DSPs on xc7); 1: MSB-first radix 16 (iCE40 HX)
  parameter int FifoDepth = trirast_pkg::DefaultFifoDepth,     // span FIFO entries (power of 2)
  parameter int CountBits = $clog2(FifoDepth + 1)              // derived: do not override
) (
  // ---- clock, reset and configuration (static) ----
  `TRIRAST_TOP_CLOCK_AND_VIEWPORT,
  input  logic [CountBits-1:0]                  cfg_fifo_depth_i, // --fifo-depth (<= FifoDepth)
  // ---- triangle port: one set-up triangle per handshake ----
  `TRIRAST_TRIANGLE_PORT,  // tri_c_i : not read with CornerForm 1 (vertex-relative E)
  // ---- span port ----
  `TRIRAST_SPAN_PORT,
  // ---- observation (the harness's per-triangle timing) ----
  output logic                                  box_retire_o,     // empty box retires (StBox)
  output logic [trirast_pkg::TagBits-1:0]       box_retire_tag_o, // ... its tag
  `TRIRAST_WALK_OBSERVATION,
  output logic [2:0]                            setup_state_o,    // StIdle, StBox, StEdge, StHold (0, 1, 2, 4)
  output logic                                  handoff_o,        // the walk stage loads
  output logic [trirast_pkg::BoxBits-1:0]       box_xmax_o,       // its box: Xmax, Ymax
  output logic [trirast_pkg::BoxBits-1:0]       box_ymax_o        //   (valid with handoff_o)
);
  `TRIRAST_PKG_NAMES
  localparam int PB = BoxBits + 1;
  localparam int EntryBits = TagBits + PixBits + PixBits + PixBits + 1;
  localparam int UnitSize = (TileSize > 0) ? TileSize : StampSize;

  logic hand_valid, hand_ready;
  `TRIRAST_TRIANGLE_READY_GATE
  `TRIRAST_HANDOFF_BOX_SIGNALS(hand_)
  logic [3*CoefBits-1:0] hand_a, hand_b;
  logic [3*EdgeBits-1:0] hand_e0, hand_eend;
  logic [2:0] setup_state, walk_state;
  logic walker_busy;
  logic unused_obs;  // walk_state is observed in traces only
  assign unused_obs = ^walk_state;

  trirast_halfspace_setup_stage #(
    .UnitSize   (UnitSize),
    .CornerForm (CornerForm),
    .FormEend   (WalkMode == 1)  // only the zig-zag walk starts a band at E_end
  ) u_setup (
    `TRIRAST_CONNECT_SETUP_STAGE,
    .hand_a_o         (hand_a),
    .hand_b_o         (hand_b),
    .hand_e0_o        (hand_e0),
    .hand_eend_o      (hand_eend),
    .state_o          (setup_state)
  );

  logic [TagBits-1:0] tag;
  logic [PixBits-1:0] x0, y0;
  logic [UnitSize-1:0] merge, merge_tile;
  logic accept;
  logic [StampSize*PB-1:0] merge_first, merge_last;  // row r's piece: r mod StampSize
  logic band_load, band_back, unit_next, emit_held, emit_any, emit_free;
  logic [PB-1:0] band_j0;

  trirast_halfspace_tile_walker #(
    .StampSize  (StampSize),
    .TileSize   (TileSize),
    .WalkMode   (WalkMode)
  ) u_walker (
    .clk_i         (clk_i),
    .rst_ni        (rst_ni),
    .hand_valid_i  (hand_valid),
    .hand_ready_o  (hand_ready),
    `TRIRAST_CONNECT_HANDOFF_BOX(_i),
    .hand_a_i      (hand_a),
    .hand_b_i      (hand_b),
    .hand_e0_i     (hand_e0),
    .hand_eend_i   (hand_eend),
    .tag_o         (tag),
    .x0_o          (x0),
    .y0_o          (y0),
    .merge_o       (merge),
    .merge_tile_o  (merge_tile),
    .accept_o      (accept),
    .merge_first_o (merge_first),
    .merge_last_o  (merge_last),
    .band_load_o   (band_load),
    .band_j0_o     (band_j0),
    .band_back_o   (band_back),
    .unit_next_o   (unit_next),
    .emit_held_i   (emit_held),
    .emit_any_i    (emit_any),
    .emit_free_i   (emit_free),
    .busy_o        (walker_busy),
    .last_o        (walk_last_o),
    .retire_o      (walk_retire_o),
    .state_o       (walk_state)
  );

  logic push, push_pending;
  logic [EntryBits-1:0] push_data;
  // The walk stage is busy while the walker works and while a span is in the span port's push
  // register (the run ends, and a testbench may stop, only once that span is in the FIFO).
  assign walk_busy_o = walker_busy || push_pending;

  trirast_halfspace_span_emitter #(
    .UnitSize  (UnitSize),
    .StampSize (StampSize),
    .CountBits (CountBits),
    .EntryBits (EntryBits),
    .OwnLuts   (CornerForm == 1)  // the iCE40 form
  ) u_emitter (
    .clk_i         (clk_i),
    .rst_ni        (rst_ni),
    .fifo_depth_i  (cfg_fifo_depth_i),
    .fifo_count_i  (fifo_count_o),
    .fifo_pending_i (push_pending),
    .fifo_pop_i    (span_valid_o && span_ready_i),
    .tag_i         (tag),
    .x0_i          (x0),
    .y0_i          (y0),
    .merge_i       (merge),
    .merge_tile_i  (merge_tile),
    .accept_i      (accept),
    .merge_first_i (merge_first),
    .merge_last_i  (merge_last),
    .band_load_i   (band_load),
    .band_j0_i     (band_j0),
    .band_back_i   (band_back),
    .unit_next_i   (unit_next),
    .held_o        (emit_held),
    .any_o         (emit_any),
    .free_o        (emit_free),
    .push_o        (push),
    .push_data_o   (push_data),
    .stall_o       (walk_stall_o)
  );
  assign {walk_tag_o, setup_state_o} = {tag, setup_state};
  `TRIRAST_ASSIGN_HANDOFF_OBSERVATION(hand_xmax, hand_ymax)

  // The span FIFO in block RAM (trirast_span_fifo_ram) behind a registered push: the emitter's
  // span of cycle t is written into the memory at the end of t and counted from the end of
  // t + 1 (push_pending in t + 1), so it shows on the span port from t + 2.
  logic [EntryBits-1:0] span_head;
  `TRIRAST_FLOP_AR(push_pending, push, 1'b0)
  trirast_span_fifo_ram #(.FifoDepth (FifoDepth), .EntryBits (EntryBits)) u_span_fifo (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .wr_i    (push),
    .wdata_i (push_data),
    .push_i  (push_pending),
    .count_o (fifo_count_o),
    .valid_o (span_valid_o),
    .ready_i (span_ready_i),
    .data_o  (span_head)
  );
  assign {span_tag_o, span_y_o, span_x_begin_o, span_x_end_o} = span_head;
  `TRIRAST_SPAN_PORT_CHECKS(span_valid_o, span_ready_i, span_head, fifo_count_o)

  `ASSERT(CfgFifoDepthInRange_A, cfg_fifo_depth_i != '0 && 32'(cfg_fifo_depth_i) <= FifoDepth,
          clk_i, !rst_ni)
  `ASSERT_KNOWN(StrobesKnown_A, {tri_ready_o, box_retire_o, walk_busy_o, walk_stall_o, walk_last_o,
                                walk_retire_o}, clk_i, !rst_ni)
  `ASSERT_KNOWN_IF(RetireTagKnown_A, box_retire_o, box_retire_tag_o, clk_i, !rst_ni)
  `ASSERT_KNOWN_IF(WalkTagKnown_A, walk_busy_o, walk_tag_o, clk_i, !rst_ni)
  // The triangle port: a triangle offered and not taken stays (the harness offers back to back).
  `ASSERT_NEXT(TriValidHeld_A, tri_valid_i && !tri_ready_o, tri_valid_i, clk_i, !rst_ni)

  // The triangle port's preconditions (docs/port.md, "Preconditions"), simulation only.
`ifndef SYNTHESIS  // simulation only: neither synthesis nor the formal flow (Yosys)
`ifndef FORMAL
  `TRIRAST_TRIANGLE_PORT_CHECK(1'b1, CornerForm == 0, 1'b1, tri_a_i, tri_b_i, tri_c_i, tri_bias_i)
`endif  // FORMAL
`endif  // SYNTHESIS

endmodule
