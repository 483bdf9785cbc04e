// The improved2 unit's corner unit (rtl/common/trirast_corner_serial.sv: MSB-first on
// signed-digit pairs, radix 4 and 16) against the formula E_L = A*(cx0 - vx) + B*(cy0 - vy) - bias,
// on operands drawn over the full widths of the package (tb/improved2/run_checks.sh --check-all;
// built with Verilator's --binary). Unlike improved2_blocks_tb's corner trials (vertices of a
// triangle near the box), the vertices here are drawn over the full widths and include the
// extremes: vertices in {-2^(P-1), 2^(P-1) - 1, cx0, cy0 (a zero operand)}, so A and B (the
// vertices' edge coefficients, A_k = y_k - y_k+1, B_k = x_k+1 - x_k, as the unit forms them:
// trirast_corner_serial takes edge 2's operands from v0) reach +-(2^(P) - 1) and 0; box
// corners 0 and 2^PB - 1. It also checks the radix-16 unit's cycle count (busy for the fewest
// digits of 4 bits in which v0's and v1's operands fit as two's complement numbers) and its
// far-from-0 flags (the direct 2x2 test's far_i, fneg_i). Prints "improved2_corner_unit_tb: N
// errors (...)" and stops with $fatal on a difference.
`include "trirast_ports.svh"

module improved2_corner_unit_tb;
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  localparam int Trials = 20000;

  logic clk = 0, rst_n = 0;
  int errors = 0, extremes = 0, zeros = 0;
  longint max_abs = 0;

  logic [3*P-1:0] vx, vy;
  logic [3*CB-1:0] a, b;
  logic [3*(CB+1)-1:0] p;   // A + B per edge (trirast_corner_serial's p_i), set with a and b
  logic [2:0] bias;
  logic [PB-1:0] x0, y0;
  logic start;
  logic busy_sd4, busy_sd16;
  logic [3*EB-1:0] el_sd4, el_sd16;
  logic [2:0] far_sd16, fneg_sd16;   // E far from 0 (the 2x2 test's far_i): checked below
  int far_seen = 0, near_seen = 0;

  // The unit's corner unit: signed-digit pairs (rtl/common/trirast_corner_serial.sv).
  trirast_corner_serial #(.DigitBits (2)) u_sd4 (.clk_i (clk), .rst_ni (rst_n), .start_i (start),
    .second_i (1'b0), .run_i (3'b111), .vx_i (vx), .vy_i (vy), .a_i (a), .b_i (b), .p_i (p), .bias_i (bias),
    .x0_i (x0), .y0_i (y0), .xmax_i ('0), .busy_o (busy_sd4), .el_o (el_sd4));
  trirast_corner_serial #(.DigitBits (4)) u_sd16 (.clk_i (clk), .rst_ni (rst_n), .start_i (start),
    .second_i (1'b0), .run_i (3'b111), .vx_i (vx), .vy_i (vy), .a_i (a), .b_i (b), .p_i (p), .bias_i (bias),
    .x0_i (x0), .y0_i (y0), .xmax_i ('0), .busy_o (busy_sd16), .el_o (el_sd16),
    .far_o (far_sd16), .fneg_o (fneg_sd16));

  always #5 clk = ~clk;

  function automatic longint sx(input logic [63:0] v, input int w);
    sx = longint'(v << (64 - w)) >>> (64 - w);
  endfunction
  function automatic int bitlen(input longint v);  // v >= 0
    bitlen = 0;
    while (v != 0) begin
      bitlen++;
      v = v >> 1;
    end
  endfunction

  // A vertex coordinate against the box corner c (c = cx0 or cy0): uniform over P bits, near c,
  // or an extreme, or c itself (a zero operand).
  function automatic logic [P-1:0] vert(input longint c);
    unique case ($urandom % 8)
      0: vert = {1'b1, {(P - 1){1'b0}}};   // -2^(P-1): the largest c - v
      1: vert = {1'b0, {(P - 1){1'b1}}};   // 2^(P-1) - 1: the most negative c - v
      2: vert = P'(c);                     // c - v = 0
      3: vert = P'(c + longint'($urandom % 4096) - 2048);
      default: vert = P'({$urandom, $urandom});
    endcase
  endfunction

  task automatic trial();
    longint cx0, cy0, want;
    longint mag_sd [2];
    int sdigits, cyc, depth_seensd;
    bit ext;
    unique case ($urandom % 4)
      0: x0 = '0;
      1: x0 = '1;
      default: x0 = PB'($urandom);
    endcase
    unique case ($urandom % 4)
      0: y0 = '0;
      1: y0 = '1;
      default: y0 = PB'($urandom);
    endcase
    cx0 = longint'(x0) * (1 << F) + (1 << (F - 1));
    cy0 = longint'(y0) * (1 << F) + (1 << (F - 1));
    ext = 0;
    for (int k = 0; k < 3; k++) begin
      vx[k*P +: P] = vert(cx0);
      vy[k*P +: P] = vert(cy0);
      if (vx[k*P +: P] == {1'b1, {(P - 1){1'b0}}} || vy[k*P +: P] == {1'b1, {(P - 1){1'b0}}} ||
          vx[k*P +: P] == {1'b0, {(P - 1){1'b1}}} || vy[k*P +: P] == {1'b0, {(P - 1){1'b1}}}) ext = 1;
    end
    // The signed-digit unit's digits: v0's and v1's operands, two's complement.
    sdigits = 1;
    for (int k = 0; k < 2; k++) begin
      foreach (mag_sd[i]) begin
        mag_sd[i] = (i == 0) ? cx0 - sx(64'(vx[k*P +: P]), P) : cy0 - sx(64'(vy[k*P +: P]), P);
        while (mag_sd[i] < -(longint'(1) << (4 * sdigits - 1)) ||
               mag_sd[i] >= (longint'(1) << (4 * sdigits - 1))) sdigits++;
      end
    end
    for (int k = 0; k < 3; k++) begin   // the vertices' edge coefficients
      a[k*CB +: CB] = CB'(sx(64'(vy[k*P +: P]), P) - sx(64'(vy[((k + 1) % 3)*P +: P]), P));
      b[k*CB +: CB] = CB'(sx(64'(vx[((k + 1) % 3)*P +: P]), P) - sx(64'(vx[k*P +: P]), P));
      p[k*(CB+1) +: CB+1] = (CB+1)'(sx(64'(a[k*CB +: CB]), CB) + sx(64'(b[k*CB +: CB]), CB));
    end
    if (ext) extremes++;
    bias = 3'($urandom);
    @(negedge clk); start = 1; @(negedge clk); start = 0;
    cyc = 0;
    depth_seensd = -1;
    while ((busy_sd4 || busy_sd16) && cyc < 100) begin
      @(negedge clk);
      cyc++;
      if (!busy_sd16 && depth_seensd < 0) depth_seensd = cyc;
    end
    if (depth_seensd < 0) depth_seensd = cyc;
    if (depth_seensd != sdigits) begin
      errors++;
      if (errors < 10) $display("cycles: signed-digit unit busy %0d cycles, want %0d", depth_seensd,
                                sdigits);
    end
    for (int k = 0; k < 3; k++) begin
      longint A, B, vxk, vyk;
      A = sx(64'(a[k*CB +: CB]), CB);  B = sx(64'(b[k*CB +: CB]), CB);
      vxk = sx(64'(vx[k*P +: P]), P);  vyk = sx(64'(vy[k*P +: P]), P);
      if (A == 0 || B == 0 || vxk == cx0 || vyk == cy0) zeros++;
      want = A * (cx0 - vxk) + B * (cy0 - vyk) - longint'(bias[k]);
      if ((want < 0 ? -want : want) > max_abs) max_abs = want < 0 ? -want : want;
      // far: |E >> F| >= 2^CB and fneg = E < 0; else |E >> F| < 2^(CB+3) (the 2x2 test's contract)
      begin
        longint eh;
        eh = want >>> F;
        if (far_sd16[k]) far_seen++;
        else near_seen++;
        if (far_sd16[k] ? ((eh < 0 ? -eh : eh) < (longint'(1) <<< CB) || fneg_sd16[k] != (want < 0))
                        : ((eh < 0 ? -eh : eh) >= (longint'(1) <<< (CB + 3)))) begin
          errors++;
          if (errors < 10) $display("edge %0d: far %0d fneg %0d for E_L %0d", k, far_sd16[k],
                                    fneg_sd16[k], want);
        end
      end
      if (sx(64'(el_sd4[k*EB +: EB]), EB) != want || sx(64'(el_sd16[k*EB +: EB]), EB) != want) begin
        errors++;
        if (errors < 10) $display("edge %0d (A %0d B %0d dxL %0d dy %0d bias %0d): radix 4 %0d radix 16 %0d, want %0d",
          k, A, B, cx0 - vxk, cy0 - vyk, bias[k],
          sx(64'(el_sd4[k*EB +: EB]), EB), sx(64'(el_sd16[k*EB +: EB]), EB), want);
      end
    end
  endtask

  initial begin
    start = 0;
    repeat (2) @(negedge clk);
    rst_n = 1;
    for (int t = 0; t < Trials; t++) trial();
    $display("improved2_corner_unit_tb: %0d errors (%0d trials of 3 edges, %0d with an extreme operand, %0d edges with a zero operand, largest |E_L| %0d = 2^%0d; E far from 0 on %0d edges, near on %0d)",
             errors, Trials, extremes, zeros, max_abs, bitlen(max_abs) - 1, far_seen, near_seen);
    if (errors != 0) $fatal(1, "improved2_corner_unit_tb: FAILED");
    $finish;
  end
endmodule
