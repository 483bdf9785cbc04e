// The improved-Bresenham unit (docs/unit.md, docs/timing.md):
//   setup stage (interface, 3 normalizers, 3 edge lanes) -> walk stage (3 walkers,
//   NumEndpoints span generators) -> span FIFO and span port (trirast_span_port).
// Every boundary is a valid/ready handshake: triangle port, hand-off, FIFO pushes (admitted by
// the occupancy test), span port. The cfg_* inputs are static during a run (docs/rtl.md).
`include "trirast_assert.svh"
`include "trirast_ports.svh"

module trirast_improved_top #(
  parameter int NumEndpoints = trirast_pkg::DefaultEndpoints,  // rows per cycle (hardware)
  parameter int FifoDepth = trirast_pkg::DefaultFifoDepth,     // span FIFO entries (power of 2)
  parameter int CountBits = $clog2(FifoDepth + 1)              // derived: do not override
) (
  // ---- clock, reset and configuration (static) ----
  `TRIRAST_TOP_CLOCK_AND_VIEWPORT,
  input  logic                                  cfg_divide_i,     // --boundary divide
  input  logic                                  cfg_adaptive_i,   // --divider adaptive
  input  logic [2:0]                            cfg_endpoints_i,  // --endpoints (<= NumEndpoints)
  input  logic [CountBits-1:0]                  cfg_fifo_depth_i, // --fifo-depth (<= FifoDepth)
  // ---- triangle port: one set-up triangle per handshake ----
  `TRIRAST_TRIANGLE_PORT,
  // ---- span port ----
  `TRIRAST_SPAN_PORT,
  // ---- observation (the harness's per-triangle timing) ----
  output logic                                  box_retire_o,     // empty box retires (StBox)
  output logic [trirast_pkg::TagBits-1:0]       box_retire_tag_o, // ... its tag
  `TRIRAST_WALK_OBSERVATION,
  // ---- observation of the setup stage (the harness's stage breakdown, docs/rtl.md) ----
  output logic [2:0]                            setup_state_o,    // StIdle..StHold (0..4)
  output logic [2:0]                            lane_busy_o,      // lane k works this cycle
  output logic [2:0]                            lane_div_o,       // ... a divider iteration
  output logic                                  handoff_o,        // the walk stage loads
  output logic [trirast_pkg::BoxBits-1:0]       box_xmax_o,       // its box: Xmax, Ymax
  output logic [trirast_pkg::BoxBits-1:0]       box_ymax_o        //   (valid with handoff_o)
);
  `TRIRAST_PKG_NAMES
  localparam int EntryBits = TagBits + PixBits + PixBits + PixBits + 1;

  // Hand-off bundle.
  logic hand_valid, hand_ready;
  `TRIRAST_TRIANGLE_READY_GATE
  `TRIRAST_HANDOFF_BOX_SIGNALS(hand_)
  `TRIRAST_IMPROVED_HANDOFF_EDGES_SIGNALS(hand_)
  logic [3*RemBits-1:0] hand_entry_e;
  // Observation signals (the trace; the harness counts module busy cycles from them, hence
  // public: Verilator keeps them even in a build without tracing).
  logic [2:0] setup_state /* verilator public_flat_rd */;
  logic [2:0] lane_busy /* verilator public_flat_rd */;
  logic [2:0] lane_div;
  logic [RowBits-1:0] walk_row;
  logic unused_obs;  // walk_row is observed in traces only
  assign unused_obs = ^walk_row;

  trirast_improved_setup_stage u_setup (
    `TRIRAST_CONNECT_SETUP_STAGE,
    .divide_i           (cfg_divide_i),
    .adaptive_i         (cfg_adaptive_i),
    `TRIRAST_CONNECT_IMPROVED_HANDOFF_EDGES(_o),
    .hand_entry_e_o     (hand_entry_e),
    .state_o            (setup_state),
    .lane_busy_o        (lane_busy),
    .lane_div_o         (lane_div)
  );

  logic [NumEndpoints-1:0] push;
  logic [NumEndpoints*EntryBits-1:0] push_data;

  trirast_improved_walk_stage #(
    .NumEndpoints (NumEndpoints),
    .CountBits    (CountBits),
    .EntryBits    (EntryBits)
  ) u_walk (
    .clk_i              (clk_i),
    .rst_ni             (rst_ni),
    .endpoints_i        (cfg_endpoints_i),
    .fifo_depth_i       (cfg_fifo_depth_i),
    .hand_valid_i       (hand_valid),
    .hand_ready_o       (hand_ready),
    `TRIRAST_CONNECT_HANDOFF_BOX(_i),
    `TRIRAST_CONNECT_IMPROVED_HANDOFF_EDGES(_i),
    .hand_entry_e_i     (hand_entry_e),
    `TRIRAST_CONNECT_WALK_STAGE_OUTPUTS
  );

  // Observation outputs.
  assign {setup_state_o, lane_busy_o, lane_div_o} = {setup_state, lane_busy, lane_div};
  `TRIRAST_ASSIGN_HANDOFF_OBSERVATION(hand_xmax, hand_ymax)

  trirast_span_port #(.NumEndpoints (NumEndpoints), .FifoDepth (FifoDepth)) u_span_port (
    `TRIRAST_CONNECT_SPAN_PORT);

  // Runtime configuration within the hardware maximums: 1 <= n <= NumEndpoints and
  // n <= DEPTH <= FifoDepth (a larger n or DEPTH would overflow the walk stage or the FIFO).
  `ASSERT(CfgEndpointsInRange_A, cfg_endpoints_i >= 3'd1 && 32'(cfg_endpoints_i) <= NumEndpoints,
          clk_i, !rst_ni)
  `ASSERT(CfgFifoDepthInRange_A, 32'(cfg_fifo_depth_i) >= 32'(cfg_endpoints_i) &&
          32'(cfg_fifo_depth_i) <= FifoDepth, clk_i, !rst_ni)
  `ASSERT_INIT(NumEndpointsInRange_A, NumEndpoints >= 1 && NumEndpoints <= 7)
  // Known values on the outputs (the span port's are checked in trirast_span_port): the handshake
  // and observation strobes always, a tag when its strobe is high.
  `ASSERT_KNOWN(StrobesKnown_A, {tri_ready_o, box_retire_o, walk_busy_o, walk_stall_o, walk_last_o,
                                walk_retire_o, setup_state_o, lane_busy_o, lane_div_o, handoff_o},
                clk_i, !rst_ni)
  `ASSERT_KNOWN_IF(BoxKnown_A, handoff_o, {box_xmax_o, box_ymax_o}, clk_i, !rst_ni)
  `ASSERT_KNOWN_IF(RetireTagKnown_A, box_retire_o, box_retire_tag_o, clk_i, !rst_ni)
  `ASSERT_KNOWN_IF(WalkTagKnown_A, walk_busy_o, walk_tag_o, clk_i, !rst_ni)

  // The triangle port's preconditions (docs/port.md, "Preconditions"), simulation only.
`ifndef SYNTHESIS  // simulation only: neither synthesis nor the formal flow (Yosys)
`ifndef FORMAL
  `TRIRAST_TRIANGLE_PORT_CHECK(1'b1, 1'b1, 1'b1, tri_a_i, tri_b_i, tri_c_i, tri_bias_i)
`endif  // FORMAL
`endif  // SYNTHESIS

endmodule
