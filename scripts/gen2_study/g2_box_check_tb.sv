// gen2 study: a random cross-check of the box stage prototypes (scripts/gen2_study.sh --check,
// built with Verilator's --binary). Each triangle's box and empty flag come from the first generation's
// interface (rtl/common/trirast_box_stage.sv: accept, then StBox's empty_o, then the registered box),
// its operands from the formula (cx0 = x0*u + h, dxL = cx0 - vx_k, dy = cy0 - vy_k, magnitude and
// sign). Three designs then take the same triangles, each with its own random offer and stall
// pattern: g2_box_stage (Split = 0, one cycle), g2_box_stage3 (PortMinMax = 0 and 1). Each design's
// sequence of retirements (empty) and takes (the corner stage's register one cycle later) must be
// the triangles' in order with the expected contents: a lost, repeated, reordered or changed
// triangle is an error. Not part of the test suite.
module g2_box_check_tb;
  localparam int P = trirast_pkg::VertexBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int PB = trirast_pkg::PixBits;
  localparam int BB = trirast_pkg::BoxBits;
  localparam int TB = trirast_pkg::TagBits;
  localparam int F = trirast_pkg::FracBits;
  localparam int MW = P + 1;
  localparam int ND = 3;           // designs under test
  localparam int Batches = 100;    // viewport and stall pattern per batch
  localparam int PerBatch = 200;
  localparam longint VMin = -(longint'(1) <<< (P - 1));
  localparam longint VMax = (longint'(1) <<< (P - 1)) - 1;
  localparam longint H = longint'(1) <<< (F - 1);
  localparam longint U = longint'(1) <<< F;

  logic clk = 0, rst_n = 0;
  always #5 clk = ~clk;
  int errors = 0;
  int n_empty = 0, n_full = 0, n_stall = 0, n_last = 0, n_one = 0;
  logic [PB-1:0] vpx, vpy;

  // ---- the batch's triangles and their expected results ----
  logic [TB-1:0] s_tag[PerBatch];
  logic [3*P-1:0] s_vx[PerBatch], s_vy[PerBatch];
  logic [3*CB-1:0] s_a[PerBatch], s_b[PerBatch];
  logic [2:0] s_bias[PerBatch];
  logic g_empty[PerBatch];
  logic [PB-1:0] g_x0[PerBatch], g_y0[PerBatch];
  logic [BB-1:0] g_xmax[PerBatch], g_ymax[PerBatch];
  logic [6*MW-1:0] g_mag[PerBatch];
  logic [5:0] g_neg[PerBatch];

  // ---- gen1's interface: the reference box ----
  logic g1_accept = 0, g1_box = 0, g1_empty;
  logic [TB-1:0] g1_tag;
  logic [3*P-1:0] g1_vx, g1_vy;
  logic [PB-1:0] g1_x0, g1_y0;
  logic [BB-1:0] g1_xmax, g1_ymax;
  trirast_box_stage u_g1 (.clk_i (clk), .rst_ni (rst_n), .vp_xmax_i (vpx), .vp_ymax_i (vpy),
    .accept_i (g1_accept), .tag_i (g1_tag), .vx_i (g1_vx), .vy_i (g1_vy), .a_i ('0), .b_i ('0),
    .c_i ('0), .bias_i ('0), .box_i (g1_box), .empty_o (g1_empty), .tag_o (), .x0_o (g1_x0),
    .y0_o (g1_y0), .xmax_o (g1_xmax), .ymax_o (g1_ymax), .a_o (), .b_o (), .el_o (), .er_o ());

  // ---- the designs under test ----
  // The simulator (Verilator 5.006) does not re-evaluate the logic fed by an element written
  // with a variable index (a design's ready_o after take_i, PortMinMax = 1's step 1 on the port
  // data): the testbench writes these vectors whole.
  logic [ND-1:0] acc, rdy, take, full, emp;
  logic [ND-1:0][TB-1:0] i_tag, o_tag;
  logic [ND-1:0][3*P-1:0] i_vx, i_vy;
  logic [ND-1:0][3*CB-1:0] i_a, i_b, o_a, o_b;
  logic [ND-1:0][2:0] i_bias, o_bias;
  logic [ND-1:0][PB-1:0] o_x0, o_y0;
  logic [ND-1:0][BB-1:0] o_xmax, o_ymax;
  logic [ND-1:0][6*MW-1:0] o_mag;
  logic [ND-1:0][5:0] o_neg;
  logic ref_rdy;  // g2_box_stage has no ready output: the testbench forms it

  g2_box_stage #(.Split (0)) u_ref (.clk_i (clk), .rst_ni (rst_n), .vp_xmax_i (vpx),
    .vp_ymax_i (vpy), .accept_i (acc[0]), .tag_i (i_tag[0]), .vx_i (i_vx[0]), .vy_i (i_vy[0]),
    .a_i (i_a[0]), .b_i (i_b[0]), .bias_i (i_bias[0]), .take_i (take[0]), .full_o (full[0]),
    .empty_o (emp[0]), .c_tag_o (o_tag[0]), .c_x0_o (o_x0[0]), .c_y0_o (o_y0[0]),
    .c_xmax_o (o_xmax[0]), .c_ymax_o (o_ymax[0]), .c_a_o (o_a[0]), .c_b_o (o_b[0]),
    .c_bias_o (o_bias[0]), .c_mag_o (o_mag[0]), .c_neg_o (o_neg[0]));
  assign rdy[0] = ref_rdy;
  for (genvar d = 1; d < ND; d++) begin : g_dut
    g2_box_stage3 #(.PortMinMax (d - 1)) u_dut (.clk_i (clk), .rst_ni (rst_n), .vp_xmax_i (vpx),
      .vp_ymax_i (vpy), .accept_i (acc[d]), .tag_i (i_tag[d]), .vx_i (i_vx[d]), .vy_i (i_vy[d]),
      .a_i (i_a[d]), .b_i (i_b[d]), .bias_i (i_bias[d]), .ready_o (rdy[d]), .take_i (take[d]),
      .full_o (full[d]), .empty_o (emp[d]), .c_tag_o (o_tag[d]), .c_x0_o (o_x0[d]),
      .c_y0_o (o_y0[d]), .c_xmax_o (o_xmax[d]), .c_ymax_o (o_ymax[d]), .c_a_o (o_a[d]),
      .c_b_o (o_b[d]), .c_bias_o (o_bias[d]), .c_mag_o (o_mag[d]), .c_neg_o (o_neg[d]));
  end

  function automatic longint sx(input logic [63:0] v, input int w);
    sx = longint'(v << (64 - w)) >>> (64 - w);
  endfunction
  function automatic longint clamp(input longint v);
    clamp = (v < VMin) ? VMin : ((v > VMax) ? VMax : v);
  endfunction
  function automatic longint rnd(input longint lo, input longint hi);  // uniform in [lo, hi]
    rnd = lo + longint'({$urandom, $urandom} % 64'(hi - lo + 1));
  endfunction

  // One axis of a triangle, of a kind that covers the box's hard cases.
  function automatic logic [3*P-1:0] axis(input int kind, input logic [PB-1:0] vp);
    longint v[3], last, base;
    logic [3*P-1:0] r;
    last = longint'(vp) * U + H;  // the viewport's last pixel centre
    base = 0;
    case (kind)
      6: base = rnd(VMin, VMax);
      7: base = rnd(0, longint'(vp)) * U + rnd(0, U - 1);
      8: base = rnd(0, longint'(vp)) * U + H + 1;
      default: ;
    endcase
    for (int k = 0; k < 3; k++) begin
      case (kind)
        0: v[k] = rnd(VMin, VMax);                                  // anywhere
        1: v[k] = H + rnd(-600, 600);                               // around the first centre
        2: v[k] = last + rnd(-600, 600);                            // around the last centre
        3: v[k] = ($urandom % 2 == 0) ? rnd(VMin, H - 1) : H - 1 - rnd(0, 700);  // wholly before
        4: v[k] = ($urandom % 2 == 0) ? rnd(last + 1, VMax) : last + 1 + rnd(0, 700);  // after
        5: case ($urandom % 13)                                     // the limits
             0: v[k] = VMin;  1: v[k] = VMin + 1;  2: v[k] = VMax;  3: v[k] = VMax - 1;
             4: v[k] = 0;  5: v[k] = H - 1;  6: v[k] = H;  7: v[k] = H + 1;
             8: v[k] = last;  9: v[k] = last - 1;  10: v[k] = last + 1;
             11: v[k] = last + U - 1;  default: v[k] = last + U;
           endcase
        6: v[k] = base;                                             // degenerate: one point
        7: v[k] = base + rnd(0, 500);                               // a small box inside
        default: v[k] = base + rnd(0, U - 2);                       // between two centres
      endcase
      r[k*P +: P] = P'(clamp(v[k]));
    end
    axis = r;
  endfunction

  task automatic make_batch(input int batch);
    for (int i = 0; i < PerBatch; i++) begin
      int kx, ky;
      kx = $urandom % 9;  // y: the same kind, or one that mostly leaves a box
      case ($urandom % 6)
        0, 1: ky = kx;
        2: ky = 0;
        3: ky = 1 + 6 * int'($urandom % 2);
        4: ky = 2;
        default: ky = 7;
      endcase
      s_tag[i] = TB'(batch * 100000 + i);
      s_vx[i] = axis(kx, vpx);
      s_vy[i] = axis(ky, vpy);
      s_a[i] = {$urandom, $urandom, $urandom};
      s_b[i] = {$urandom, $urandom, $urandom};
      s_bias[i] = 3'($urandom);
    end
  endtask

  // The expected results: gen1's interface one triangle at a time, the operands by the formula.
  task automatic golden();
    for (int i = 0; i < PerBatch; i++) begin
      @(negedge clk);
      g1_accept = 1;  g1_tag = s_tag[i];  g1_vx = s_vx[i];  g1_vy = s_vy[i];
      @(negedge clk);
      g1_accept = 0;
      g_empty[i] = g1_empty;
      g1_box = 1;
      @(negedge clk);
      g1_box = 0;
      g_x0[i] = g1_x0;  g_y0[i] = g1_y0;  g_xmax[i] = g1_xmax;  g_ymax[i] = g1_ymax;
      if (!g_empty[i] && (g1_x0 + PB'(g1_xmax) == vpx || g1_y0 + PB'(g1_ymax) == vpy)) n_last++;
      if (!g_empty[i] && g1_xmax == 0 && g1_ymax == 0) n_one++;
      for (int k = 0; k < 3; k++) begin
        longint cx0, cy0, dx, dy;
        cx0 = longint'(g1_x0) * U + H;
        cy0 = longint'(g1_y0) * U + H;
        dx = cx0 - sx(64'(s_vx[i][k*P +: P]), P);
        dy = cy0 - sx(64'(s_vy[i][k*P +: P]), P);
        g_neg[i][2*k] = dx < 0;
        g_neg[i][2*k+1] = dy < 0;
        g_mag[i][2*k*MW +: MW] = MW'((dx < 0) ? -dx : dx);
        g_mag[i][(2*k+1)*MW +: MW] = MW'((dy < 0) ? -dy : dy);
      end
    end
  endtask

  // Design d's n-th retirement or take against the n-th triangle.
  task automatic check_event(input int d, input int n, input bit took);
    string what;
    what = "";
    if (n >= PerBatch) what = "more triangles out than in";
    else if (!took && !g_empty[n]) what = "retired as empty, gen1 has a box";
    else if (took && g_empty[n]) what = "taken, gen1 finds it empty";
    else if (took && (o_tag[d] != s_tag[n] || o_x0[d] != g_x0[n] || o_y0[d] != g_y0[n] ||
                      o_xmax[d] != g_xmax[n] || o_ymax[d] != g_ymax[n] || o_a[d] != s_a[n] ||
                      o_b[d] != s_b[n] || o_bias[d] != s_bias[n] || o_mag[d] != g_mag[n] ||
                      o_neg[d] != g_neg[n]))
      what = $sformatf("corner register differs: tag %0d x0 %0d y0 %0d xmax %0d ymax %0d neg %b, want tag %0d x0 %0d y0 %0d xmax %0d ymax %0d neg %b",
                       o_tag[d], o_x0[d], o_y0[d], o_xmax[d], o_ymax[d], o_neg[d],
                       s_tag[n], g_x0[n], g_y0[n], g_xmax[n], g_ymax[n], g_neg[n]);
    if (what != "") begin
      errors++;
      if (errors < 10)
        $display("design %0d, triangle %0d (vp %0d x %0d; vx %0d %0d %0d, vy %0d %0d %0d): %s", d, n,
                 vpx, vpy, sx(64'(s_vx[n % PerBatch][0 +: P]), P), sx(64'(s_vx[n % PerBatch][P +: P]), P),
                 sx(64'(s_vx[n % PerBatch][2*P +: P]), P), sx(64'(s_vy[n % PerBatch][0 +: P]), P),
                 sx(64'(s_vy[n % PerBatch][P +: P]), P), sx(64'(s_vy[n % PerBatch][2*P +: P]), P), what);
    end
  endtask

  // The batch through the three designs: per cycle and design a random offer (if the design is
  // ready) and a random take (if it holds a non-empty triangle).
  task automatic run_batch(input int offer_pct, input int take_pct);
    int nxt[ND], nev[ND], cycles;
    bit pend[ND];
    logic [ND-1:0] t_take, t_acc;
    logic [ND-1:0][TB-1:0] t_tag;
    logic [ND-1:0][3*P-1:0] t_vx, t_vy;
    logic [ND-1:0][3*CB-1:0] t_a, t_b;
    logic [ND-1:0][2:0] t_bias;
    for (int d = 0; d < ND; d++) begin
      nxt[d] = 0;  nev[d] = 0;  pend[d] = 0;
    end
    cycles = 0;
    while ((nev[0] < PerBatch || nev[1] < PerBatch || nev[2] < PerBatch) && cycles < 100 * PerBatch) begin
      @(negedge clk);
      cycles++;
      t_take = '0;
      for (int d = 0; d < ND; d++) begin
        if (pend[d]) begin  // the take of the last cycle: the corner register now holds it
          check_event(d, nev[d], 1);
          nev[d]++;
          pend[d] = 0;
        end
        if (full[d] && emp[d]) begin  // retires this cycle
          check_event(d, nev[d], 0);
          nev[d]++;
          if (d == 0) n_empty++;
        end else if (full[d]) begin
          if (int'($urandom % 100) < take_pct) begin
            t_take[d] = 1;
            pend[d] = 1;
            if (d == 0) n_full++;
          end else if (d == 0) n_stall++;
        end
      end
      take = t_take;
      #1;
      ref_rdy = !full[0] || take[0] || emp[0];
      #1;
      for (int d = 0; d < ND; d++) begin
        int i;
        i = (nxt[d] < PerBatch) ? nxt[d] : PerBatch - 1;
        t_tag[d] = s_tag[i];  t_vx[d] = s_vx[i];  t_vy[d] = s_vy[i];
        t_a[d] = s_a[i];  t_b[d] = s_b[i];  t_bias[d] = s_bias[i];
        t_acc[d] = nxt[d] < PerBatch && int'($urandom % 100) < offer_pct && rdy[d];
        if (t_acc[d]) nxt[d]++;
      end
      {i_tag, i_vx, i_vy, i_a, i_b, i_bias, acc} = {t_tag, t_vx, t_vy, t_a, t_b, t_bias, t_acc};
    end
    acc = '0;
    for (int d = 0; d < ND; d++) begin
      if (nev[d] != PerBatch) begin
        errors++;
        $display("design %0d: %0d of %0d triangles out after %0d cycles", d, nev[d], PerBatch, cycles);
      end
    end
    @(negedge clk);
    take = '0;
    for (int d = 0; d < ND; d++) begin
      if (full[d]) begin
        errors++;
        $display("design %0d: holds a triangle after the batch", d);
      end
    end
  endtask

  initial begin
    acc = '0;
    take = '0;
    vpx = 1023;  vpy = 767;
    repeat (2) @(negedge clk);
    rst_n = 1;
    for (int batch = 0; batch < Batches; batch++) begin
      int offer_pct, take_pct;
      case (batch % 5)
        0: begin vpx = 1023;  vpy = 767; end
        1: begin vpx = 0;  vpy = 0; end
        2: begin vpx = PB'((1 << PB) - 1);  vpy = PB'((1 << PB) - 1); end
        3: begin vpx = PB'($urandom % 64);  vpy = PB'($urandom % 64); end
        default: begin vpx = PB'($urandom);  vpy = PB'($urandom); end
      endcase
      offer_pct = (batch % 3 == 0) ? 100 : 30 + int'($urandom % 70);
      take_pct = (batch % 4 == 0) ? 100 : 5 + int'($urandom % 90);
      make_batch(batch);
      golden();
      run_batch(offer_pct, take_pct);
    end
    $display("g2_box_check_tb: %0d errors (%0d batches of %0d triangles through 3 designs; of them empty %0d, taken %0d: %0d reach the viewport's last column or row, %0d one pixel; cycles a taken triangle waited %0d)",
             errors, Batches, PerBatch, n_empty, n_full, n_last, n_one, n_stall);
    if (errors != 0) $fatal(1, "g2_box_check_tb: FAILED");
    $finish;
  end
endmodule
