// Icarus Verilog testbench (iverilog -g2012): runs trirast_improved_top at its default parameters
// (NumEndpoints = 1, FifoDepth = 8) on vectors from trirast_rtl_vectors (tb/icarus/run.sh) and
// (TRIRAST_TB_HALFSPACE) the half-space unit trirast_halfspace_top, (TRIRAST_TB_IMPROVED2) the
// second-generation unit trirast_improved2_top in the corner form I2CornerForm; it
// checks every span (in pop order), every accept cycle and every triangle's first_span_cycle and
// done_cycle against the Verilated model's, with a periodic sink (+ready=R +stall=S).
`timescale 1ns / 1ps
`include "trirast_ports.svh"

module tb_trirast #(
  // The half-space unit's build parameters (TRIRAST_TB_HALFSPACE; run.sh sets them with -P).
  parameter int HalfspaceStamp = 2,
  parameter int HalfspaceTile = 8,
  parameter bit HalfspaceZigzag = 1'b1,
  // The second-generation unit's corner form (TRIRAST_TB_IMPROVED2): 1 radix 16, 0 products.
  parameter int I2CornerForm = 1
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  localparam int TriBits = TB + 6 * P + 6 * CB + 3 * EB + 3;
  localparam int SpanBits = TB + 3 * PB + 1;
  localparam int MaxTris = 8192;
  localparam int MaxSpans = 65536;
  localparam int CountBits = $clog2(trirast_pkg::DefaultFifoDepth + 1);

  logic [TriBits-1:0] tris [MaxTris];
  logic [SpanBits-1:0] spans [MaxSpans];
  logic [31:0] accepts [MaxTris];
  logic [63:0] dones [MaxTris];        // {first_span_cycle, done_cycle}
  logic [31:0] got_first [MaxTris];
  logic [31:0] got_done [MaxTris];
  logic got_any [MaxTris];

  logic clk, rst_n;
  logic tri_valid, tri_ready, span_valid, span_ready;
  logic [TriBits-1:0] cur;
  logic [TB-1:0] span_tag, box_tag, walk_tag;
  logic [PB-1:0] span_y, span_xb;
  logic [PB:0] span_xe;
  logic box_retire, walk_busy, walk_stall, walk_last, walk_retire;
  logic [CountBits-1:0] fifo_count;
  logic [PB-1:0] vpx, vpy;
  logic unit_idle;  // no triangle inside the unit (the run's end once every span left)

`ifndef TRIRAST_TB_IMPROVED2
  assign unit_idle = tri_ready && !walk_busy && !span_valid;
`endif
`ifdef TRIRAST_TB_HALFSPACE
  // The half-space unit at the build parameters HalfspaceStamp, HalfspaceTile, HalfspaceZigzag: same ports but no
  // boundary, divider or endpoints configuration.
  trirast_halfspace_top #(
    .StampSize  (HalfspaceStamp),
    .TileSize   (HalfspaceTile),
    .WalkZigzag (HalfspaceZigzag)
  ) u_dut (
    .clk_i            (clk),
    .rst_ni           (rst_n),
    .cfg_vp_xmax_i    (vpx),
    .cfg_vp_ymax_i    (vpy),
`elsif TRIRAST_TB_IMPROVED2
  // The second-generation unit: its setup is a pipeline, so "idle" is its busy_o.
  logic i2_busy;
  assign unit_idle = !i2_busy;
  trirast_improved2_top #(
    .CornerForm (I2CornerForm)
  ) u_dut (
    .clk_i            (clk),
    .rst_ni           (rst_n),
    .cfg_vp_xmax_i    (vpx),
    .cfg_vp_ymax_i    (vpy),
    .busy_o           (i2_busy),
`else
  trirast_improved_top u_dut (
    .clk_i            (clk),
    .rst_ni           (rst_n),
    .cfg_vp_xmax_i    (vpx),
    .cfg_vp_ymax_i    (vpy),
    .cfg_divide_i     (1'b0),
    .cfg_adaptive_i   (1'b1),
    .cfg_endpoints_i  (3'd1),
`endif
    .cfg_fifo_depth_i (CountBits'(trirast_pkg::DefaultFifoDepth)),
    .tri_valid_i      (tri_valid),
    .tri_ready_o      (tri_ready),
    .tri_tag_i        (cur[0 +: TB]),
    .tri_vx_i         (cur[TB +: 3 * P]),
    .tri_vy_i         (cur[TB + 3 * P +: 3 * P]),
    .tri_a_i          (cur[TB + 6 * P +: 3 * CB]),
    .tri_b_i          (cur[TB + 6 * P + 3 * CB +: 3 * CB]),
    .tri_c_i          (cur[TB + 6 * P + 6 * CB +: 3 * EB]),
    .tri_bias_i       (cur[TB + 6 * P + 6 * CB + 3 * EB +: 3]),
    .span_valid_o     (span_valid),
    .span_ready_i     (span_ready),
    .span_tag_o       (span_tag),
    .span_y_o         (span_y),
    .span_x_begin_o   (span_xb),
    .span_x_end_o     (span_xe),
    .box_retire_o     (box_retire),
    .box_retire_tag_o (box_tag),
    .walk_busy_o      (walk_busy),
    .walk_stall_o     (walk_stall),
    .walk_last_o      (walk_last),
    .walk_retire_o    (walk_retire),
    .walk_tag_o       (walk_tag),
    .fifo_count_o     (fifo_count)
  );

  integer ntris, nspans, ready_n, stall_n, vpx_i, vpy_i, last;
  integer next, si, errors, c, k;
  string dir;

  initial begin
    if (!$value$plusargs("dir=%s", dir)) dir = ".";
    if (!$value$plusargs("ntris=%d", ntris)) $fatal(1, "+ntris missing");
    if (!$value$plusargs("nspans=%d", nspans)) $fatal(1, "+nspans missing");
    if (!$value$plusargs("vpx=%d", vpx_i)) $fatal(1, "+vpx missing");
    if (!$value$plusargs("vpy=%d", vpy_i)) $fatal(1, "+vpy missing");
    if (!$value$plusargs("ready=%d", ready_n)) ready_n = 1;
    if (!$value$plusargs("stall=%d", stall_n)) stall_n = 0;
    if (!$value$plusargs("last=%d", last)) last = 0;
    if (ntris > MaxTris || nspans > MaxSpans) $fatal(1, "vectors too large for the testbench");
    $readmemh({dir, "/tris.hex"}, tris);
    $readmemh({dir, "/accept.hex"}, accepts);
    $readmemh({dir, "/done.hex"}, dones);
    if (nspans > 0) $readmemh({dir, "/spans.hex"}, spans);
    for (k = 0; k < ntris; k = k + 1) got_any[k] = 1'b0;
    vpx = PB'(vpx_i);
    vpy = PB'(vpy_i);
    errors = 0;
    next = 0;
    si = 0;
    clk = 1'b0;
    rst_n = 1'b1;
    tri_valid = 1'b0;
    span_ready = 1'b0;
    cur = '0;
    #1 rst_n = 1'b0;
    #1 clk = 1'b1;
    #1 clk = 1'b0;
    #1 rst_n = 1'b1;
    for (c = 0; c < last + 100; c = c + 1) begin
      // Inputs of cycle c, then sample with the clock low.
      tri_valid = next < ntris;
      cur = (next < ntris) ? tris[next] : '0;
      span_ready = (c % (ready_n + stall_n)) < ready_n;
      #1;
      if (next == ntris && si == nspans && unit_idle) begin
        c = last + 100;  // done
      end else begin
        if (tri_valid && tri_ready) begin
          if (accepts[next] != c) begin
            $display("ERROR: triangle %0d accepted in cycle %0d, expected %0d", next, c,
                     accepts[next]);
            errors = errors + 1;
          end
          next = next + 1;
        end
        if (box_retire) begin
          got_first[box_tag] = c;
          got_done[box_tag] = c;
          got_any[box_tag] = 1'b1;
        end
        if (walk_retire) begin
          got_first[walk_tag] = c;
          got_done[walk_tag] = c;
          got_any[walk_tag] = 1'b1;
        end
        if (span_valid && span_ready) begin
          if (si >= nspans || spans[si] != {span_tag, span_y, span_xb, span_xe}) begin
            $display("ERROR: span %0d in cycle %0d: tri %0d y %0d [%0d, %0d), expected %h", si, c,
                     span_tag, span_y, span_xb, span_xe, spans[si]);
            errors = errors + 1;
          end
          if (!got_any[span_tag]) got_first[span_tag] = c;
          got_any[span_tag] = 1'b1;
          got_done[span_tag] = c;
          si = si + 1;
        end
        #1 clk = 1'b1;
        #1 clk = 1'b0;
      end
    end
    if (next != ntris || si != nspans) begin
      $display("ERROR: %0d of %0d triangles accepted, %0d of %0d spans", next, ntris, si, nspans);
      errors = errors + 1;
    end
    for (k = 0; k < ntris; k = k + 1) begin
      if (!got_any[k] || {got_first[k], got_done[k]} != dones[k]) begin
        $display("ERROR: triangle %0d: first/done %0d/%0d, expected %0d/%0d", k, got_first[k],
                 got_done[k], dones[k][63:32], dones[k][31:0]);
        errors = errors + 1;
      end
    end
    if (errors == 0) $display("PASS: %0d triangles, %0d spans, cycles identical", ntris, nspans);
    else $display("FAIL: %0d errors", errors);
    $finish;
  end

endmodule
