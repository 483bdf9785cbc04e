// Formal harness of the second-generation improved unit's ports (rtl/improved2/trirast_improved2_top.sv,
// its default build: the iCE40 form, CornerForm 1, span FIFO in block RAM; docs/formal.md,
// "The improved2 unit's ports"). Bounded model checking from reset: every input is free in every
// cycle (anyseq: the triangle, the sink's ready, reset) but for the triangle port's protocol
// (a triangle offered stays offered, unchanged, until taken) and the static configuration
// (anyconst: the viewport, the FIFO depth 1..FifoDepth). The properties:
//   SpanHeld        a span offered and not taken (span_valid_o && !span_ready_i) is offered
//                   again next cycle, unchanged (tag, y, x_begin, x_end)
//   SpanIdleInReset no span is offered in reset, nor in the first cycle after it
//   CountInRange    the span FIFO's occupancy stays within the configured depth (no push into a
//                   full FIFO), and changes by at most one push and one pop a cycle
//   TriReadyRoom    the triangle port is ready only when its register (B) is empty or leaves
//                   this cycle (no triangle is taken into a full register)
//   TriIdleInReset  with TRI_READY_LOW_IN_RESET only (see docs/formal.md: it fails, the unit
//                   holds tri_ready_o high in reset): tri_ready_o low in reset
module formal_improved2_top (
  input logic clk_i
);
  localparam int FifoDepth = trirast_pkg::DefaultFifoDepth;
  localparam int CountBits = $clog2(FifoDepth + 1);
  localparam int P = trirast_pkg::VertexBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int TB = trirast_pkg::TagBits;
  localparam int PB = trirast_pkg::PixBits;

  (* anyseq *) logic rst_ni;
  (* anyseq *) logic tri_valid_i, span_ready_i;
  (* anyseq *) logic [TB-1:0] tri_tag_i;
  (* anyseq *) logic [3*P-1:0] tri_vx_i, tri_vy_i;
  (* anyseq *) logic [3*CB-1:0] tri_a_i, tri_b_i;
  (* anyseq *) logic [3*EB-1:0] tri_c_i;
  (* anyseq *) logic [2:0] tri_bias_i;
  (* anyconst *) logic [PB-1:0] cfg_vp_xmax_i, cfg_vp_ymax_i;
  (* anyconst *) logic [CountBits-1:0] cfg_fifo_depth_i;

  logic tri_ready_o, span_valid_o;
  logic [TB-1:0] span_tag_o;
  logic [PB-1:0] span_y_o, span_x_begin_o;
  logic [PB:0] span_x_end_o;
  logic box_valid_o, box_stall_o, busy_o;
  logic [CountBits-1:0] fifo_count_o;

  /* verilator lint_off PINCONNECTEMPTY */
  trirast_improved2_top dut (
    .clk_i (clk_i), .rst_ni (rst_ni), .cfg_vp_xmax_i (cfg_vp_xmax_i),
    .cfg_vp_ymax_i (cfg_vp_ymax_i), .cfg_fifo_depth_i (cfg_fifo_depth_i),
    .cfg_endpoints_i (3'd1),
    .tri_valid_i (tri_valid_i), .tri_ready_o (tri_ready_o), .tri_tag_i (tri_tag_i),
    .tri_vx_i (tri_vx_i), .tri_vy_i (tri_vy_i), .tri_a_i (tri_a_i), .tri_b_i (tri_b_i),
    .tri_c_i (tri_c_i), .tri_bias_i (tri_bias_i),
    .span_valid_o (span_valid_o), .span_ready_i (span_ready_i), .span_tag_o (span_tag_o),
    .span_y_o (span_y_o), .span_x_begin_o (span_x_begin_o), .span_x_end_o (span_x_end_o),
    .box_retire_o (), .box_retire_tag_o (), .busy_o (busy_o),
    .box_valid_o (box_valid_o), .box_stall_o (box_stall_o), .box_tag_o (),
    .corner_valid_o (), .corner_stall_o (), .job_valid_o (), .job_ready_o (), .job_tag_o (),
    .handoff_o (), .box_xmax_o (), .box_ymax_o (), .lane_busy_o (), .lane_div_o (),
    .lane_step_o (), .walk_busy_o (), .walk_stall_o (), .walk_last_o (), .walk_retire_o (),
    .walk_tag_o (), .fifo_count_o (fifo_count_o));
  /* verilator lint_on PINCONNECTEMPTY */

  logic [TB+3*PB:0] span;
  assign span = {span_tag_o, span_y_o, span_x_begin_o, span_x_end_o};
  logic [TB+6*P+6*CB+3*EB+2:0] tri_port;
  assign tri_port = {tri_tag_i, tri_vx_i, tri_vy_i, tri_a_i, tri_b_i, tri_c_i, tri_bias_i};

  // ---- the environment ----
  logic f_first_q = 1'b1;
  logic f_rst_q, f_tri_wait_q;
  logic [$bits(tri_port)-1:0] f_tri_q;
  always @(posedge clk_i) begin
    f_first_q <= 1'b0;
    f_rst_q <= rst_ni;
    f_tri_wait_q <= rst_ni && tri_valid_i && !tri_ready_o;
    f_tri_q <= tri_port;
  end
  always @* begin
    if (f_first_q) assume (!rst_ni);
    assume (cfg_fifo_depth_i >= CountBits'(1) && 32'(cfg_fifo_depth_i) <= FifoDepth);
    // the triangle port's protocol: a triangle offered and not taken stays, unchanged
    if (rst_ni && f_tri_wait_q) assume (tri_valid_i && tri_port == f_tri_q);
  end

  // ---- the properties ----
  logic f_span_wait_q;
  logic [$bits(span)-1:0] f_span_q;
  logic [CountBits-1:0] f_count_q;
  logic f_pop_q;
  always @(posedge clk_i) begin
    f_span_wait_q <= rst_ni && span_valid_o && !span_ready_i;
    f_span_q <= span;
    f_count_q <= fifo_count_o;
    f_pop_q <= span_valid_o && span_ready_i;
  end
  always @* begin
    if (!rst_ni || !f_rst_q) SpanIdleInReset: assert (!span_valid_o);
    if (rst_ni) begin
      if (f_span_wait_q) SpanHeld: assert (span_valid_o && span == f_span_q);
      CountInRange: assert (fifo_count_o <= cfg_fifo_depth_i);
      if (f_rst_q) CountStep: assert (32'(fifo_count_o) + 32'(f_pop_q) <= 32'(f_count_q) + 1 &&
                                      32'(fifo_count_o) + 32'(f_pop_q) >= 32'(f_count_q));
      TriReadyRoom: assert (!(tri_ready_o && box_stall_o));
    end
`ifdef TRI_READY_LOW_IN_RESET
    if (!rst_ni) TriIdleInReset: assert (!tri_ready_o);
`endif
  end

  // ---- reachability (yosys-smtbmc -c): what the depth reaches ----
  always @* begin
    if (rst_ni) begin
      CoverSpanStall: cover (f_span_wait_q && span_valid_o);
      CoverFull: cover (fifo_count_o == cfg_fifo_depth_i && cfg_fifo_depth_i == CountBits'(2));
      CoverTriStall: cover (tri_valid_i && !tri_ready_o && box_valid_o);
    end
  end
endmodule
