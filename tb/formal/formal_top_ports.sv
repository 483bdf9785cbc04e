// Formal harness of a unit's triangle and span ports (docs/formal.md, "The tops' ports"): one of
// rtl/UNIT/trirast_UNIT_top.sv at its default build, chosen by a define (UNIT_IMPROVED,
// UNIT_IMPROVED2, UNIT_TRAD, UNIT_HALFSPACE; HS_CORNER_RADIX16 with the last: its CornerForm 1).
// Bounded model checking from reset; the datapath
// blocks are cut points in the proof (tb/formal/proofs.json "cutpoints": their outputs free in
// every cycle), an over-approximation that is sound for these safety properties: whatever the
// datapath computes, the handshakes hold. Every input is free in every cycle (anyseq: the
// triangle, the sink's ready, reset) but for the triangle port's protocol (a triangle offered
// stays offered, unchanged, until taken) and the static configuration (anyconst, in its legal
// range). The properties, and with them the RTL's own assertions (rtl/common/trirast_assert.svh
// under FORMAL), checked in every cycle:
//   SpanHeld        a span offered and not taken (span_valid_o && !span_ready_i) is offered
//                   again next cycle, unchanged (tag, y, x_begin, x_end)
//   SpanIdleInReset no span is offered in reset, nor in the first cycle after it
//   CountInRange    the span FIFO's occupancy stays within the configured depth (no push into a
//                   full FIFO; the FIFO's own FifoNoOverflow_A/FifoNoUnderflow_A too)
//   ValidIsCount    a span is offered exactly when the FIFO holds one
//   TriNotTakenInReset  tri_ready_o low in reset (no triangle is taken while rst_ni is low)
module formal_top_ports (
  input logic clk_i
);
  localparam int FifoDepth = trirast_pkg::DefaultFifoDepth;
  localparam int NumEndpoints = trirast_pkg::DefaultEndpoints;
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
  (* anyseq *) logic [3*EB-1:0] tri_c_i;
  (* anyconst *) logic [PB-1:0] cfg_vp_xmax_i, cfg_vp_ymax_i;
  (* anyconst *) logic [CountBits-1:0] cfg_fifo_depth_i;
  (* anyconst *) logic [2:0] cfg_endpoints_i;
  (* anyconst *) logic cfg_divide_i, cfg_adaptive_i;
  // The port's A, B and bias are the vertices' (the improved2 unit's TriEdgesFromVertices_A, an
  // assumption on its input): written here from the specification, A_k = y_k - y_k+1,
  // B_k = x_k+1 - x_k, bias_k = 1 unless A_k > 0, or A_k = 0 and B_k > 0.
  logic [3*CB-1:0] tri_a_i, tri_b_i;
  logic [2:0] tri_bias_i;
  always @* begin
    for (int k = 0; k < 3; k++) begin
      tri_a_i[k*CB +: CB] = CB'($signed(tri_vy_i[k*P +: P])) - CB'($signed(tri_vy_i[((k+1)%3)*P +: P]));
      tri_b_i[k*CB +: CB] = CB'($signed(tri_vx_i[((k+1)%3)*P +: P])) - CB'($signed(tri_vx_i[k*P +: P]));
      tri_bias_i[k] = !($signed(tri_a_i[k*CB +: CB]) > 0 ||
                        ($signed(tri_a_i[k*CB +: CB]) == 0 && $signed(tri_b_i[k*CB +: CB]) > 0));
    end
  end

  logic tri_ready_o, span_valid_o;
  logic [TB-1:0] span_tag_o;
  logic [PB-1:0] span_y_o, span_x_begin_o;
  logic [PB:0] span_x_end_o;
  logic [CountBits-1:0] fifo_count_o;

  /* verilator lint_off PINCONNECTEMPTY */
`ifdef UNIT_IMPROVED
  trirast_improved_top dut (
    .clk_i (clk_i), .rst_ni (rst_ni), .cfg_vp_xmax_i (cfg_vp_xmax_i),
    .cfg_vp_ymax_i (cfg_vp_ymax_i), .cfg_divide_i (cfg_divide_i), .cfg_adaptive_i (cfg_adaptive_i),
    .cfg_endpoints_i (cfg_endpoints_i), .cfg_fifo_depth_i (cfg_fifo_depth_i),
    .tri_valid_i (tri_valid_i), .tri_ready_o (tri_ready_o), .tri_tag_i (tri_tag_i),
    .tri_vx_i (tri_vx_i), .tri_vy_i (tri_vy_i), .tri_a_i (tri_a_i), .tri_b_i (tri_b_i),
    .tri_c_i (tri_c_i), .tri_bias_i (tri_bias_i),
    .span_valid_o (span_valid_o), .span_ready_i (span_ready_i), .span_tag_o (span_tag_o),
    .span_y_o (span_y_o), .span_x_begin_o (span_x_begin_o), .span_x_end_o (span_x_end_o),
    .box_retire_o (), .box_retire_tag_o (), .walk_busy_o (), .walk_stall_o (), .walk_last_o (),
    .walk_retire_o (), .walk_tag_o (), .fifo_count_o (fifo_count_o), .setup_state_o (),
    .lane_busy_o (), .lane_div_o (), .handoff_o (), .box_xmax_o (), .box_ymax_o ());
`elsif UNIT_IMPROVED2
  trirast_improved2_top dut (
    .clk_i (clk_i), .rst_ni (rst_ni), .cfg_vp_xmax_i (cfg_vp_xmax_i),
    .cfg_vp_ymax_i (cfg_vp_ymax_i), .cfg_fifo_depth_i (cfg_fifo_depth_i),
    .cfg_endpoints_i (cfg_endpoints_i),
    .tri_valid_i (tri_valid_i), .tri_ready_o (tri_ready_o), .tri_tag_i (tri_tag_i),
    .tri_vx_i (tri_vx_i), .tri_vy_i (tri_vy_i), .tri_a_i (tri_a_i), .tri_b_i (tri_b_i),
    .tri_c_i (tri_c_i), .tri_bias_i (tri_bias_i),
    .span_valid_o (span_valid_o), .span_ready_i (span_ready_i), .span_tag_o (span_tag_o),
    .span_y_o (span_y_o), .span_x_begin_o (span_x_begin_o), .span_x_end_o (span_x_end_o),
    .box_retire_o (), .box_retire_tag_o (), .busy_o (),
    .box_valid_o (), .box_stall_o (), .box_tag_o (),
    .corner_valid_o (), .corner_stall_o (), .job_valid_o (), .job_ready_o (), .job_tag_o (),
    .handoff_o (), .box_xmax_o (), .box_ymax_o (), .lane_busy_o (), .lane_div_o (),
    .lane_step_o (), .walk_busy_o (), .walk_stall_o (), .walk_last_o (), .walk_retire_o (),
    .walk_tag_o (), .fifo_count_o (fifo_count_o));
`elsif UNIT_TRAD
  trirast_trad_top dut (
    .clk_i (clk_i), .rst_ni (rst_ni), .cfg_vp_xmax_i (cfg_vp_xmax_i),
    .cfg_vp_ymax_i (cfg_vp_ymax_i), .cfg_fifo_depth_i (cfg_fifo_depth_i),
    .tri_valid_i (tri_valid_i), .tri_ready_o (tri_ready_o), .tri_tag_i (tri_tag_i),
    .tri_vx_i (tri_vx_i), .tri_vy_i (tri_vy_i),
    .span_valid_o (span_valid_o), .span_ready_i (span_ready_i), .span_tag_o (span_tag_o),
    .span_y_o (span_y_o), .span_x_begin_o (span_x_begin_o), .span_x_end_o (span_x_end_o),
    .setup_retire_o (), .setup_retire_tag_o (), .walk_busy_o (), .walk_stall_o (),
    .walk_last_o (), .walk_retire_o (), .walk_tag_o (), .fifo_count_o (fifo_count_o),
    .setup_state_o (), .handoff_o (), .hand_px_o (), .hand_py_o ());
`elsif UNIT_HALFSPACE
  // HS_CORNER_RADIX16: the set-up's digit-serial corner form (CornerForm 1), else products.
`ifdef HS_CORNER_RADIX16
  localparam int HsCornerForm = 1;
`else
  localparam int HsCornerForm = 0;
`endif
  trirast_halfspace_top #(.CornerForm (HsCornerForm)) dut (
    .clk_i (clk_i), .rst_ni (rst_ni), .cfg_vp_xmax_i (cfg_vp_xmax_i),
    .cfg_vp_ymax_i (cfg_vp_ymax_i), .cfg_fifo_depth_i (cfg_fifo_depth_i),
    .tri_valid_i (tri_valid_i), .tri_ready_o (tri_ready_o), .tri_tag_i (tri_tag_i),
    .tri_vx_i (tri_vx_i), .tri_vy_i (tri_vy_i), .tri_a_i (tri_a_i), .tri_b_i (tri_b_i),
    .tri_c_i (tri_c_i), .tri_bias_i (tri_bias_i),
    .span_valid_o (span_valid_o), .span_ready_i (span_ready_i), .span_tag_o (span_tag_o),
    .span_y_o (span_y_o), .span_x_begin_o (span_x_begin_o), .span_x_end_o (span_x_end_o),
    .box_retire_o (), .box_retire_tag_o (), .walk_busy_o (), .walk_stall_o (),
    .walk_last_o (), .walk_retire_o (), .walk_tag_o (), .fifo_count_o (fifo_count_o),
    .setup_state_o (), .handoff_o (), .box_xmax_o (), .box_ymax_o ());
`endif
  /* verilator lint_on PINCONNECTEMPTY */

  logic [TB+3*PB:0] span;
  assign span = {span_tag_o, span_y_o, span_x_begin_o, span_x_end_o};
  logic [TB+6*P+3*EB-1:0] tri_port;
  assign tri_port = {tri_tag_i, tri_vx_i, tri_vy_i, tri_c_i};

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
    // the configuration's legal range (the tops' CfgFifoDepthInRange_A, CfgEndpointsInRange_A)
    assume (32'(cfg_fifo_depth_i) >= 1 && 32'(cfg_fifo_depth_i) <= FifoDepth);
    assume (cfg_endpoints_i >= 3'd1 && 32'(cfg_endpoints_i) <= NumEndpoints &&
            cfg_fifo_depth_i >= CountBits'(cfg_endpoints_i));
    // the triangle port's protocol: a triangle offered and not taken stays, unchanged
    if (rst_ni && f_tri_wait_q) assume (tri_valid_i && tri_port == f_tri_q);
  end

  // ---- the properties ----
  logic f_span_wait_q;
  logic [$bits(span)-1:0] f_span_q;
  always @(posedge clk_i) begin
    f_span_wait_q <= rst_ni && span_valid_o && !span_ready_i;
    f_span_q <= span;
  end
  always @* begin
    if (!rst_ni || !f_rst_q) SpanIdleInReset: assert (!span_valid_o);
    if (rst_ni) begin
      if (f_span_wait_q) SpanHeld: assert (span_valid_o && span == f_span_q);
      CountInRange: assert (fifo_count_o <= cfg_fifo_depth_i);
      ValidIsCount: assert (span_valid_o == (fifo_count_o != '0));
    end
    if (!rst_ni) TriNotTakenInReset: assert (!tri_ready_o);
  end

  // ---- reachability (yosys-smtbmc -c): a span is offered, stalled, and the FIFO fills ----
  always @* begin
    if (rst_ni) begin
      CoverSpanStall: cover (f_span_wait_q && span_valid_o);
      CoverFull: cover (fifo_count_o == cfg_fifo_depth_i && cfg_fifo_depth_i == CountBits'(2));
      CoverTriStall: cover (tri_valid_i && !tri_ready_o && f_tri_wait_q);
    end
  end
endmodule
