// The whole improved2 unit (rtl/improved2/trirast_improved2_top.sv) against the improved unit
// (rtl/improved/trirast_improved_top.sv, configured as tb/common/cycle_loop.hpp configures it for
// the default run: the scene's viewport, N = 1, FIFO depth 8, boundary mode step, adaptive
// divider) (tb/improved2/run_checks.sh --check-unit and --check-all; Verilator --binary; ctest
// improved2_unit_vs_improved). Both get the same triangles (a $readmemh file from unit_tris.py,
// +tris=FILE +n=N +w=WIDTH +h=HEIGHT), each through its own triangle port handshake, sinks always
// ready (+stall: both sinks ready in two cycles of three, the same pattern; +rseed=S +rpct=P: both
// ready as trirast's --sink-stall random:S:P, model/common/sink_pattern.cpp); the two span
// sequences are compared span for span (tag, y, x_begin, x_end), and the empty-box retires
// counted. Cycles: from the first cycle a triangle is offered to the first cycle in which every
// triangle has been accepted and the unit is idle (no triangle inside, FIFO empty).
// Prints "improved2_unit_vs_improved_tb: N errors" (0 = the sequences are equal). (Per-triangle
// cycles against the SystemC model: the improved2-rtl engine, tests/rtl/test_rtl_improved2_engine.cpp.)
// Build defines: IMPROVED2_CORNER_FORM (0: products, 1: MSB-first radix 16; required);
// IMPROVED2_FIT (1: the iCE40 fit's build choices, the unit's defaults: FifoRam 1, WalkerCs 0,
// TestHi 1, JobRing 1; 0, the default here: their other values); IMPROVED2_LANE_FIXEDM and
// IMPROVED2_LANE_PREITER (the lanes' FixedM and PreIter, default 0); IMPROVED2_FIFO_DEPTH (both
// units' span FIFO depth, a power of two 1..8, default 8).
`ifndef IMPROVED2_FIFO_DEPTH
`define IMPROVED2_FIFO_DEPTH 8
`endif
`ifndef IMPROVED2_FIT
`define IMPROVED2_FIT 0
`endif
`ifndef IMPROVED2_LANE_FIXEDM
`define IMPROVED2_LANE_FIXEDM 0
`endif
`ifndef IMPROVED2_LANE_PREITER
`define IMPROVED2_LANE_PREITER 0
`endif
`include "trirast_ports.svh"

module improved2_unit_vs_improved_tb;
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  localparam int TriBits = 6 * P + 6 * CB + 3 * EB + 3;
  localparam int SpanBits = TB + 3 * PB + 1;
  localparam int MaxTris = 400000;
  localparam longint MaxCycles = 64'd50_000_000;

  logic [TriBits-1:0] tris [MaxTris];
  int n, w, h;
  bit stall;
  logic sready;
  string path;

  logic clk = 1'b0;
  logic rst_n = 1'b0;
  int i1, i2;
  longint cyc;
  logic [TriBits-1:0] t1, t2;
  assign t1 = tris[(i1 < n) ? i1 : 0];
  assign t2 = tris[(i2 < n) ? i2 : 0];
  // --sink-stall random:SEED:PERCENT (model/common/sink_pattern.cpp's sink_mix: splitmix64).
  bit rsink;
  longint unsigned rseed;
  int rpct;
  function automatic longint unsigned sink_mix(input longint unsigned seed,
                                               input longint unsigned c);
    longint unsigned z;
    z = seed * 64'h9E3779B97F4A7C15 + c;
    z += 64'h9E3779B97F4A7C15;
    z = (z ^ (z >> 30)) * 64'hBF58476D1CE4E5B9;
    z = (z ^ (z >> 27)) * 64'h94D049BB133111EB;
    return z ^ (z >> 31);
  endfunction
  assign sready = rsink ? (sink_mix(rseed, longint'(cyc)) % 100 >= longint'(rpct))
                        : (!stall || (cyc % 3 != 2));

  // ---- improved ----
  logic v1, r1, sv1, retire1, walk_busy1;
  logic [2:0] setup_state1;
  logic [3:0] count1;
  logic [TB-1:0] stag1, rtag1;
  logic [PB-1:0] sy1, sxb1;
  logic [PB:0] sxe1;
  assign v1 = rst_n && (i1 < n);
  /* verilator lint_off PINCONNECTEMPTY */
  trirast_improved_top #(.NumEndpoints (1), .FifoDepth (`IMPROVED2_FIFO_DEPTH)) u_improved (
    .clk_i (clk), .rst_ni (rst_n),
    .cfg_vp_xmax_i (PB'(w - 1)), .cfg_vp_ymax_i (PB'(h - 1)),
    .cfg_divide_i (1'b0), .cfg_adaptive_i (1'b1), .cfg_endpoints_i (3'd1),
    .cfg_fifo_depth_i (4'(`IMPROVED2_FIFO_DEPTH)),
    .tri_valid_i (v1), .tri_ready_o (r1), .tri_tag_i (TB'(i1)),
    .tri_vx_i (t1[0 +: 3*P]), .tri_vy_i (t1[3*P +: 3*P]),
    .tri_a_i (t1[6*P +: 3*CB]), .tri_b_i (t1[6*P+3*CB +: 3*CB]),
    .tri_c_i (t1[6*P+6*CB +: 3*EB]), .tri_bias_i (t1[6*P+6*CB+3*EB +: 3]),
    .span_valid_o (sv1), .span_ready_i (sready), .span_tag_o (stag1), .span_y_o (sy1),
    .span_x_begin_o (sxb1), .span_x_end_o (sxe1),
    .box_retire_o (retire1), .box_retire_tag_o (rtag1), .walk_busy_o (walk_busy1),
    .walk_stall_o (), .walk_last_o (), .walk_retire_o (), .walk_tag_o (),
    .fifo_count_o (count1), .setup_state_o (setup_state1), .lane_busy_o (), .lane_div_o (),
    .handoff_o (), .box_xmax_o (), .box_ymax_o ());
  /* verilator lint_on PINCONNECTEMPTY */

  // ---- improved2 ----
  logic v2, r2, sv2, retire2, busy2;
  logic [TB-1:0] stag2, rtag2;
  logic [PB-1:0] sy2, sxb2;
  logic [PB:0] sxe2;
  assign v2 = rst_n && (i2 < n);
  // IMPROVED2_FIT 1: the iCE40 fit's build choices (the unit's defaults; the same cycles); 0
  // their other values, the job ring's too (JobRing 0: the walk stage copies L's tag and box).
  trirast_improved2_top #(.FifoDepth (`IMPROVED2_FIFO_DEPTH), .CornerForm (`IMPROVED2_CORNER_FORM), .FifoRam (`IMPROVED2_FIT),
            .WalkerCs (!`IMPROVED2_FIT), .TestHi (`IMPROVED2_FIT), .JobRing (`IMPROVED2_FIT),
            .LaneFixedM (`IMPROVED2_LANE_FIXEDM), .LanePreIter (`IMPROVED2_LANE_PREITER)) u_improved2 (
    .clk_i (clk), .rst_ni (rst_n),
    .cfg_vp_xmax_i (PB'(w - 1)), .cfg_vp_ymax_i (PB'(h - 1)),
    .cfg_fifo_depth_i ($clog2(`IMPROVED2_FIFO_DEPTH + 1)'(`IMPROVED2_FIFO_DEPTH)),
    .tri_valid_i (v2), .tri_ready_o (r2), .tri_tag_i (TB'(i2)),
    .tri_vx_i (t2[0 +: 3*P]), .tri_vy_i (t2[3*P +: 3*P]),
    .tri_a_i (t2[6*P +: 3*CB]), .tri_b_i (t2[6*P+3*CB +: 3*CB]),
    .tri_c_i (t2[6*P+6*CB +: 3*EB]), .tri_bias_i (t2[6*P+6*CB+3*EB +: 3]),
    .span_valid_o (sv2), .span_ready_i (sready), .span_tag_o (stag2), .span_y_o (sy2),
    .span_x_begin_o (sxb2), .span_x_end_o (sxe2),
    .box_retire_o (retire2), .box_retire_tag_o (rtag2), .busy_o (busy2));

  logic [SpanBits-1:0] q1 [$], q2 [$];
  longint end1 = -1, end2 = -1, retires1 = 0, retires2 = 0;
  logic idle1, idle2;
  assign idle1 = (i1 >= n) && (setup_state1 == 3'd0) && !walk_busy1 && (count1 == '0) && !sv1;
  assign idle2 = (i2 >= n) && !busy2;

  always @(posedge clk) begin
    if (rst_n) begin
      if (v1 && r1) i1 <= i1 + 1;
      if (v2 && r2) i2 <= i2 + 1;
      if (sv1 && sready) q1.push_back({stag1, sy1, sxb1, sxe1});
      if (sv2 && sready) q2.push_back({stag2, sy2, sxb2, sxe2});
      if (retire1) retires1++;
      if (retire2) retires2++;
      if (idle1 && end1 < 0) end1 = cyc;
      if (idle2 && end2 < 0) end2 = cyc;
      cyc <= cyc + 1;
    end
  end

  initial begin
    int errors;
    if (!$value$plusargs("tris=%s", path) || !$value$plusargs("n=%d", n) ||
        !$value$plusargs("w=%d", w) || !$value$plusargs("h=%d", h)) begin
      $display("improved2_unit_vs_improved_tb: needs +tris=FILE +n=N +w=WIDTH +h=HEIGHT");
      $finish;
    end
    if (n > MaxTris) begin
      $display("improved2_unit_vs_improved_tb: %0d triangles, more than %0d", n, MaxTris);
      $finish;
    end
    stall = $test$plusargs("stall");
    rsink = $value$plusargs("rseed=%d", rseed) && $value$plusargs("rpct=%d", rpct);
    $readmemh(path, tris, 0, n - 1);
    i1 = 0;
    i2 = 0;
    cyc = 0;
    repeat (3) begin
      #5 clk = 1'b1;
      #5 clk = 1'b0;
    end
    rst_n = 1'b1;
    while ((end1 < 0 || end2 < 0) && cyc < MaxCycles) begin
      #5 clk = 1'b1;
      #5 clk = 1'b0;
    end
    errors = 0;
    if (end1 < 0 || end2 < 0) begin
      $display("improved2_unit_vs_improved_tb: stopped after %0d cycles (improved done %0d, improved2 done %0d)", cyc, end1, end2);
      errors++;
    end
    if (q1.size() != q2.size()) begin
      $display("improved2_unit_vs_improved_tb: %0d spans from improved, %0d from improved2", q1.size(), q2.size());
      errors++;
    end
    for (int k = 0; k < q1.size() && k < q2.size(); k++) begin
      if (q1[k] != q2[k]) begin
        if (errors < 10)
          $display("improved2_unit_vs_improved_tb: span %0d: improved tag %0d y %0d [%0d, %0d), improved2 tag %0d y %0d [%0d, %0d)",
                   k, q1[k][SpanBits-1 -: TB], q1[k][2*PB+1 +: PB], q1[k][PB+1 +: PB], q1[k][PB:0],
                   q2[k][SpanBits-1 -: TB], q2[k][2*PB+1 +: PB], q2[k][PB+1 +: PB], q2[k][PB:0]);
        errors++;
      end
    end
    if (retires1 != retires2) begin
      $display("improved2_unit_vs_improved_tb: empty boxes retired: improved %0d, improved2 %0d", retires1, retires2);
      errors++;
    end
    if (rsink) $write("improved2_unit_vs_improved_tb: sink random:%0d:%0d: ", rseed, rpct);
    else if (stall) $write("improved2_unit_vs_improved_tb: sink ready 2 of 3 cycles: ");
    else $write("improved2_unit_vs_improved_tb: ");
    $display("%0d triangles, %0d spans, %0d empty boxes; cycles improved %0d (%.2f per triangle), improved2 %0d (%.2f per triangle)",
             n, q1.size(), retires1, end1, real'(end1) / n, end2, real'(end2) / n);
    $display("improved2_unit_vs_improved_tb: %0d errors", errors);
    $finish;
  end
endmodule
