// The improved-Bresenham unit (docs/unit.md, docs/timing.md):
//   setup stage (interface, 3 normalizers, 3 edge lanes) -> walk stage (3 walkers,
//   NumEndpoints span generators) -> span FIFO and span port (trirast_span_port).
// Every boundary is a valid/ready handshake: triangle port, hand-off, FIFO pushes (admitted by
// the occupancy test), span port. The cfg_* inputs are static during a run (docs/rtl.md).
`include "trirast_assert.svh"

module trirast_improved_top #(
  parameter int NumEndpoints = trirast_pkg::DefaultEndpoints,  // rows per cycle (hardware)
  parameter int FifoDepth = trirast_pkg::DefaultFifoDepth,     // span FIFO entries (power of 2)
  parameter int CountBits = $clog2(FifoDepth + 1)              // derived: do not override
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  // ---- configuration (static) ----
  input  logic [trirast_pkg::PixBits-1:0]       cfg_vp_xmax_i,    // viewport width - 1
  input  logic [trirast_pkg::PixBits-1:0]       cfg_vp_ymax_i,    // viewport height - 1
  input  logic                                  cfg_divide_i,     // --boundary divide
  input  logic                                  cfg_adaptive_i,   // --divider adaptive
  input  logic [2:0]                            cfg_endpoints_i,  // --endpoints (<= NumEndpoints)
  input  logic [CountBits-1:0]                  cfg_fifo_depth_i, // --fifo-depth (<= FifoDepth)
  // ---- triangle port: one set-up triangle per handshake ----
  input  logic                                  tri_valid_i,
  output logic                                  tri_ready_o,
  input  logic [trirast_pkg::TagBits-1:0]       tri_tag_i,        // returned with its spans
  input  logic [3*trirast_pkg::VertexBits-1:0]  tri_vx_i,         // vertex k: [k*p +: p] signed
  input  logic [3*trirast_pkg::VertexBits-1:0]  tri_vy_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]    tri_a_i,          // edge k: A signed
  input  logic [3*trirast_pkg::CoefBits-1:0]    tri_b_i,          // edge k: B signed
  input  logic [3*trirast_pkg::EdgeBits-1:0]    tri_c_i,          // edge k: C signed
  input  logic [2:0]                            tri_bias_i,       // edge k: 1 = bias -1
  // ---- span port ----
  output logic                                  span_valid_o,
  input  logic                                  span_ready_i,
  output logic [trirast_pkg::TagBits-1:0]       span_tag_o,
  output logic [trirast_pkg::PixBits-1:0]       span_y_o,
  output logic [trirast_pkg::PixBits-1:0]       span_x_begin_o,
  output logic [trirast_pkg::PixBits:0]         span_x_end_o,     // exclusive
  // ---- observation (the harness's per-triangle timing) ----
  output logic                                  box_retire_o,     // empty box retires (StBox)
  output logic [trirast_pkg::TagBits-1:0]       box_retire_tag_o,
  output logic                                  walk_busy_o,      // walk stage in StWalk
  output logic                                  walk_stall_o,     // a stall cycle
  output logic                                  walk_last_o,      // its last group goes
  output logic                                  walk_retire_o,    // ... and it has no span
  output logic [trirast_pkg::TagBits-1:0]       walk_tag_o,
  output logic [CountBits-1:0]                  fifo_count_o,     // occupancy at cycle start
  // ---- observation of the setup stage (the harness's stage breakdown, docs/rtl.md) ----
  output logic [2:0]                            setup_state_o,    // StIdle..StHold (0..4)
  output logic [2:0]                            lane_busy_o,      // lane k works this cycle
  output logic [2:0]                            lane_div_o,       // ... a divider iteration
  output logic                                  handoff_o,        // the walk stage loads
  output logic [trirast_pkg::BoxBits-1:0]       box_xmax_o,       // its box: Xmax, Ymax
  output logic [trirast_pkg::BoxBits-1:0]       box_ymax_o        //   (valid with handoff_o)
);
  localparam int PixBits = trirast_pkg::PixBits;
  localparam int TagBits = trirast_pkg::TagBits;
  localparam int StepBits = trirast_pkg::StepBits;
  localparam int QuotBits = trirast_pkg::QuotBits;
  localparam int RemBits = trirast_pkg::RemBits;
  localparam int RowBits = trirast_pkg::RowBits;
  localparam int XBits = trirast_pkg::WalkerXBits;
  localparam int BoxBits = trirast_pkg::BoxBits;
  localparam int EntryBits = TagBits + PixBits + PixBits + PixBits + 1;

  // Hand-off bundle.
  logic hand_valid, hand_ready;
  logic [TagBits-1:0] hand_tag;
  logic [PixBits-1:0] hand_x0, hand_y0;
  logic [BoxBits-1:0] hand_xmax, hand_ymax;
  logic [2:0] hand_mirror, hand_dir_down, hand_ssat, hand_enters;
  logic [3*StepBits-1:0] hand_d;
  logic [3*QuotBits-1:0] hand_qs;
  logic [3*RemBits-1:0] hand_rs, hand_entry_e;
  logic [3*RowBits-1:0] hand_j_entry;
  logic [5:0] hand_entry_state;
  logic [3*XBits-1:0] hand_entry_x;
  // Observation signals (the trace; the harness counts module busy cycles from them, hence
  // public: Verilator keeps them even in a build without tracing).
  logic [2:0] setup_state /* verilator public_flat_rd */;
  logic [2:0] lane_busy /* verilator public_flat_rd */;
  logic [2:0] lane_div;
  logic [RowBits-1:0] walk_row;

  trirast_improved_setup_stage u_setup (
    .clk_i              (clk_i),
    .rst_ni             (rst_ni),
    .vp_xmax_i          (cfg_vp_xmax_i),
    .vp_ymax_i          (cfg_vp_ymax_i),
    .divide_i           (cfg_divide_i),
    .adaptive_i         (cfg_adaptive_i),
    .tri_valid_i        (tri_valid_i),
    .tri_ready_o        (tri_ready_o),
    .tri_tag_i          (tri_tag_i),
    .tri_vx_i           (tri_vx_i),
    .tri_vy_i           (tri_vy_i),
    .tri_a_i            (tri_a_i),
    .tri_b_i            (tri_b_i),
    .tri_c_i            (tri_c_i),
    .tri_bias_i         (tri_bias_i),
    .box_retire_o       (box_retire_o),
    .box_retire_tag_o   (box_retire_tag_o),
    .hand_valid_o       (hand_valid),
    .hand_ready_i       (hand_ready),
    .hand_tag_o         (hand_tag),
    .hand_x0_o          (hand_x0),
    .hand_y0_o          (hand_y0),
    .hand_xmax_o        (hand_xmax),
    .hand_ymax_o        (hand_ymax),
    .hand_mirror_o      (hand_mirror),
    .hand_dir_down_o    (hand_dir_down),
    .hand_d_o           (hand_d),
    .hand_qs_o          (hand_qs),
    .hand_rs_o          (hand_rs),
    .hand_ssat_o        (hand_ssat),
    .hand_enters_o      (hand_enters),
    .hand_j_entry_o     (hand_j_entry),
    .hand_entry_state_o (hand_entry_state),
    .hand_entry_x_o     (hand_entry_x),
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
    .hand_tag_i         (hand_tag),
    .hand_x0_i          (hand_x0),
    .hand_y0_i          (hand_y0),
    .hand_xmax_i        (hand_xmax),
    .hand_ymax_i        (hand_ymax),
    .hand_mirror_i      (hand_mirror),
    .hand_dir_down_i    (hand_dir_down),
    .hand_d_i           (hand_d),
    .hand_qs_i          (hand_qs),
    .hand_rs_i          (hand_rs),
    .hand_ssat_i        (hand_ssat),
    .hand_enters_i      (hand_enters),
    .hand_j_entry_i     (hand_j_entry),
    .hand_entry_state_i (hand_entry_state),
    .hand_entry_x_i     (hand_entry_x),
    .hand_entry_e_i     (hand_entry_e),
    .fifo_count_i       (fifo_count_o),
    .push_o             (push),
    .push_data_o        (push_data),
    .busy_o             (walk_busy_o),
    .stall_o            (walk_stall_o),
    .last_o             (walk_last_o),
    .retire_o           (walk_retire_o),
    .tag_o              (walk_tag_o),
    .row_o              (walk_row)
  );

  // Observation outputs; the walk row is observed in traces only.
  assign setup_state_o = setup_state;
  assign lane_busy_o   = lane_busy;
  assign lane_div_o    = lane_div;
  assign handoff_o     = hand_valid && hand_ready;
  assign box_xmax_o    = hand_xmax;
  assign box_ymax_o    = hand_ymax;
  logic unused_obs;
  assign unused_obs = ^walk_row;

  trirast_span_port #(.NumEndpoints (NumEndpoints), .FifoDepth (FifoDepth)) u_span_port (
    .clk_i (clk_i), .rst_ni (rst_ni),
    .push_i (push), .push_data_i (push_data), .count_o (fifo_count_o),
    .span_valid_o (span_valid_o), .span_ready_i (span_ready_i), .span_tag_o (span_tag_o),
    .span_y_o (span_y_o), .span_x_begin_o (span_x_begin_o), .span_x_end_o (span_x_end_o));

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
  `ASSERT(BoxKnown_A, handoff_o |-> !$isunknown({box_xmax_o, box_ymax_o}), clk_i, !rst_ni)
  `ASSERT(RetireTagKnown_A, box_retire_o |-> !$isunknown(box_retire_tag_o), clk_i, !rst_ni)
  `ASSERT(WalkTagKnown_A, walk_busy_o |-> !$isunknown(walk_tag_o), clk_i, !rst_ni)

endmodule
