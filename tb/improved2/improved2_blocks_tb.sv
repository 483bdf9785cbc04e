// The improved2 unit's blocks on random operands, against the formulas they compute and the
// improved unit's blocks (tb/improved2/run_checks.sh --check-blocks; Verilator --binary; ctest
// improved2_block_checks):
//   corner values: trirast_improved2_corner_products and trirast_corner_serial (radix 4
//     and 16) against E_L = A*(cx0 - vx) + B*(cy0 - vy) - bias, vertices near the box;
//   edge walkers: trirast_improved2_edge_walker (carry-select and the carry-in step) against
//     rtl/improved/trirast_improved_edge_walker.sv row by row (state, and the bound on bound rows);
//   span generators: trirast_improved2_span_generator against
//     rtl/improved/trirast_improved_span_generator.sv (its bounds are the improved unit's - 1);
//   the direct 2x2 test: trirast_improved2_direct_test_2x2 at 50 bits and in the unit's split form
//     (TestHi) against the 12 sign tests written out.
// Prints "improved2_blocks_tb: N errors (...)" and stops with $fatal on a difference.
`include "trirast_ports.svh"

module improved2_blocks_tb;
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  localparam int Trials = 3000;

  logic clk = 0, rst_n = 0;
  int errors = 0;
  int bound_rows = 0, spans_valid = 0;

  // ---------------- corner values ----------------
  logic [3*P-1:0] vx, vy;
  logic [3*CB-1:0] a, b;
  logic [3*(CB+1)-1:0] p;   // A + B per edge (trirast_corner_serial's p_i), set with a and b
  logic [2:0] bias;
  logic [PB-1:0] x0, y0;
  logic [BB-1:0] xmax;
  logic start;
  logic busym4, busym16;
  logic [3*EB-1:0] m4_el, m16_el, mul_el;
  trirast_improved2_corner_products u_mul (.vx_i (vx), .vy_i (vy), .a_i (a), .b_i (b), .bias_i (bias), .x0_i (x0),
    .x1_i (x0), .x1sel_i (3'b000),
    .y0_i (y0), .el_o (mul_el));
  trirast_corner_serial #(.DigitBits (2)) u_m4 (.clk_i (clk), .rst_ni (rst_n), .start_i (start), .second_i (1'b0), .run_i (3'b111),
    .vx_i (vx), .vy_i (vy), .a_i (a), .b_i (b), .p_i (p), .bias_i (bias), .x0_i (x0), .y0_i (y0),
    .xmax_i ('0), .busy_o (busym4), .el_o (m4_el));
  trirast_corner_serial #(.DigitBits (4)) u_m16 (.clk_i (clk), .rst_ni (rst_n), .start_i (start), .second_i (1'b0), .run_i (3'b111),
    .vx_i (vx), .vy_i (vy), .a_i (a), .b_i (b), .p_i (p), .bias_i (bias), .x0_i (x0), .y0_i (y0),
    .xmax_i ('0), .busy_o (busym16), .el_o (m16_el));

  // ---------------- walkers ----------------
  logic load, adv, mirror, dir, ssat, enters;
  logic [SB-1:0] d;
  logic [QB-1:0] qs;
  logic [RB-1:0] rs, ee, ef;
  // The improved2 walkers take the error term as f: e for dir +, D - 1 - e for dir - (the lane's r).
  assign ef = dir ? ee : RB'(d) - 1'b1 - ee;
  // ... and X' as the leave offset o: X' - Xmax (dir +), -X' - 1 (dir -).
  logic signed [XB-1:0] eo;
  assign eo = dir ? ex - XB'(xmax) : -ex - 1'b1;
  // ... and the entry row's span bound - 1: Xmax - X' - 1 (mirrored), X' (not).
  logic [BB:0] eb;
  assign eb = mirror ? (BB + 1)'(XB'(xmax) - ex - 1'b1) : (BB + 1)'(ex);
  logic [WB-1:0] je, row;
  logic [1:0] est, st1, st2, st3;
  logic signed [XB-1:0] ex, x1;
  logic [BB:0] bnd2, bnd3;
  logic m1, m2, m3;
  trirast_improved_edge_walker #(.NumEndpoints (1)) u_w1 (.clk_i (clk), .rst_ni (rst_n), .load_i (load),
    .mirror_i (mirror), .dir_down_i (dir), .d_i (d), .qs_i (qs), .rs_i (rs), .ssat_i (ssat),
    .enters_i (enters), .j_entry_i (je), .entry_state_i (est), .entry_x_i (ex), .entry_e_i (ee),
    .xmax_i (xmax), .row_i (row), .adv_i (adv), .adv_rows_i (3'd1), .mirror_o (m1),
    .row_state_o (st1), .row_x_o (x1));
  trirast_improved2_edge_walker u_w2 (.clk_i (clk), .rst_ni (rst_n), .load_i (load), .mirror_i (mirror),
    .dir_down_i (dir), .d_i (d), .qs_i (qs), .rs_i (rs), .ssat_i (ssat), .enters_i (enters),
    .j_entry_i (je), .entry_state_i (est), .entry_x_i (eo), .entry_e_i (ef), .entry_b_i (eb),
    .adv_i (adv), .mirror_o (m2), .row_state_o (st2), .row_bound_o (bnd2));
  // The iCE40 fit's walker (carry-in step, no entry copies): the same rows.
  trirast_improved2_edge_walker #(.CarrySelect (1'b0)) u_w3 (.clk_i (clk), .rst_ni (rst_n), .load_i (load),
    .mirror_i (mirror), .dir_down_i (dir), .d_i (d), .qs_i (qs), .rs_i (rs), .ssat_i (ssat),
    .enters_i (enters), .j_entry_i (je), .entry_state_i (est), .entry_x_i (eo), .entry_e_i (ef),
    .entry_b_i (eb), .adv_i (adv), .mirror_o (m3), .row_state_o (st3), .row_bound_o (bnd3));

  // ---------------- span generators ----------------
  logic [5:0] gst;
  logic [3*XB-1:0] gx;
  logic [3*(BB+1)-1:0] gb;
  logic [2:0] gm;
  logic v1, v2;
  logic [BB:0] b1, e1, b2, e2;   // improved2's: begin - 1, end - 1 (its bounds are improved's - 1)
  trirast_improved_span_generator u_span_improved (.state_i (gst), .x_i (gx), .mirror_i (gm), .xmax_i (xmax),
    .valid_o (v1), .begin_o (b1), .end_o (e1));
  trirast_improved2_span_generator u_span_improved2 (.state_i (gst), .bound_i (gb), .mirror_i (gm), .xmax_i (xmax),
    .valid_o (v2), .begin_o (b2), .end_o (e2));

  // ---------------- 2x2 direct test ----------------
  logic [3*EB-1:0] t_el, t_a, t_b, t_ab;
  logic t_xm, t_ym;
  logic [1:0] t_valid;
  logic [2*PB-1:0] t_y, t_xb;
  logic [2*(PB+1)-1:0] t_xe;
  int tiny_spans = 0;
  trirast_improved2_direct_test_2x2 #(.W (EB)) u_box (.el_i (t_el), .a_i (t_a), .b_i (t_b), .ab_i (t_ab), .far_i (3'b000),
    .fneg_i (3'b000), .xmax_i (t_xm), .ymax_i (t_ym),
    .x0_i (x0), .y0_i (y0), .valid_o (t_valid), .y_o (t_y), .xb_o (t_xb), .xe_o (t_xe));
  // The unit's form (TestHi): E_L >> F in EB - F bits, A and B in CB bits, the sums' signs from
  // CB + 2 bits (SW); checked on the trials whose values fit it.
  localparam int TW = EB - F;
  logic [3*TW-1:0] s_el, s_a, s_b, s_ab;
  logic [1:0] s_valid;
  logic [2*PB-1:0] s_y, s_xb;
  logic [2*(PB+1)-1:0] s_xe;
  int split_boxes = 0;
  logic [2:0] s_far, s_fneg;   // E_L outside [-2^(CB+2), 2^(CB+2)), as the unit's corner unit says
  trirast_improved2_direct_test_2x2 #(.W (TW), .SW (CB)) u_boxs (.el_i (s_el), .a_i (s_a), .b_i (s_b), .ab_i (s_ab),
    .far_i (s_far), .fneg_i (s_fneg),
    .xmax_i (t_xm), .ymax_i (t_ym), .x0_i (x0), .y0_i (y0), .valid_o (s_valid), .y_o (s_y),
    .xb_o (s_xb), .xe_o (s_xe));

  // Row j of a 2x2 test's outputs against the expected span [first, last] (first < 0: none).
  function automatic bit row_wrong(input logic [1:0] valid, input logic [2*PB-1:0] y,
                                   input logic [2*PB-1:0] xb, input logic [2*(PB+1)-1:0] xe,
                                   input int j, input int first, input int last);
    row_wrong = (first >= 0) != valid[j] ||
                (first >= 0 && (y[j*PB +: PB] != PB'(32'(y0) + j) ||
                                xb[j*PB +: PB] != PB'(32'(x0) + first) ||
                                xe[j*(PB+1) +: PB+1] != (PB + 1)'(32'(x0) + last + 1)));
  endfunction
  // v in `bits` signed bits
  function automatic bit fits_signed(input longint v, input int bits);
    fits_signed = v >= -(longint'(1) <<< (bits - 1)) && v < (longint'(1) <<< (bits - 1));
  endfunction

  task automatic box_trial(input bit unit_form);
    longint e[3], av[3], bv[3];
    logic [3*EB-1:0] el_v, a_v, b_v;
    logic [3*TW-1:0] sel_v, sa_v, sb_v;
    bit fits;
    fits = 1;
    for (int k = 0; k < 3; k++) begin
      e[k]  = longint'($urandom % 2001) - 1000;
      av[k] = longint'($urandom % 2001) - 1000;
      bv[k] = longint'($urandom % 2001) - 1000;
      if (unit_form) begin
        // E_L = h * 2^CB + l with h around 0 and -1 (where the split form's cases meet), or any;
        // A, B of up to CB signed bits, often near their ends.
        longint h, l;
        case ($urandom % 5)
          0: h = 0;
          1: h = -1;
          2: h = longint'($urandom % 5) - 2;
          default: h = longint'($urandom % 64) - 32;
        endcase
        if ($urandom % 8 == 0) h = h <<< (TW - CB - 7);
        l = longint'({$urandom, $urandom} % (64'd1 << CB));
        e[k] = h * (longint'(1) <<< CB) + l;
        av[k] = longint'({$urandom, $urandom} % (64'd1 << CB)) - (longint'(1) <<< (CB - 1));
        bv[k] = longint'({$urandom, $urandom} % (64'd1 << CB)) - (longint'(1) <<< (CB - 1));
      end else if ($urandom % 4 == 0) begin  // large values too
        e[k] = e[k] <<< 30;  av[k] = av[k] <<< 30;  bv[k] = bv[k] <<< 30;
      end
      if (!fits_signed(av[k], CB) || !fits_signed(bv[k], CB) || !fits_signed(e[k], TW)) fits = 0;
      el_v[k*EB +: EB] = EB'(e[k]);
      a_v[k*EB +: EB]  = EB'(av[k]);
      b_v[k*EB +: EB]  = EB'(bv[k]);
      sel_v[k*TW +: TW] = TW'(e[k]);
      sa_v[k*TW +: TW]  = TW'(av[k]);
      sb_v[k*TW +: TW]  = TW'(bv[k]);
    end
    s_el = sel_v;
    s_a = sa_v;
    s_b = sb_v;
    t_el = el_v;
    t_a = a_v;
    t_b = b_v;
    for (int k = 0; k < 3; k++) begin
      s_far[k] = e[k] < -(longint'(1) <<< (CB + 2)) || e[k] >= (longint'(1) <<< (CB + 2));
      s_fneg[k] = e[k] < 0;
      s_ab[k*TW +: TW] = TW'(av[k] + bv[k]);
      t_ab[k*EB +: EB] = EB'(av[k] + bv[k]);
    end
    t_xm = 1'($urandom);
    t_ym = 1'($urandom);
    x0 = PB'($urandom % 1000);
    y0 = PB'($urandom % 1000);
    @(negedge clk);
    for (int j = 0; j < 2; j++) begin
      int first, last;
      first = -1;  last = -1;
      for (int i = 0; i < 2; i++) begin
        bit cov;
        cov = (i <= int'(t_xm)) && (j <= int'(t_ym));
        for (int k = 0; k < 3; k++) if (e[k] + i * av[k] + j * bv[k] < 0) cov = 0;
        if (cov) begin
          if (first < 0) first = i;
          last = i;
        end
      end
      if (row_wrong(t_valid, t_y, t_xb, t_xe, j, first, last)) begin
        errors++;
        if (errors < 10) $display("2x2 row %0d (xmax %0d ymax %0d, e %0d %0d %0d, a %0d %0d %0d, b %0d %0d %0d): want %0d [%0d,%0d), got %0d [%0d,%0d)",
          j, t_xm, t_ym, e[0], e[1], e[2], av[0], av[1], av[2], bv[0], bv[1], bv[2], first >= 0,
          first, last + 1, t_valid[j], t_xb[j*PB +: PB] - x0, t_xe[j*(PB+1) +: PB+1] - x0);
        if (errors < 4) $display("   dut: c00 %b c10 %b c01 %b c11 %b el0 %0d", u_box.c00, u_box.c10, u_box.c01, u_box.c11, $signed(t_el[0 +: EB]));
      end
      if (fits && row_wrong(s_valid, s_y, s_xb, s_xe, j, first, last)) begin
        errors++;
        if (errors < 10) $display("2x2 split row %0d (xmax %0d ymax %0d, e %0d %0d %0d, a %0d %0d %0d, b %0d %0d %0d): want %0d [%0d,%0d), got %0d",
          j, t_xm, t_ym, e[0], e[1], e[2], av[0], av[1], av[2], bv[0], bv[1], bv[2], first >= 0,
          first, last + 1, s_valid[j]);
        if (errors < 4) $display("   split dut: c00 %b c10 %b c01 %b c11 %b", u_boxs.c00, u_boxs.c10, u_boxs.c01, u_boxs.c11);
      end
      if (first >= 0) tiny_spans++;
    end
    if (fits) split_boxes++;
  endtask

  always #5 clk = ~clk;

  function automatic longint sx(input logic [63:0] v, input int w);
    sx = longint'(v << (64 - w)) >>> (64 - w);
  endfunction

  task automatic corner_trial(input int ext);
    longint ref_l[3], cx0, cy0;
    int cyc;
    int basex, basey;
    basex = $urandom % 64;
    basey = $urandom % 64;
    for (int k = 0; k < 3; k++) begin
      vx[k*P +: P] = P'(($urandom % (ext * 256)) + 256 * basex);
      vy[k*P +: P] = P'(($urandom % (ext * 256)) + 256 * basey);
    end
    for (int k = 0; k < 3; k++) begin
      longint ax, ay, bx, by;
      ax = sx(64'(vx[k*P +: P]), P);  ay = sx(64'(vy[k*P +: P]), P);
      bx = sx(64'(vx[((k+1)%3)*P +: P]), P);  by = sx(64'(vy[((k+1)%3)*P +: P]), P);
      a[k*CB +: CB] = CB'(ay - by);
      b[k*CB +: CB] = CB'(bx - ax);
      p[k*(CB+1) +: CB+1] = (CB+1)'((ay - by) + (bx - ax));
    end
    bias = 3'($urandom);
    // The box near the vertices (its centres inside their extent when ext is small); its width is
    // not read here, but drawn as before so that every later trial sees the same operands.
    x0 = PB'(basex + $urandom % ((ext < 64) ? ext : 64));
    y0 = PB'(basey + $urandom % ((ext < 64) ? ext : 64));
    xmax = BB'($urandom % ((ext < 16) ? ext : 200));
    cx0 = longint'(x0) * 256 + 128;
    cy0 = longint'(y0) * 256 + 128;
    for (int k = 0; k < 3; k++) begin
      longint A, B, vxk, vyk;
      A = sx(64'(a[k*CB +: CB]), CB);  B = sx(64'(b[k*CB +: CB]), CB);
      vxk = sx(64'(vx[k*P +: P]), P);  vyk = sx(64'(vy[k*P +: P]), P);
      ref_l[k] = A * (cx0 - vxk) + B * (cy0 - vyk) - longint'(bias[k]);
    end
    @(negedge clk); start = 1; @(negedge clk); start = 0;
    cyc = 0;
    while ((busym4 || busym16) && cyc < 100) begin @(negedge clk); cyc++; end
    for (int k = 0; k < 3; k++) begin
      if (sx(64'(m4_el[k*EB +: EB]), EB) != ref_l[k] || sx(64'(m16_el[k*EB +: EB]), EB) != ref_l[k] ||
          sx(64'(mul_el[k*EB +: EB]), EB) != ref_l[k]) begin
        errors++;
        if (errors < 10) $display("corner edge %0d: serial radix 4 %0d radix 16 %0d products %0d want %0d", k,
          sx(64'(m4_el[k*EB +: EB]), EB), sx(64'(m16_el[k*EB +: EB]), EB),
          sx(64'(mul_el[k*EB +: EB]), EB), ref_l[k]);
      end
    end
  endtask

  task automatic walker_trial();
    int rows;
    xmax = BB'($urandom % 40);
    // D and r_s with F zero low bits, as a lane hands them off (D = |A| * 2^F, r_s the remainder
    // of |B| * 2^F); e with any low bits (E's).
    d = SB'(1 + $urandom % 1000) << trirast_pkg::FracBits;
    qs = QB'($urandom % 6);
    rs = RB'($urandom % (d >> trirast_pkg::FracBits)) << trirast_pkg::FracBits;
    ee = RB'($urandom % d);
    ssat = ($urandom % 16) == 0;
    mirror = 1'($urandom);
    dir = 1'($urandom);
    enters = ($urandom % 8) != 0;
    je = WB'($urandom % 6);
    est = ($urandom % 4 == 0) ? (dir ? trirast_pkg::RowClear : trirast_pkg::RowOut) : trirast_pkg::RowBound;
    ex = XB'($urandom % (32'(xmax) + 1));
    rows = 2 + $urandom % 40;
    row = '0;
    @(negedge clk); load = 1; @(negedge clk); load = 0;
    for (int j = 0; j < rows; j++) begin
      logic [BB:0] want;
      want = m1 ? (BB + 1)'(32'(xmax) - 32'(x1) - 1) : (BB + 1)'(x1);   // the bound - 1
      if (st1 != st2 || (st1 == trirast_pkg::RowBound && want != bnd2) ||
          st1 != st3 || (st1 == trirast_pkg::RowBound && want != bnd3)) begin
        errors++;
        if (errors < 10) $display("walker row %0d: improved st %0d x %0d (bound %0d), improved2 st %0d bound %0d, carry-in st %0d bound %0d", j, st1, x1, want, st2, bnd2, st3, bnd3);
      end
      if (st1 == trirast_pkg::RowBound) bound_rows++;
      adv = 1; @(negedge clk); adv = 0; row = row + 1'b1;
    end
  endtask

  task automatic span_trial();
    // a bound row's X' lies in [0, Xmax) (the walker leaves at X' >= Xmax or X' < 0), so Xmax >= 1
    xmax = BB'(1 + $urandom % 40);
    for (int k = 0; k < 3; k++) begin
      logic signed [XB-1:0] x;
      gst[2*k +: 2] = ($urandom % 8 == 0) ? trirast_pkg::RowOut : (($urandom % 4 == 0) ? trirast_pkg::RowClear : trirast_pkg::RowBound);
      x = XB'($urandom % 32'(xmax));
      gm[k] = 1'($urandom);
      gx[k*XB +: XB] = x;
      gb[k*(BB+1) +: BB+1] = gm[k] ? (BB + 1)'(32'(xmax) - 32'(x) - 1) : (BB + 1)'(x);
    end
    #1;
    if (v1) spans_valid++;
    if (v1 != v2 || (v1 && (b1 != b2 + 1'b1 || e1 != e2 + 1'b1))) begin
      errors++;
      if (errors < 10) $display("span gen: improved %0d [%0d,%0d) improved2 %0d [%0d,%0d)", v1, b1, e1, v2, b2, e2);
    end
  endtask

  initial begin
    start = 0; load = 0; adv = 0; row = '0;
    repeat (2) @(negedge clk);
    rst_n = 1;
    for (int t = 0; t < Trials; t++) corner_trial((t % 3 == 0) ? 3 : ((t % 3 == 1) ? 15 : 4000));
    for (int t = 0; t < Trials; t++) walker_trial();
    for (int t = 0; t < 20 * Trials; t++) span_trial();
    for (int t = 0; t < 20 * Trials; t++) box_trial(t % 2 == 1);
    $display("improved2_blocks_tb: %0d errors (corner trials %0d; walker bound rows %0d; span rows %0d, of them with a span %0d; 2x2 boxes %0d, spans %0d, of them in the unit's split form %0d)",
             errors, Trials, bound_rows, 20 * Trials, spans_valid, 20 * Trials, tiny_spans, split_boxes);
    if (errors != 0) $fatal(1, "improved2_blocks_tb: FAILED");
    $finish;
  end
endmodule
