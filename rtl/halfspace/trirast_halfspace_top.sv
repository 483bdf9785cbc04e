// The half-space (Pineda edge-function) tile unit (model/halfspace_*, docs/unit.md "The
// half-space unit", docs/timing.md "The half-space unit"):
//   setup stage (interface: box, edge values at the box corner) -> tile walker (unit tests,
//   stamp tester) -> span emitter (band buffers, one span per cycle) -> span FIFO and span port
//   (trirast_span_port, one push port).
// The triangle port is trirast_improved_top's; the span port and FIFO are the shared trirast_span_port.
// Build parameters: StampSize (1, 2, 4), TileSize (8, 16; 0 = no tiles), WalkZigzag.
// Every boundary is a valid/ready handshake: triangle port, hand-off, band hand-over to the
// emitter, FIFO push (admitted by the occupancy test count <= DEPTH - 1), span port.
`include "trirast_assert.svh"

module trirast_halfspace_top #(
  parameter int StampSize = 2,
  parameter int TileSize = 8,
  parameter bit WalkZigzag = 1'b1,
  parameter int FifoDepth = trirast_pkg::DefaultFifoDepth,     // span FIFO entries (power of 2)
  parameter int CountBits = $clog2(FifoDepth + 1)              // derived: do not override
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  // ---- configuration (static) ----
  input  logic [trirast_pkg::PixBits-1:0]       cfg_vp_xmax_i,
  input  logic [trirast_pkg::PixBits-1:0]       cfg_vp_ymax_i,
  input  logic [CountBits-1:0]                  cfg_fifo_depth_i,
  // ---- triangle port: one set-up triangle per handshake ----
  input  logic                                  tri_valid_i,
  output logic                                  tri_ready_o,
  input  logic [trirast_pkg::TagBits-1:0]       tri_tag_i,
  input  logic [3*trirast_pkg::VertexBits-1:0]  tri_vx_i,
  input  logic [3*trirast_pkg::VertexBits-1:0]  tri_vy_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]    tri_a_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]    tri_b_i,
  input  logic [3*trirast_pkg::EdgeBits-1:0]    tri_c_i,
  input  logic [2:0]                            tri_bias_i,
  // ---- span port ----
  output logic                                  span_valid_o,
  input  logic                                  span_ready_i,
  output logic [trirast_pkg::TagBits-1:0]       span_tag_o,
  output logic [trirast_pkg::PixBits-1:0]       span_y_o,
  output logic [trirast_pkg::PixBits-1:0]       span_x_begin_o,
  output logic [trirast_pkg::PixBits:0]         span_x_end_o,
  // ---- observation (the harness's per-triangle timing) ----
  output logic                                  box_retire_o,
  output logic [trirast_pkg::TagBits-1:0]       box_retire_tag_o,
  output logic                                  walk_busy_o,
  output logic                                  walk_stall_o,
  output logic                                  walk_last_o,
  output logic                                  walk_retire_o,
  output logic [trirast_pkg::TagBits-1:0]       walk_tag_o,
  output logic [CountBits-1:0]                  fifo_count_o,
  output logic [2:0]                            setup_state_o,    // StIdle, StBox, StEdge, StHold (0, 1, 2, 4)
  output logic                                  handoff_o,        // the walk stage loads
  output logic [trirast_pkg::BoxBits-1:0]       box_xmax_o,       // its box: Xmax, Ymax
  output logic [trirast_pkg::BoxBits-1:0]       box_ymax_o        //   (valid with handoff_o)
);
  localparam int PixBits = trirast_pkg::PixBits;
  localparam int TagBits = trirast_pkg::TagBits;
  localparam int BoxBits = trirast_pkg::BoxBits;
  localparam int CoefBits = trirast_pkg::CoefBits;
  localparam int EdgeBits = trirast_pkg::EdgeBits;
  localparam int PB = BoxBits + 1;
  localparam int EntryBits = TagBits + PixBits + PixBits + PixBits + 1;
  localparam int UnitSize = (TileSize > 0) ? TileSize : StampSize;

  logic hand_valid, hand_ready;
  logic [TagBits-1:0] hand_tag;
  logic [PixBits-1:0] hand_x0, hand_y0;
  logic [BoxBits-1:0] hand_xmax, hand_ymax;
  logic [3*CoefBits-1:0] hand_a, hand_b;
  logic [3*EdgeBits-1:0] hand_e0, hand_eend;
  logic [2:0] setup_state, walk_state;

  trirast_halfspace_setup_stage #(.UnitSize (UnitSize)) u_setup (
    .clk_i            (clk_i),
    .rst_ni           (rst_ni),
    .vp_xmax_i        (cfg_vp_xmax_i),
    .vp_ymax_i        (cfg_vp_ymax_i),
    .tri_valid_i      (tri_valid_i),
    .tri_ready_o      (tri_ready_o),
    .tri_tag_i        (tri_tag_i),
    .tri_vx_i         (tri_vx_i),
    .tri_vy_i         (tri_vy_i),
    .tri_a_i          (tri_a_i),
    .tri_b_i          (tri_b_i),
    .tri_c_i          (tri_c_i),
    .tri_bias_i       (tri_bias_i),
    .box_retire_o     (box_retire_o),
    .box_retire_tag_o (box_retire_tag_o),
    .hand_valid_o     (hand_valid),
    .hand_ready_i     (hand_ready),
    .hand_tag_o       (hand_tag),
    .hand_x0_o        (hand_x0),
    .hand_y0_o        (hand_y0),
    .hand_xmax_o      (hand_xmax),
    .hand_ymax_o      (hand_ymax),
    .hand_a_o         (hand_a),
    .hand_b_o         (hand_b),
    .hand_e0_o        (hand_e0),
    .hand_eend_o      (hand_eend),
    .state_o          (setup_state)
  );

  logic [TagBits-1:0] tag;
  logic [PixBits-1:0] x0, y0;
  logic [UnitSize-1:0] merge;
  logic [UnitSize*PB-1:0] merge_first, merge_last;
  logic band_load, emit_any, emit_free;
  logic [PB-1:0] band_j0;

  trirast_halfspace_tile_walker #(
    .StampSize  (StampSize),
    .TileSize   (TileSize),
    .WalkZigzag (WalkZigzag)
  ) u_walker (
    .clk_i         (clk_i),
    .rst_ni        (rst_ni),
    .hand_valid_i  (hand_valid),
    .hand_ready_o  (hand_ready),
    .hand_tag_i    (hand_tag),
    .hand_x0_i     (hand_x0),
    .hand_y0_i     (hand_y0),
    .hand_xmax_i   (hand_xmax),
    .hand_ymax_i   (hand_ymax),
    .hand_a_i      (hand_a),
    .hand_b_i      (hand_b),
    .hand_e0_i     (hand_e0),
    .hand_eend_i   (hand_eend),
    .tag_o         (tag),
    .x0_o          (x0),
    .y0_o          (y0),
    .merge_o       (merge),
    .merge_first_o (merge_first),
    .merge_last_o  (merge_last),
    .band_load_o   (band_load),
    .band_j0_o     (band_j0),
    .emit_any_i    (emit_any),
    .emit_free_i   (emit_free),
    .busy_o        (walk_busy_o),
    .last_o        (walk_last_o),
    .retire_o      (walk_retire_o),
    .state_o       (walk_state)
  );

  logic push;
  logic [EntryBits-1:0] push_data;

  trirast_halfspace_span_emitter #(
    .UnitSize  (UnitSize),
    .CountBits (CountBits),
    .EntryBits (EntryBits)
  ) u_emitter (
    .clk_i         (clk_i),
    .rst_ni        (rst_ni),
    .fifo_depth_i  (cfg_fifo_depth_i),
    .fifo_count_i  (fifo_count_o),
    .tag_i         (tag),
    .x0_i          (x0),
    .y0_i          (y0),
    .merge_i       (merge),
    .merge_first_i (merge_first),
    .merge_last_i  (merge_last),
    .band_load_i   (band_load),
    .band_j0_i     (band_j0),
    .any_o         (emit_any),
    .free_o        (emit_free),
    .push_o        (push),
    .push_data_o   (push_data),
    .stall_o       (walk_stall_o)
  );
  assign walk_tag_o = tag;
  assign setup_state_o = setup_state;
  assign handoff_o = hand_valid && hand_ready;
  assign box_xmax_o = hand_xmax;
  assign box_ymax_o = hand_ymax;

  // Observed in traces only.
  logic unused_obs;
  assign unused_obs = ^walk_state;

  trirast_span_port #(.FifoDepth (FifoDepth)) u_span_port (
    .clk_i (clk_i), .rst_ni (rst_ni),
    .push_i (push), .push_data_i (push_data), .count_o (fifo_count_o),
    .span_valid_o (span_valid_o), .span_ready_i (span_ready_i), .span_tag_o (span_tag_o),
    .span_y_o (span_y_o), .span_x_begin_o (span_x_begin_o), .span_x_end_o (span_x_end_o));

  `ASSERT(CfgFifoDepthInRange_A, cfg_fifo_depth_i != '0 && 32'(cfg_fifo_depth_i) <= FifoDepth,
          clk_i, !rst_ni)
  `ASSERT_KNOWN(StrobesKnown_A, {tri_ready_o, box_retire_o, walk_busy_o, walk_stall_o, walk_last_o,
                                walk_retire_o}, clk_i, !rst_ni)
  `ASSERT(RetireTagKnown_A, box_retire_o |-> !$isunknown(box_retire_tag_o), clk_i, !rst_ni)
  `ASSERT(WalkTagKnown_A, walk_busy_o |-> !$isunknown(walk_tag_o), clk_i, !rst_ni)
  // The triangle port: a triangle offered and not taken stays (the harness offers back to back).
  `ASSERT(TriValidHeld_A, tri_valid_i && !tri_ready_o |=> tri_valid_i, clk_i, !rst_ni)
endmodule
