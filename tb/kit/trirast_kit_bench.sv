// Testbench kit: the bench top. It runs one unit's top (rtl/UNIT/trirast_UNIT_top.sv), chosen by
// a define (TRIRAST_KIT_IMPROVED, TRIRAST_KIT_IMPROVED2, TRIRAST_KIT_TRAD or TRIRAST_KIT_HALFSPACE),
// at the parameters below (tb/kit/run.sh sets them from the vectors' params.txt), between the
// kit's driver, downstream, monitor and scoreboard. The static configuration inputs come from
// plusargs (+vp_xmax +vp_ymax +fifo_depth +endpoints +divide +adaptive; the vectors' plusargs.txt).
// Clock period 10 time units; reset for two rising edges; cycle 0 is the first cycle after it.
// Files: tb/kit/trirast_kit.f with the unit's rtl/UNIT/trirast_UNIT.f, include dir rtl/common.
`include "trirast_ports.svh"

module trirast_kit_bench #(
  // the unit top's parameters (those the unit has; the others are unused)
  parameter int NumEndpoints = 1,  // improved, improved2
  parameter int FifoDepth = 8,     // every unit (a power of two)
  parameter int CornerForm = 1,    // improved2, halfspace (the vectors' params file sets it)
  parameter int StampSize = 2,     // halfspace
  parameter int TileSize = 8,      // halfspace
  parameter int WalkMode = 2,      // halfspace: 0 row, 1 zigzag, 2 forward
  // the bench's memories: triangles and expected spans it can hold
  parameter int MaxTris = 1024,
  parameter int MaxSpans = 65536
);
  `TRIRAST_PKG_NAMES
  localparam int CountBits = $clog2(FifoDepth + 1);
`ifdef TRIRAST_KIT_TRAD
  // The traditional unit's port: {tri_vy_i, tri_vx_i, tri_tag_i}.
  localparam int TriBits = TagBits + 6 * VertexBits;
`else
  // {tri_bias_i, tri_c_i, tri_b_i, tri_a_i, tri_vy_i, tri_vx_i, tri_tag_i}
  localparam int TriBits = TagBits + 6 * VertexBits + 6 * CoefBits + 3 * EdgeBits + 3;
`endif

  logic clk, rst_n;
  logic [63:0] cycle;  // the cycle number: 0 in the first cycle after reset

  initial begin
    clk = 1'b0;
    rst_n = 1'b0;
    #22 rst_n = 1'b1;  // after the rising edges at 5 and 15, with the clock low
  end
  always #5 clk = ~clk;
  always @(posedge clk or negedge rst_n) begin
    if (!rst_n) cycle <= 64'd0;
    else cycle <= cycle + 64'd1;
  end

  // ---- static configuration ----
  int vp_xmax, vp_ymax, fifo_depth, endpoints, divide, adaptive;
  initial begin
    if (!$value$plusargs("vp_xmax=%d", vp_xmax)) $fatal(1, "kit bench: +vp_xmax missing");
    if (!$value$plusargs("vp_ymax=%d", vp_ymax)) $fatal(1, "kit bench: +vp_ymax missing");
    if (!$value$plusargs("fifo_depth=%d", fifo_depth)) fifo_depth = FifoDepth;
    if (!$value$plusargs("endpoints=%d", endpoints)) endpoints = NumEndpoints;
    if (!$value$plusargs("divide=%d", divide)) divide = 0;
    if (!$value$plusargs("adaptive=%d", adaptive)) adaptive = 1;
    if (fifo_depth < 1 || fifo_depth > FifoDepth)
      $fatal(1, "kit bench: +fifo_depth=%0d is outside 1..FifoDepth %0d", fifo_depth, FifoDepth);
    if (endpoints < 1 || endpoints > NumEndpoints)
      $fatal(1, "kit bench: +endpoints=%0d is outside 1..NumEndpoints %0d", endpoints, NumEndpoints);
  end
  wire [PixBits-1:0] cfg_vp_xmax = PixBits'(vp_xmax);
  wire [PixBits-1:0] cfg_vp_ymax = PixBits'(vp_ymax);
  wire [CountBits-1:0] cfg_fifo_depth = CountBits'(fifo_depth);
  wire [2:0] cfg_endpoints = 3'(endpoints);

  // ---- triangle port ----
  logic tri_valid, tri_ready, all_sent;
  logic [TriBits-1:0] tri_data;
  logic [31:0] next_tri;
  wire [TagBits-1:0] tri_tag = tri_data[0 +: TagBits];
  wire [3*VertexBits-1:0] tri_vx = tri_data[TagBits +: 3 * VertexBits];
  wire [3*VertexBits-1:0] tri_vy = tri_data[TagBits + 3 * VertexBits +: 3 * VertexBits];
`ifndef TRIRAST_KIT_TRAD
  localparam int EdgeAt = TagBits + 6 * VertexBits;
  wire [3*CoefBits-1:0] tri_a = tri_data[EdgeAt +: 3 * CoefBits];
  wire [3*CoefBits-1:0] tri_b = tri_data[EdgeAt + 3 * CoefBits +: 3 * CoefBits];
  wire [3*EdgeBits-1:0] tri_c = tri_data[EdgeAt + 6 * CoefBits +: 3 * EdgeBits];
  wire [2:0] tri_bias = tri_data[EdgeAt + 6 * CoefBits + 3 * EdgeBits +: 3];
`endif

  // ---- span port and observation ----
  logic span_valid, span_ready;
  logic [TagBits-1:0] span_tag;
  logic [PixBits-1:0] span_y, span_x_begin;
  logic [PixBits:0] span_x_end;
  logic early_retire, walk_busy, walk_stall, walk_last, walk_retire;
  logic [TagBits-1:0] early_retire_tag, walk_tag;
  logic [CountBits-1:0] fifo_count;
  logic unit_idle;  // no triangle in the unit: the run is over once every triangle went in

`define TRIRAST_KIT_COMMON_PORTS \
    .clk_i (clk), .rst_ni (rst_n), .cfg_vp_xmax_i (cfg_vp_xmax), .cfg_vp_ymax_i (cfg_vp_ymax), \
    .cfg_fifo_depth_i (cfg_fifo_depth), \
    .tri_valid_i (tri_valid), .tri_ready_o (tri_ready), .tri_tag_i (tri_tag), \
    .tri_vx_i (tri_vx), .tri_vy_i (tri_vy), \
    .span_valid_o (span_valid), .span_ready_i (span_ready), .span_tag_o (span_tag), \
    .span_y_o (span_y), .span_x_begin_o (span_x_begin), .span_x_end_o (span_x_end), \
    .walk_busy_o (walk_busy), .walk_stall_o (walk_stall), .walk_last_o (walk_last), \
    .walk_retire_o (walk_retire), .walk_tag_o (walk_tag), .fifo_count_o (fifo_count)
`define TRIRAST_KIT_EDGE_PORTS \
    .tri_a_i (tri_a), .tri_b_i (tri_b), .tri_c_i (tri_c), .tri_bias_i (tri_bias)

`ifdef TRIRAST_KIT_IMPROVED
  assign unit_idle = tri_ready && !walk_busy && !span_valid;
  trirast_improved_top #(
    .NumEndpoints (NumEndpoints),
    .FifoDepth    (FifoDepth)
  ) u_dut (
    `TRIRAST_KIT_COMMON_PORTS,
    `TRIRAST_KIT_EDGE_PORTS,
    .cfg_divide_i (divide != 0), .cfg_adaptive_i (adaptive != 0), .cfg_endpoints_i (cfg_endpoints),
    .box_retire_o (early_retire), .box_retire_tag_o (early_retire_tag),
    .setup_state_o (), .lane_busy_o (), .lane_div_o (), .handoff_o (), .box_xmax_o (),
    .box_ymax_o ()
  );
`elsif TRIRAST_KIT_IMPROVED2
  // A pipelined setup (box, corner and job stages): busy_o says whether a triangle is inside.
  logic busy;
  assign unit_idle = !busy;
  trirast_improved2_top #(
    .NumEndpoints (NumEndpoints),
    .FifoDepth    (FifoDepth),
    .CornerForm   (CornerForm)
  ) u_dut (
    `TRIRAST_KIT_COMMON_PORTS,
    `TRIRAST_KIT_EDGE_PORTS,
    .cfg_endpoints_i (cfg_endpoints), .busy_o (busy),
    .box_retire_o (early_retire), .box_retire_tag_o (early_retire_tag),
    .box_valid_o (), .box_stall_o (), .box_tag_o (), .corner_valid_o (), .corner_stall_o (),
    .job_valid_o (), .job_ready_o (), .job_tag_o (), .handoff_o (), .box_xmax_o (),
    .box_ymax_o (), .lane_busy_o (), .lane_div_o (), .lane_step_o ()
  );
`elsif TRIRAST_KIT_TRAD
  assign unit_idle = tri_ready && !walk_busy && !span_valid;
  trirast_trad_top #(
    .FifoDepth (FifoDepth)
  ) u_dut (
    `TRIRAST_KIT_COMMON_PORTS,
    .setup_retire_o (early_retire), .setup_retire_tag_o (early_retire_tag),
    .setup_state_o (), .handoff_o (), .hand_px_o (), .hand_py_o ()
  );
`elsif TRIRAST_KIT_HALFSPACE
  assign unit_idle = tri_ready && !walk_busy && !span_valid;
  trirast_halfspace_top #(
    .StampSize  (StampSize),
    .TileSize   (TileSize),
    .WalkMode   (WalkMode),
    .CornerForm (CornerForm),
    .FifoDepth  (FifoDepth)
  ) u_dut (
    `TRIRAST_KIT_COMMON_PORTS,
    `TRIRAST_KIT_EDGE_PORTS,
    .box_retire_o (early_retire), .box_retire_tag_o (early_retire_tag),
    .setup_state_o (), .handoff_o (), .box_xmax_o (), .box_ymax_o ()
  );
`else
  // No unit chosen: this instance of a module nobody defines makes the build fail, naming it.
  trirast_kit_define_one_of_TRIRAST_KIT_IMPROVED_IMPROVED2_TRAD_HALFSPACE u_no_unit ();
`endif

  // ---- the kit ----
  trirast_kit_driver #(
    .TriBits (TriBits),
    .MaxTris (MaxTris)
  ) u_driver (
    .clk (clk), .rst_n (rst_n), .tri_ready (tri_ready), .tri_valid (tri_valid),
    .tri_data (tri_data), .next_tri (next_tri), .all_sent (all_sent)
  );

  trirast_kit_downstream u_downstream (.cycle (cycle), .span_ready (span_ready));

  logic take;
  int protocol_errors;
  trirast_kit_monitor #(
    .TagBits (TagBits),
    .PixBits (PixBits)
  ) u_monitor (
    .clk (clk), .rst_n (rst_n), .cycle (cycle), .span_valid (span_valid),
    .span_ready (span_ready), .span_tag (span_tag), .span_y (span_y),
    .span_x_begin (span_x_begin), .span_x_end (span_x_end), .take (take),
    .protocol_errors (protocol_errors)
  );

  trirast_kit_scoreboard #(
    .TagBits  (TagBits),
    .PixBits  (PixBits),
    .MaxTris  (MaxTris),
    .MaxSpans (MaxSpans)
  ) u_scoreboard (
    .clk (clk), .rst_n (rst_n), .cycle (cycle),
    .accept (tri_valid && tri_ready), .accept_tag (next_tri),
    .retire (early_retire), .retire_tag (early_retire_tag),
    .retire2 (walk_last && walk_retire), .retire2_tag (walk_tag),
    .take (take), .span_tag (span_tag), .span_y (span_y), .span_x_begin (span_x_begin),
    .span_x_end (span_x_end), .all_sent (all_sent), .unit_idle (unit_idle),
    .protocol_errors (protocol_errors)
  );
endmodule
