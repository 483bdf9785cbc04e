// The traditional-Bresenham unit (model/trad_bresenham.*, docs/timing.md "The traditional
// unit"), the baseline of the improved unit (trirast_improved_top) with the same port protocol:
//   setup stage (quantizer + sorter, line set-up) -> walk stage (long-edge walker, short-side
//   walker, span filler) -> span FIFO and span port
//   (trirast_span_port, one push port).
// Every boundary is a valid/ready handshake: triangle port, hand-off, FIFO push (admitted by the
// occupancy test count <= DEPTH - 1), span port. The cfg_* inputs are static during a run.
// Differences from trirast_improved_top's ports (docs/rtl.md): the triangle port carries the vertices only
// (no edge functions: the unit draws Bresenham lines between integer pixels); no boundary,
// divider or endpoints configuration; setup_retire_o (collinear pixels, StSort) stands where
// trirast_improved_top has box_retire_o (empty box, StBox).
`include "trirast_assert.svh"
`include "trirast_ports.svh"

module trirast_trad_top #(
  parameter int FifoDepth = trirast_pkg::DefaultFifoDepth,     // span FIFO entries (power of 2)
  parameter int CountBits = $clog2(FifoDepth + 1)              // derived: do not override
) (
  // ---- clock, reset and configuration (static) ----
  `TRIRAST_TOP_CLOCK_AND_VIEWPORT,
  input  logic [CountBits-1:0]                  cfg_fifo_depth_i, // --fifo-depth (<= FifoDepth)
  // ---- triangle port: one set-up triangle per handshake ----
  `TRIRAST_TRIANGLE_PORT_VERTICES,
  // ---- span port ----
  `TRIRAST_SPAN_PORT,
  // ---- observation (the harness's per-triangle timing) ----
  output logic                                  setup_retire_o,   // collinear retires (StSort)
  output logic [trirast_pkg::TagBits-1:0]       setup_retire_tag_o, // ... its tag
  `TRIRAST_WALK_OBSERVATION,
  // ---- observation of the setup stage (the harness's stage breakdown, docs/rtl.md) ----
  output logic [2:0]                            setup_state_o,    // StIdle, StSort, StLine, StHold
  output logic                                  handoff_o,        // the walk stage loads
  output logic [3*trirast_pkg::CoordIntBits-1:0] hand_px_o,       // its sorted pixels p0..p2
  output logic [3*trirast_pkg::CoordIntBits-1:0] hand_py_o        //   (valid with handoff_o)
);
  `TRIRAST_PKG_NAMES
  localparam int DecBits = CoordIntBits + 3;
  localparam int EntryBits = TagBits + PixBits + PixBits + PixBits + 1;
  // The walk stage's coordinate width (its derived parameter WBits).
  localparam int WBits = ((CoordIntBits > PixBits + 1) ? CoordIntBits : PixBits + 1) + 2;

  // Hand-off bundle.
  logic hand_valid, hand_ready;
  `TRIRAST_TRIANGLE_READY_GATE
  logic [TagBits-1:0] hand_tag;
  logic [3*CoordIntBits-1:0] hand_px, hand_py, hand_dmaj, hand_dmin;
  logic [2:0] hand_sx_neg, hand_x_major;
  logic [2:0] setup_state /* verilator public_flat_rd */;  // observation (trace, busy counts)
  logic [3*DecBits-1:0] hand_d0;

  trirast_trad_setup_stage u_setup (
    .clk_i          (clk_i),
    .rst_ni         (rst_ni),
    `TRIRAST_CONNECT_TRIANGLE_PORT_VERTICES,
    .retire_o       (setup_retire_o),
    .retire_tag_o   (setup_retire_tag_o),
    .hand_valid_o   (hand_valid),
    .hand_ready_i   (hand_ready),
    `TRIRAST_CONNECT_TRAD_HANDOFF(_o),
    .state_o        (setup_state)
  );

  logic push;
  logic [EntryBits-1:0] push_data;
  logic [WBits-1:0] walk_row;
  logic unused_obs;  // walk_row is observed in traces only
  assign unused_obs = ^walk_row;

  trirast_trad_walk_stage #(
    .CountBits (CountBits),
    .EntryBits (EntryBits)
  ) u_walk (
    .clk_i          (clk_i),
    .rst_ni         (rst_ni),
    .vp_xmax_i      (cfg_vp_xmax_i),
    .vp_ymax_i      (cfg_vp_ymax_i),
    .fifo_depth_i   (cfg_fifo_depth_i),
    .hand_valid_i   (hand_valid),
    .hand_ready_o   (hand_ready),
    `TRIRAST_CONNECT_TRAD_HANDOFF(_i),
    `TRIRAST_CONNECT_WALK_STAGE_OUTPUTS
  );

  // Observation outputs; the walk row is observed in traces only.
  assign setup_state_o = setup_state;
  assign handoff_o = hand_valid && hand_ready;
  assign {hand_px_o, hand_py_o} = {hand_px, hand_py};

  trirast_span_port #(.FifoDepth (FifoDepth)) u_span_port (
    `TRIRAST_CONNECT_SPAN_PORT);

  // Runtime configuration within the hardware maximum: 1 <= DEPTH <= FifoDepth.
  `ASSERT(CfgFifoDepthInRange_A, cfg_fifo_depth_i != '0 && 32'(cfg_fifo_depth_i) <= FifoDepth,
          clk_i, !rst_ni)
  // Known values on the outputs (the span port's are checked in trirast_span_port): the handshake
  // and observation strobes always, a tag when its strobe is high.
  `ASSERT_KNOWN(StrobesKnown_A, {tri_ready_o, setup_retire_o, walk_busy_o, walk_stall_o, walk_last_o,
                                walk_retire_o, setup_state_o, handoff_o}, clk_i, !rst_ni)
  `ASSERT_KNOWN_IF(HandPixelsKnown_A, handoff_o, {hand_px_o, hand_py_o}, clk_i, !rst_ni)
  `ASSERT_KNOWN_IF(RetireTagKnown_A, setup_retire_o, setup_retire_tag_o, clk_i, !rst_ni)
  `ASSERT_KNOWN_IF(WalkTagKnown_A, walk_busy_o, walk_tag_o, clk_i, !rst_ni)

  // The triangle port's preconditions (docs/port.md, "Preconditions"; the vertices only: this
  // port has no edge functions and the unit no box), simulation only.
`ifndef SYNTHESIS  // simulation only: neither synthesis nor the formal flow (Yosys)
`ifndef FORMAL
  `TRIRAST_TRIANGLE_PORT_CHECK(1'b0, 1'b0, 1'b0, '0, '0, '0, '0)
`endif  // FORMAL
`endif  // SYNTHESIS

endmodule
