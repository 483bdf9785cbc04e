// The improved2 unit's edge lane (rtl/improved2/trirast_improved2_edge_lane.sv) against the
// improved unit's normalizer + lane (rtl/improved/trirast_improved_edge_normalizer.sv,
// rtl/improved/trirast_improved_edge_lane.sv, boundary mode step) on the same edges
// (tb/improved2/run_checks.sh --check-all; Verilator --binary).
//
// Edges: random ones (every field drawn from a mix of special values: zero, limits, +-1, and
// random magnitudes of random bit length; E_R consistent with E_L = E_R - A*u*Xmax or not; a
// quarter with the fixed divider m = Q), then, with +edges=FILE (lines "A B E_L E_R Xmax Ymax
// tiny" from lane_edges.py), a scene's edges.
//
// Compared bit for bit, per edge: horiz, mirror, dir, D, enters, ssat (non-horizontal edges);
// q_s, r_s (non-horizontal, not saturated); j_entry and the entry state (when it enters);
// entry X' and e (when it enters bound). The other values are not read by the walker in those
// cases (rtl/improved/trirast_improved_edge_walker.sv: a row steps only in RowBound, which needs
// the entry state RowBound, after which a saturated slope turns the row clear or out), and the
// improved2 lane leaves them undefined; to show that, both lanes' results are loaded into two of
// the improved unit's walkers and every row's state (and X' on bound rows) is compared, for boxes
// up to WalkRows rows.
// Cycles per edge: from the cycle after the load to the first cycle whose registers hold the
// results (improved: !busy_o, improved2: done_o); both must be what the lanes' headers state.
// Prints "improved2_edge_lane_tb: N errors".
`include "trirast_ports.svh"

module improved2_edge_lane_tb #(
  parameter int PreIter = 0  // trirast_improved2_edge_lane's PreIter
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  localparam int IB = $clog2(QB + 1);
  localparam int Random = 40000;
  localparam int WalkRows = 300;

  logic clk = 0, rst_n = 0;
  int errors = 0;

  function automatic logic [IB-1:0] bits_plus_one(input logic [BB-1:0] v);
    logic [IB-1:0] n;
    n = IB'(1);
    for (int i = 0; i < BB; i++) if (v[i]) n = IB'(i + 1);
    bits_plus_one = n + 1'b1;
  endfunction

  // ---- the edge under test ----
  logic load;
  logic signed [CB-1:0] a, b;
  logic signed [EB-1:0] el, er;
  logic [BB-1:0] xmax, ymax;
  logic [IB-1:0] m;

  // ---- improved ----
  logic improved_horiz, improved_mirror, improved_dir;
  logic signed [EB-1:0] improved_t, improved_t1;
  logic [SB-1:0] improved_dn, improved_sn;
  logic improved_busy, improved_dnext, improved_div, improved_horiz_o, improved_mirror_o, improved_dir_o, improved_ssat, improved_enters;
  logic [SB-1:0] improved_d;
  logic [QB-1:0] improved_qs;
  logic [RB-1:0] improved_rs, improved_ee;
  logic [WB-1:0] improved_je;
  logic [1:0] improved_est;
  logic signed [XB-1:0] improved_ex;
  trirast_improved_edge_normalizer u_n1 (.a_i (a), .b_i (b), .el_i (el), .er_i (er), .horiz_o (improved_horiz),
    .mirror_o (improved_mirror), .dir_down_o (improved_dir), .t_o (improved_t), .t1_o (improved_t1), .d_o (improved_dn),
    .s_o (improved_sn));
  trirast_improved_edge_lane u_l1 (.clk_i (clk), .rst_ni (rst_n), .divide_i (1'b0), .qx_i (m),
    .qy_i (m), .load_i (load), .horiz_i (improved_horiz), .mirror_i (improved_mirror), .dir_down_i (improved_dir),
    .t_i (improved_t), .t1_i (improved_t1), .d_i (improved_dn), .s_i (improved_sn), .xmax_i (xmax), .ymax_i (ymax),
    .busy_o (improved_busy), .done_next_o (improved_dnext), .div_o (improved_div), .horiz_o (improved_horiz_o),
    .mirror_o (improved_mirror_o), .dir_down_o (improved_dir_o), .d_o (improved_d), .qs_o (improved_qs), .rs_o (improved_rs),
    .ssat_o (improved_ssat), .enters_o (improved_enters), .j_entry_o (improved_je), .entry_state_o (improved_est),
    .entry_x_o (improved_ex), .entry_e_o (improved_ee));

  // ---- improved2 ----
  logic improved2_busy, improved2_done, improved2_horiz, improved2_mirror, improved2_dir, improved2_ssat, improved2_enters;
  logic [SB-1:0] improved2_d;
  logic [QB-1:0] improved2_qs;
  logic [RB-1:0] improved2_rs, improved2_ee, improved2_f;
  logic [WB-1:0] improved2_je;
  logic [1:0] improved2_est;
  logic signed [XB-1:0] improved2_ex, improved2_o;
  // The value at the column the lane traverses.
  logic signed [EB-1:0] lane_e;
  assign lane_e = trirast_pkg::lane_reads_right(a, b) ? er : el;
  trirast_improved2_edge_lane #(.PreIter (PreIter)) u_l2 (.clk_i (clk), .rst_ni (rst_n), .m_i (m), .load_i (load), .a_i (a), .b_i (b),
    .e_i (lane_e), .xmax_i (xmax), .ymax_i (ymax), .busy_o (improved2_busy), .done_o (improved2_done),
    .horiz_o (improved2_horiz), .mirror_o (improved2_mirror), .dir_down_o (improved2_dir), .d_o (improved2_d), .qs_o (improved2_qs),
    .rs_o (improved2_rs), .ssat_o (improved2_ssat), .enters_o (improved2_enters), .j_entry_o (improved2_je),
    .entry_state_o (improved2_est), .entry_x_o (improved2_o), .entry_e_o (improved2_f));
  // ... and the leave offset o = q - Xmax; the improved unit's X' from it (dir +: o + Xmax, dir -: -o - 1):
  assign improved2_ex = improved2_dir ? improved2_o + XB'(xmax) : -improved2_o - 1'b1;
  // The improved2 lane hands off f (e for dir +, D - 1 - e for dir -); the improved unit's e from it:
  assign improved2_ee = improved2_dir ? improved2_f : RB'(improved2_d) - 1'b1 - improved2_f;

  // ---- two of the improved unit's walkers, one per lane's results ----
  logic wload, wadv;
  logic [WB-1:0] wrow;
  logic wm1, wm2;
  logic [1:0] ws1, ws2;
  logic signed [XB-1:0] wx1, wx2;
  trirast_improved_edge_walker #(.NumEndpoints (1)) u_w1 (.clk_i (clk), .rst_ni (rst_n), .load_i (wload),
    .mirror_i (improved_mirror_o), .dir_down_i (improved_dir_o), .d_i (improved_d), .qs_i (improved_qs), .rs_i (improved_rs),
    .ssat_i (improved_ssat), .enters_i (improved_enters), .j_entry_i (improved_je), .entry_state_i (improved_est),
    .entry_x_i (improved_ex), .entry_e_i (improved_ee), .xmax_i (xmax), .row_i (wrow), .adv_i (wadv),
    .adv_rows_i (3'd1), .mirror_o (wm1), .row_state_o (ws1), .row_x_o (wx1));
  trirast_improved_edge_walker #(.NumEndpoints (1)) u_w2 (.clk_i (clk), .rst_ni (rst_n), .load_i (wload),
    .mirror_i (improved2_mirror), .dir_down_i (improved2_dir), .d_i (improved2_d), .qs_i (improved2_qs), .rs_i (improved2_rs),
    .ssat_i (improved2_ssat), .enters_i (improved2_enters), .j_entry_i (improved2_je), .entry_state_i (improved2_est),
    .entry_x_i (improved2_ex), .entry_e_i (improved2_ee), .xmax_i (xmax), .row_i (wrow), .adv_i (wadv),
    .adv_rows_i (3'd1), .mirror_o (wm2), .row_state_o (ws2), .row_x_o (wx2));

  always #5 clk = ~clk;

  // ---- statistics ----
  longint sum1, sum2, n_edges, walked_rows;
  int max1, max2;
  int hist_less, hist_same, hist_more;
  task automatic stats_reset();
    sum1 = 0; sum2 = 0; n_edges = 0; max1 = 0; max2 = 0;
    hist_less = 0; hist_same = 0; hist_more = 0;
  endtask
  task automatic stats_print(input string what);
    $display("improved2_edge_lane_tb: %s: %0d edges; cycles per edge improved mean %.2f max %0d, improved2 mean %.2f max %0d; improved2 fewer on %0d, same on %0d, more on %0d",
             what, n_edges, n_edges ? real'(sum1) / n_edges : 0.0, max1,
             n_edges ? real'(sum2) / n_edges : 0.0, max2, hist_less, hist_same, hist_more);
  endtask

  // Run one edge (inputs set): load both lanes, wait for both, compare, walk.
  int last1, last2;  // the last edge's cycles
  task automatic run_edge(input bit count);
    int c1, c2, t;
    bit d1, d2;
    load = 1'b1;
    @(posedge clk); #1;
    load = 1'b0;
    c1 = -1; c2 = -1; t = 0;
    while (c1 < 0 || c2 < 0) begin
      if (c1 < 0 && !improved_busy) c1 = t;
      if (c2 < 0 && improved2_done) c2 = t;
      if (c1 >= 0 && c2 >= 0) break;
      @(posedge clk); #1;
      t++;
      if (t > 40000) begin
        $display("improved2_edge_lane_tb: ERROR timeout (a=%0d b=%0d el=%0d er=%0d xmax=%0d ymax=%0d)", a, b, el, er, xmax, ymax);
        errors++;
        return;
      end
    end
    last1 = c1; last2 = c2;
    // The improved2 lane's cycles as trirast_improved2_edge_lane.sv's header states them (T = the
    // traversal's steps = j at its end; a saturated division takes 2 iterations), and the improved lane's.
    begin
      int tt, ms, cs, expect2;
      tt = int'(improved2_je);
      ms = improved2_ssat ? 2 : int'(m) + PreIter;
      cs = (ms + 1 > tt + 1) ? ms + 1 : tt + 1;
      if (improved2_horiz) expect2 = tt + 1;
      else if (improved2_enters) expect2 = cs + (u_l2.sat_q ? 2 : int'(m) + PreIter);
      else expect2 = cs;
      // The improved lane's (docs/timing.md "Lane cycles": steps + iterations; no early stop on saturation).
      begin
        int t1, expect1;
        t1 = int'(improved_je);
        expect1 = improved_horiz_o ? t1 : t1 + int'(m) + (improved_enters ? int'(m) : 0);
        if (expect1 != c1) begin
          errors++;
          if (errors <= 10)
            $display("improved2_edge_lane_tb: ERROR improved took %0d cycles, expected %0d (a=%0d b=%0d xmax=%0d ymax=%0d m=%0d)",
                     c1, expect1, a, b, xmax, ymax, m);
        end
      end
      if (expect2 != c2) begin
        errors++;
        if (errors <= 10)
          $display("improved2_edge_lane_tb: ERROR improved2 took %0d cycles, its header says %0d (a=%0d b=%0d el=%0d er=%0d xmax=%0d ymax=%0d m=%0d)",
                   c2, expect2, a, b, el, er, xmax, ymax, m);
      end
    end
    if (count) begin
      sum1 += c1; sum2 += c2; n_edges++;
      if (c1 > max1) max1 = c1;
      if (c2 > max2) max2 = c2;
      if (c2 < c1) hist_less++; else if (c2 == c1) hist_same++; else hist_more++;
    end
    // Results (both lanes hold them now).
    begin
      bit bad;
      bad = improved_mirror_o != improved2_mirror || improved_dir_o != improved2_dir || improved_horiz_o != improved2_horiz ||
            improved_d != improved2_d || improved_enters != improved2_enters;
      if (!improved_horiz_o) begin
        bad |= improved_ssat != improved2_ssat;
        if (!improved_ssat) bad |= improved_qs != improved2_qs || improved_rs != improved2_rs;
      end
      if (improved_enters) begin
        bad |= improved_je != improved2_je || improved_est != improved2_est;
        if (improved_est == RowBound) bad |= improved_ex != improved2_ex || improved_ee != improved2_ee;
      end
      if (bad) begin
        errors++;
        if (errors <= 10)
          $display("improved2_edge_lane_tb: ERROR a=%0d b=%0d el=%0d er=%0d xmax=%0d ymax=%0d m=%0d: improved h%0b m%0b d%0b D=%0d qs=%0d rs=%0d sat%0b en%0b j=%0d st=%0d x=%0d e=%0d | improved2 h%0b m%0b d%0b D=%0d qs=%0d rs=%0d sat%0b en%0b j=%0d st=%0d x=%0d e=%0d",
                   a, b, el, er, xmax, ymax, m,
                   improved_horiz_o, improved_mirror_o, improved_dir_o, improved_d, improved_qs, improved_rs, improved_ssat, improved_enters, improved_je, improved_est, improved_ex, improved_ee,
                   improved2_horiz, improved2_mirror, improved2_dir, improved2_d, improved2_qs, improved2_rs, improved2_ssat, improved2_enters, improved2_je, improved2_est, improved2_ex, improved2_ee);
      end
    end
    // Walk both (the improved unit's walkers), row by row.
    if (ymax < WalkRows) begin
      wload = 1'b1;
      @(posedge clk); #1;
      wload = 1'b0;
      for (int j = 0; j <= int'(ymax); j++) begin
        wrow = WB'(j);
        if (ws1 != ws2 || (ws1 == RowBound && wx1 != wx2)) begin
          errors++;
          if (errors <= 10)
            $display("improved2_edge_lane_tb: ERROR walk a=%0d b=%0d el=%0d er=%0d xmax=%0d ymax=%0d row %0d: improved %0d x %0d, improved2 %0d x %0d",
                     a, b, el, er, xmax, ymax, j, ws1, wx1, ws2, wx2);
          break;
        end
        walked_rows++;
        wadv = 1'b1;
        @(posedge clk); #1;
        wadv = 1'b0;
      end
    end
  endtask

  // ---- random fields ----
  function automatic longint rnd64();
    return {$urandom, $urandom};
  endfunction
  // A signed value of at most `bits` bits (two's complement range), often special.
  function automatic longint pick_signed(input int bits);
    longint lim, v;
    int k;
    lim = (longint'(1) << (bits - 1)) - 1;
    k = $urandom % 12;
    case (k)
      0: v = 0;
      1: v = 1;
      2: v = -1;
      3: v = lim;
      4: v = -lim;
      5: v = -lim - 1;
      default: begin
        v = rnd64() & lim;
        v = v >> ($urandom % bits);
        if ($urandom % 2) v = -v;
      end
    endcase
    return v;
  endfunction
  function automatic logic [BB-1:0] pick_box();
    int k;
    k = $urandom % 8;
    case (k)
      0: return '0;
      1: return 1;
      2: return {BB{1'b1}};
      default: return BB'($urandom) >> ($urandom % BB);
    endcase
  endfunction

  initial begin
    string path;
    int fd, n, tiny;
    longint fa, fb, fel, fer, fxm, fym;
    load = 0; wload = 0; wadv = 0; wrow = '0;
    a = '0; b = '0; el = '0; er = '0; xmax = '0; ymax = '0; m = 2;
    walked_rows = 0;
    repeat (3) @(posedge clk);
    #1 rst_n = 1;
    @(posedge clk); #1;

    // Random and hard edges.
    stats_reset();
    for (int i = 0; i < Random; i++) begin
      // |A|, |B| < 2^p (docs/unit.md): magnitudes of at most CB - 1 bits.
      a = CB'(pick_signed(CB));
      b = CB'(pick_signed(CB));
      if (a == {1'b1, {(CB-1){1'b0}}}) a = a + 1'b1;
      if (b == {1'b1, {(CB-1){1'b0}}}) b = b + 1'b1;
      xmax = pick_box();
      ymax = pick_box();
      // Tall boxes make long traversals: keep most of them short.
      if (ymax > 2000 && ($urandom % 8) != 0) ymax = ymax & 14'h3ff;
      el = EB'(pick_signed(EB - 1));
      if ($urandom % 2) er = el + EB'(longint'(a) * longint'(xmax) * (longint'(1) << F));
      else er = EB'(pick_signed(EB - 1));
      m = ($urandom % 4 == 0) ? IB'(QB) : bits_plus_one(xmax);
      run_edge(1);
    end
    stats_print("random and hard edges");

    // A scene's edges.
    if ($value$plusargs("edges=%s", path)) begin
      fd = $fopen(path, "r");
      if (fd == 0) begin
        $display("improved2_edge_lane_tb: ERROR cannot open %s", path);
        errors++;
      end else begin
        longint s1t, s2t, nt;
        int m1t, m2t, k, l1t, l2t;
        stats_reset();
        s1t = 0; s2t = 0; nt = 0; m1t = 0; m2t = 0; k = 0; l1t = 0; l2t = 0;
        while (!$feof(fd)) begin
          n = $fscanf(fd, "%d %d %d %d %d %d %d\n", fa, fb, fel, fer, fxm, fym, tiny);
          if (n != 7) break;
          a = CB'(fa); b = CB'(fb); el = EB'(fel); er = EB'(fer);
          xmax = BB'(fxm); ymax = BB'(fym);
          m = bits_plus_one(xmax);
          // Stats over the edges the improved2 unit's lanes see (boxes larger than 2x2).
          run_edge(tiny == 0);
          // A triangle's lanes take L = max of its three edges (lines come in triangles).
          if (last1 > l1t) l1t = last1;
          if (last2 > l2t) l2t = last2;
          k++;
          if (k == 3) begin
            if (tiny == 0) begin
              s1t += l1t; s2t += l2t; nt++;
              if (l1t > m1t) m1t = l1t;
              if (l2t > m2t) m2t = l2t;
            end
            k = 0; l1t = 0; l2t = 0;
          end
        end
        $fclose(fd);
        stats_print({path, " (boxes larger than 2x2 pixels)"});
        $display("improved2_edge_lane_tb: %s: %0d triangles; lane cycles per triangle (max of its 3 edges) improved mean %.2f max %0d, improved2 mean %.2f max %0d",
                 path, nt, nt ? real'(s1t) / nt : 0.0, m1t, nt ? real'(s2t) / nt : 0.0, m2t);
      end
    end
    $display("improved2_edge_lane_tb: %0d walker rows compared", walked_rows);
    $display("improved2_edge_lane_tb: %0d errors", errors);
    $finish;
  end
endmodule
