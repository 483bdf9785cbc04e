// gen2 study prototype (not a unit; scripts/gen2_study.sh): trirast_improved2_corner_serial's MSB-first radix-16
// E_L (E_L = A*dxL + B*dy - bias, dxL = cx0 - vx, dy = cy0 - vy, the three edges at once),
// pipelined for the iCE40 HX's 50 MHz target:
//  - the multiplicands are registered at the start with the operand's sign applied, and with
//    their multiples 3x precomputed: A' = +-A, 3A' and -B', -3B' (B' = +-B; stored negated so
//    that the bias joins B's term, subtracted below);
//  - a radix-16 digit d = 4*d_hi + d_lo is two radix-4 digits: A'*d = (M(d_hi) << 2) + M(d_lo) with
//    M(.) a 4-way select of 0, A', 2A', 3A' (no adder in the select);
//  - stage 1 per edge: s = A'*dgx - (-B'*dgy + bias_last), the bias in the free low bit of
//    (M(d_hi) << 2) (two 29-bit adders in parallel, then one 30-bit subtraction), into a register;
//  - stage 2 per edge: acc = (acc << 4) + s, or acc = s for the first digit (a flag that travels
//    with the digit; one 46-bit adder, the low four bits are s's).
// RegStart = 1 registers the operand magnitudes, signs and A, B at the start and starts the
// digit stages one cycle later (the box stage B2's registers in the unit; one more cycle here).
// RegDigit = 1 adds a register after the digit select (the counter's ND-way select of the two
// operand digits) in front of stage 1. On the HX8K both reach about 61 MHz, limited by the start
// path (operand subtract, absolute value, digit count), which the unit's box stage B2 would
// register (docs/gen2-design.md section 1 c2).
// Cycles: the start cycle, ceil(bits / 4) digit cycles (at least one; bits = the largest bit length
// of the six magnitudes |dxL|, |dy|), then the pipeline's Depth = 1 + RegDigit cycles:
// busy_o is high for ceil(bits / 4) + Depth cycles after the start; el_o holds the result from
// then until stage 2 takes the next start's first digit (Depth + 1 cycles after that start). A
// start while busy_o is high is not supported (one corner computation at a time).
module g2_corner_msb16p #(
  parameter int RegDigit = 0,
  parameter int RegStart = 0
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 start_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] vx_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] vy_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]   a_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]   b_i,
  input  logic [2:0]                           bias_i,
  input  logic [trirast_pkg::PixBits-1:0]      x0_i,
  input  logic [trirast_pkg::PixBits-1:0]      y0_i,
  output logic                                 busy_o,
  output logic [3*trirast_pkg::EdgeBits-1:0]   el_o
);
  localparam int F = trirast_pkg::FracBits;
  localparam int P = trirast_pkg::VertexBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int DW = P + 2;                        // cx - vx, signed
  localparam int MW = P + 1;                        // its magnitude
  localparam int ND = (MW + 3) / 4;                 // radix-16 digits of a magnitude
  localparam int NB = $clog2(ND + 1);
  localparam int KW = CB + 2;                       // +-A, +-3A, signed (|3A| <= 3 * 2^(CB-1))
  localparam int TW = CB + 4;                       // A' * digit, signed (|15 A| < 2^(CB+3))
  localparam int SW = CB + 5;                       // s, signed

  logic signed [DW-1:0] cx0, cy0;
  assign cx0 = $signed(DW'({x0_i, 1'b1, (F - 1)'(0)}));
  assign cy0 = $signed(DW'({y0_i, 1'b1, (F - 1)'(0)}));

  logic [NB-1:0] cnt_q, cnt_d;        // digits left; the current digit is cnt_q - 1
  logic [ND*4-1:0] any_mag;           // OR of all start magnitudes (for the top digit)
  logic [ND*4-1:0] mag_k [3][2];
  logic [ND*4-1:0] magc [3][2];       // the magnitudes the start loads (RegStart: registered)
  logic startc;                       // the start of the digit stages (RegStart: one cycle later)

  // Stage-1 control: the digit is valid (dv) and the last one (dl, which carries the bias).
  logic dv, dl;
  logic sv_q, sf_q;                   // stage 2: s_q holds a digit's term, the first one
  logic df;                           // stage 1's digit is the first one

  // M(d): 0, m, 2m, 3m for a radix-4 digit d (m1 = m, m3 = 3m).
  function automatic logic signed [KW-1:0] mul4(input logic signed [KW-1:0] m1,
                                                input logic signed [KW-1:0] m3,
                                                input logic [1:0] d);
    unique case (d)
      2'd0: mul4 = '0;
      2'd1: mul4 = m1;
      2'd2: mul4 = m1 <<< 1;
      default: mul4 = m3;
    endcase
  endfunction
  // 3x in CB + 2 bits, without an adder whose two inputs are the same net (x's sign bit twice,
  // as in x + (x <<< 1): nextpnr-ice40 0.4's router did not finish with such a LUT): 3 * x's low
  // CB - 1 bits unsigned, then the sign's -3 * 2^(CB-1) in a 3-bit subtraction at the top.
  function automatic logic signed [KW-1:0] times3(input logic [CB-1:0] x);
    logic [CB:0] lo3;
    logic [2:0] hi;
    lo3 = (CB + 1)'(x[CB-2:0]) + ((CB + 1)'(x[CB-2:0]) << 1);
    hi = {1'b0, lo3[CB:CB-1]} - {1'b0, x[CB-1], x[CB-1]};
    times3 = {hi, lo3[CB-2:0]};
  endfunction
  // m * d + c for a radix-16 digit d and c in {0, 1}: ((M(d_hi) << 2) | c) + M(d_lo).
  function automatic logic signed [TW-1:0] mul16(input logic signed [KW-1:0] m1,
                                                 input logic signed [KW-1:0] m3,
                                                 input logic [3:0] d, input logic c);
    mul16 = ((TW'(mul4(m1, m3, d[3:2])) <<< 2) | TW'(c)) + TW'(mul4(m1, m3, d[1:0]));
  endfunction

  for (genvar k = 0; k < 3; k++) begin : g_edge
    logic signed [DW-1:0] dxl, dy;
    logic [ND*4-1:0] mx_q, my_q;
    logic signed [KW-1:0] ak, bk;
    logic signed [KW-1:0] a1_q, a3_q, nb1_q, nb3_q;   // A', 3A', -B', -3B'
    logic [3:0] dgx, dgy;                             // the digits stage 1 uses
    logic signed [TW-1:0] tx, uy;
    logic signed [SW-1:0] s_q;
    logic signed [EB-1:0] acc_q;
    assign dxl = cx0 - DW'($signed(vx_i[k*P +: P]));
    assign dy  = cy0 - DW'($signed(vy_i[k*P +: P]));
    logic [CB-1:0] ac, bc;
    logic sxc, syc;
    assign ak  = KW'($signed(ac));
    assign bk  = KW'($signed(bc));
    logic [MW-1:0] amx, amy;
    assign amx = dxl[DW-1] ? MW'(-dxl) : MW'(dxl);
    assign amy = dy[DW-1] ? MW'(-dy) : MW'(dy);
    assign mag_k[k][0] = (ND * 4)'(amx);
    assign mag_k[k][1] = (ND * 4)'(amy);
    // RegStart = 1: the operand magnitudes, signs and A, B registered first (the box stage B2's
    // registers in the unit, docs/gen2-design.md section 2), the digit stages start a cycle later.
    if (RegStart != 0) begin : g_regstart
      logic [ND*4-1:0] mx0_q, my0_q;
      logic [CB-1:0] a0_q, b0_q;
      logic sx0_q, sy0_q;
      always_ff @(posedge clk_i) begin
        if (start_i) begin
          mx0_q <= mag_k[k][0];
          my0_q <= mag_k[k][1];
          a0_q  <= a_i[k*CB +: CB];
          b0_q  <= b_i[k*CB +: CB];
          sx0_q <= dxl[DW-1];
          sy0_q <= dy[DW-1];
        end
      end
      assign magc[k][0] = mx0_q;
      assign magc[k][1] = my0_q;
      assign ac = a0_q;
      assign bc = b0_q;
      assign sxc = sx0_q;
      assign syc = sy0_q;
    end else begin : g_startcomb
      assign magc[k][0] = mag_k[k][0];
      assign magc[k][1] = mag_k[k][1];
      assign ac = a_i[k*CB +: CB];
      assign bc = b_i[k*CB +: CB];
      assign sxc = dxl[DW-1];
      assign syc = dy[DW-1];
    end

    // Start: operand magnitudes and the signed multiplicands. (3A is written inline: as a
    // continuous assignment of its own, Verilator 5.006 --timing evaluated it only at time 0.)
    always_ff @(posedge clk_i) begin
      if (startc) begin
        mx_q  <= magc[k][0];
        my_q  <= magc[k][1];
        a1_q  <= sxc ? -ak : ak;
        a3_q  <= sxc ? -times3(ac) : times3(ac);
        nb1_q <= syc ? bk : -bk;
        nb3_q <= syc ? times3(bc) : -times3(bc);
      end
    end

    // The current digit of each operand: a ND-way select by the counter.
    logic [3:0] selx, sely;
    always_comb begin
      selx = '0;
      sely = '0;
      for (int i = 0; i < ND; i++) begin
        if (cnt_q == NB'(i + 1)) begin
          selx = mx_q[i*4 +: 4];
          sely = my_q[i*4 +: 4];
        end
      end
    end
    if (RegDigit != 0) begin : g_regdigit
      logic [3:0] dgx_q, dgy_q;
      always_ff @(posedge clk_i) begin
        dgx_q <= selx;
        dgy_q <= sely;
      end
      assign dgx = dgx_q;
      assign dgy = dgy_q;
    end else begin : g_nodigitreg
      assign dgx = selx;
      assign dgy = sely;
    end

    // Stage 1: s = A'*dgx + B'*dgy - (last ? bias : 0) = tx - uy, uy = -B'*dgy + bias_last
    // (the bias in the free low bit of uy's shifted term: no carry-in from the fabric).
    logic signed [SW-1:0] txw, uyw;
    assign tx = mul16(a1_q, a3_q, dgx, 1'b0);
    assign uy = mul16(nb1_q, nb3_q, dgy, dl && bias_i[k]);
    assign txw = tx;
    assign uyw = uy;
    always_ff @(posedge clk_i) begin
      if (dv) s_q <= txw - uyw;
    end

    // Stage 2: acc = (acc << 4) + s, acc = s for the first digit; the low four bits are s's.
    // (No reset of acc by start_i: a start that is also a synchronous reset became a global net
    // with fabric loads, and nextpnr's router did not finish.)
    logic [EB-5:0] acc_hi;
    assign acc_hi = sf_q ? '0 : acc_q[EB-5:0];
    always_ff @(posedge clk_i) begin
      if (sv_q) acc_q <= {acc_hi + (EB - 4)'(s_q >>> 4), s_q[3:0]};
    end
    assign el_o[k*EB +: EB] = acc_q;
  end

  // The number of digits of the largest operand (priority encoder).
  always_comb begin
    any_mag = magc[0][0] | magc[0][1] | magc[1][0] | magc[1][1] | magc[2][0] | magc[2][1];
    cnt_d = (cnt_q != '0) ? cnt_q - 1'b1 : cnt_q;
    if (startc) begin
      cnt_d = NB'(1);
      for (int i = 1; i < ND; i++) begin
        if (any_mag[i*4 +: 4] != '0) cnt_d = NB'(i + 1);
      end
    end
  end
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) cnt_q <= '0;
    else cnt_q <= cnt_d;
  end
  if (RegStart != 0) begin : g_regstartctl
    logic start_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) start_q <= 1'b0;
      else start_q <= start_i;
    end
    assign startc = start_q;
  end else begin : g_startctl
    assign startc = start_i;
  end

  if (RegDigit != 0) begin : g_regctl
    logic dv_q, dl_q, df_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        dv_q <= 1'b0;
        dl_q <= 1'b0;
        df_q <= 1'b0;
      end else begin
        dv_q <= cnt_q != '0;
        dl_q <= cnt_q == NB'(1);
        df_q <= first_q;
      end
    end
    assign dv = dv_q;
    assign dl = dl_q;
    assign df = df_q;
  end else begin : g_ctl
    assign dv = cnt_q != '0;
    assign dl = cnt_q == NB'(1);
    assign df = first_q;
  end
  logic first_q;                      // the pointer is at the top digit
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) first_q <= 1'b0;
    else first_q <= startc;
  end
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      sv_q <= 1'b0;
      sf_q <= 1'b0;
    end else begin
      sv_q <= dv;
      sf_q <= df;
    end
  end
  assign busy_o = (RegStart != 0 && startc) || (cnt_q != '0) || dv || sv_q;

endmodule
