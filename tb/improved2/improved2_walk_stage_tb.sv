// The improved2 unit's walk stage (rtl/improved2/trirast_improved2_walk_stage.sv: walkers, span
// generator, registered push with a credit admission test, span FIFO; N = 1, FIFO 8, no tiny
// jobs) against the improved unit's walk stage and span port
// (rtl/improved/trirast_improved_walk_stage.sv + rtl/common/trirast_span_port.sv), simulated side by
// side on the same random hand-off bundles (tb/improved2/run_checks.sh --check-blocks; Verilator
// --binary --timing; ctest improved2_block_checks). Each has its own hand-off feeder and sink, the
// sinks driven by the same pattern by cycle index: always ready (phase 1), then random stalls
// (phase 2). Checked: the two span sequences are equal, span for span; with an always-ready sink
// every span leaves the improved2 walk stage exactly one cycle after it leaves the improved one
// (the registered push; docs/timing.md). With stalls the lag per span is reported (min / max /
// mean), not required: the credit test is stricter than the improved unit's room test.
// Parameters FifoRam, WalkerCs: the walk stage's build choices (defaults: FIFO in flip-flops,
// carry-select walkers; 1, 0: the iCE40 fit's, the same spans and cycles).
`include "trirast_ports.svh"

module improved2_walk_stage_tb #(
  parameter bit FifoRam  = 1'b0,
  parameter bit WalkerCs = 1'b1
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  localparam int Depth = 8;
  localparam int CountBits = $clog2(Depth + 1);
  localparam int EntryBits = TB + 3 * PB + 1;
  localparam int Bundles = 1500;  // per phase

  // One hand-off bundle (the setup stage's outputs to the walk stage).
  typedef struct packed {
    `TRIRAST_HANDOFF_BOX_SIGNALS()
    `TRIRAST_IMPROVED_HANDOFF_EDGES_SIGNALS()
    logic [3*RB-1:0] entry_e;
  } bundle_t;

  logic clk = 0, rst_n = 0;
  always #5 clk = ~clk;
  longint cycle = 0;
  always @(posedge clk) cycle <= cycle + 1;

  bundle_t bundles[$];
  int next1 = 0, next2 = 0;  // the bundle each feeder offers
  int total = 0;             // bundles in this phase
  bit stalls = 0;            // phase 2: random sink stalls
  logic ready_pattern;       // the sinks' ready this cycle (both)
  bundle_t h1, h2;
  // The improved2 walkers take the error term as f: e for dir +, D - 1 - e for dir - (the lane's r).
  // ... and X' as the leave offset o: X' - Xmax (dir +), -X' - 1 (dir -), and the entry row's
  // span bound - 1: Xmax - X' - 1 (mirrored), X' (not).
  logic [3*RB-1:0] h2_f;
  logic [3*XB-1:0] h2_o;
  logic [3*(BB+1)-1:0] h2_b;
  for (genvar e = 0; e < 3; e++) begin : g_f
    assign h2_f[e*RB +: RB] = h2.dir_down[e] ? h2.entry_e[e*RB +: RB]
                                             : RB'(h2.d[e*SB +: SB]) - 1'b1 - h2.entry_e[e*RB +: RB];
    assign h2_o[e*XB +: XB] = h2.dir_down[e] ? h2.entry_x[e*XB +: XB] - XB'(h2.xmax)
                                             : -h2.entry_x[e*XB +: XB] - 1'b1;
    assign h2_b[e*(BB+1) +: BB+1] = h2.mirror[e]
        ? (BB + 1)'(XB'(h2.xmax) - h2.entry_x[e*XB +: XB] - 1'b1)
        : (BB + 1)'(h2.entry_x[e*XB +: XB]);
  end
  logic v1, v2, r1, r2;

  // ---- improved: walk stage + span port ----
  logic [CountBits-1:0] count1;
  logic [0:0] push1;
  logic [EntryBits-1:0] pdata1;
  logic busy1, stall1, last1, retire1;
  logic [TB-1:0] wtag1;
  logic [WB-1:0] wrow1;
  logic sv1;
  logic [TB-1:0] stag1;
  logic [PB-1:0] sy1, sxb1;
  logic [PB:0] sxe1;
  trirast_improved_walk_stage #(.NumEndpoints (1), .CountBits (CountBits), .EntryBits (EntryBits)) u_improved (
    .clk_i (clk), .rst_ni (rst_n), .endpoints_i (3'd1), .fifo_depth_i (CountBits'(Depth)),
    .hand_valid_i (v1), .hand_ready_o (r1), .hand_tag_i (h1.tag), .hand_x0_i (h1.x0),
    .hand_y0_i (h1.y0), .hand_xmax_i (h1.xmax), .hand_ymax_i (h1.ymax),
    .hand_mirror_i (h1.mirror), .hand_dir_down_i (h1.dir_down), .hand_d_i (h1.d),
    .hand_qs_i (h1.qs), .hand_rs_i (h1.rs), .hand_ssat_i (h1.ssat), .hand_enters_i (h1.enters),
    .hand_j_entry_i (h1.j_entry), .hand_entry_state_i (h1.entry_state),
    .hand_entry_x_i (h1.entry_x), .hand_entry_e_i (h1.entry_e), .fifo_count_i (count1),
    .push_o (push1), .push_data_o (pdata1), .busy_o (busy1), .stall_o (stall1), .last_o (last1),
    .retire_o (retire1), .tag_o (wtag1), .row_o (wrow1));
  trirast_span_port #(.NumEndpoints (1), .FifoDepth (Depth)) u_p1 (
    .clk_i (clk), .rst_ni (rst_n), .push_i (push1),
    .push_data_i (pdata1), .count_o (count1), .span_valid_o (sv1), .span_ready_i (ready_pattern),
    .span_tag_o (stag1), .span_y_o (sy1), .span_x_begin_o (sxb1), .span_x_end_o (sxe1));

  // ---- improved2: the walk stage with its span FIFO ----
  logic sv2, busy2;
  logic [EntryBits-1:0] sdata2;
  /* verilator lint_off PINCONNECTEMPTY */
  trirast_improved2_walk_stage #(.FifoDepth (Depth), .FifoRam (FifoRam), .WalkerCs (WalkerCs)) u_improved2 (
    .clk_i (clk), .rst_ni (rst_n), .hand_valid_i (v2), .hand_ready_o (r2),
    .hand_tag_i (h2.tag), .hand_x0_i (h2.x0), .hand_y0_i (h2.y0), .hand_xmax_i (h2.xmax),
    .hand_ymax_i (h2.ymax), .hand_mirror_i (h2.mirror), .hand_dir_down_i (h2.dir_down),
    .hand_d_i (h2.d), .hand_qs_i (h2.qs), .hand_rs_i (h2.rs), .hand_ssat_i (h2.ssat),
    .hand_enters_i (h2.enters), .hand_j_entry_i (h2.j_entry),
    .hand_entry_state_i (h2.entry_state), .hand_entry_x_i (h2_o), .hand_entry_b_i (h2_b),
    .hand_entry_e_i (h2_f), .hand_tiny_i (1'b0), .hand_tiny_valid_i (2'b00),
    .hand_tiny_begin_i (2'b00), .hand_tiny_end1_i (2'b00),
    .cfg_fifo_depth_i (CountBits'(Depth)), .cfg_endpoints_i (3'd1),
    .span_ready_i (ready_pattern), .span_valid_o (sv2), .span_o (sdata2), .busy_o (busy2),
    .walk_o (), .stall_o (), .last_o (), .retire_o (), .tag_o (), .fifo_count_o ());
  /* verilator lint_on PINCONNECTEMPTY */

  // The feeders: bundle k on the port until taken.
  always_comb begin
    v1 = next1 < total;
    v2 = next2 < total;
    h1 = v1 ? bundles[next1] : '0;
    h2 = v2 ? bundles[next2] : '0;
  end

  // The spans leaving each side, with their cycles.
  logic [EntryBits-1:0] out1[$], out2[$];
  longint at1[$], at2[$];
  always @(posedge clk) begin
    if (rst_n) begin
      if (v1 && r1) next1 <= next1 + 1;
      if (v2 && r2) next2 <= next2 + 1;
      if (sv1 && ready_pattern) begin
        out1.push_back({stag1, sy1, sxb1, sxe1});
        at1.push_back(cycle);
      end
      if (sv2 && ready_pattern) begin
        out2.push_back(sdata2);
        at2.push_back(cycle);
      end
    end
  end
  always @(negedge clk) ready_pattern <= !stalls || ($urandom % 3 != 0);

  function automatic bundle_t random_bundle(input int k);
    bundle_t b;
    b = '0;
    b.tag = TB'(k);
    b.x0 = PB'($urandom % 900);
    b.y0 = PB'($urandom % 700);
    b.xmax = BB'($urandom % 40);
    b.ymax = BB'(($urandom % 5 == 0) ? 0 : $urandom % 24);
    for (int e = 0; e < 3; e++) begin
      logic [SB-1:0] d;
      logic dir;
      // D and r_s with F zero low bits, as a lane hands them off; e with any low bits.
      d = SB'(1 + $urandom % 1000) << trirast_pkg::FracBits;
      dir = 1'($urandom);
      b.d[e*SB +: SB] = d;
      b.qs[e*QB +: QB] = QB'($urandom % 6);
      b.rs[e*RB +: RB] = RB'($urandom % (d >> trirast_pkg::FracBits)) << trirast_pkg::FracBits;
      b.entry_e[e*RB +: RB] = RB'($urandom % d);
      b.ssat[e] = ($urandom % 16) == 0;
      b.mirror[e] = 1'($urandom);
      b.dir_down[e] = dir;
      b.enters[e] = ($urandom % 8) != 0;
      b.j_entry[e*WB +: WB] = WB'($urandom % 6);
      // A bound entry row has X' in [0, Xmax) (a lane's entry test; so Xmax >= 1).
      b.entry_state[2*e +: 2] = ($urandom % 4 == 0 || b.xmax == '0)
          ? (dir ? trirast_pkg::RowClear : trirast_pkg::RowOut) : trirast_pkg::RowBound;
      b.entry_x[e*XB +: XB] = XB'($urandom % ((b.xmax == '0) ? 1 : 32'(b.xmax)));
    end
    return b;
  endfunction

  int errors = 0;
  longint spans_total = 0;

  // Runs one phase: feeds the bundles, waits until both sides are empty, compares.
  task automatic phase(input bit with_stalls);
    longint lag, lag_min, lag_max, lag_sum, start;
    int n;
    stalls = with_stalls;
    bundles.delete();
    out1.delete(); out2.delete(); at1.delete(); at2.delete();
    for (int k = 0; k < Bundles; k++) bundles.push_back(random_bundle(k));
    @(negedge clk);
    next1 = 0;
    next2 = 0;
    total = Bundles;
    start = cycle;
    while (next1 < total || next2 < total || busy1 || busy2 || sv1 || sv2) @(negedge clk);
    repeat (4) @(negedge clk);
    total = 0;
    n = out1.size();
    if (out2.size() != n) begin
      errors++;
      $display("phase %0d: improved %0d spans, improved2 %0d", with_stalls, n, out2.size());
      if (out2.size() < n) n = out2.size();
    end
    lag_min = 1 << 30; lag_max = -(1 << 30); lag_sum = 0;
    for (int i = 0; i < n; i++) begin
      if (out1[i] != out2[i]) begin
        if (errors < 10)
          $display("phase %0d span %0d: improved %h improved2 %h", with_stalls, i, out1[i], out2[i]);
        errors++;
      end
      lag = at2[i] - at1[i];
      if (!with_stalls && lag != 1) begin
        if (errors < 10)
          $display("phase 0 span %0d: left improved in cycle %0d, improved2 in %0d (want +1)", i, at1[i],
                   at2[i]);
        errors++;
      end
      if (lag < lag_min) lag_min = lag;
      if (lag > lag_max) lag_max = lag;
      lag_sum += lag;
    end
    spans_total += n;
    $write("improved2_walk_stage_tb: phase %s: %0d bundles, %0d spans, last span in cycle %0d (improved)",
           with_stalls ? "random sink stalls (ready 2 of 3)" : "sink always ready", Bundles, n,
           n ? at1[n-1] - start : 0);
    $display(" / %0d (improved2) of the phase, improved2 lag per span min %0d max %0d mean %0.3f cycles",
             n ? at2[n-1] - start : 0, lag_min, lag_max, n ? real'(lag_sum) / n : 0.0);
  endtask

  initial begin
    repeat (3) @(negedge clk);
    rst_n = 1;
    phase(0);
    phase(1);
    $display("improved2_walk_stage_tb: %0d errors (%0d spans compared)", errors, spans_total);
    if (errors != 0) $fatal(1, "improved2_walk_stage_tb: FAILED");
    $finish;
  end
endmodule
