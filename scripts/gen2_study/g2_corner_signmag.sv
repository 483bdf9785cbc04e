// gen2 study prototype (not a unit; scripts/gen2_study.sh rows g2.corner_msb4, g2.corner_msb16,
// g2.corner_msb16f, and g2_corner_check_tb): the second-generation unit's corner unit as rtl/ had
// it until its signed-digit pairs (rtl/improved2/trirast_improved2_corner_serial.sv, docs/gen2-design.md "The corner
// unit's signed-digit pairs"): operand magnitudes and signs, the multiplicands' digit products by
// shift-and-add. Kept here so the study's rows measure the circuit they describe. As it was:
// The second-generation improved unit's corner unit, CornerForm 1 (rtl/improved2/trirast_improved2.f, the
// iCE40 form): vertex-relative E_L by digit-serial
// shift-add, MSB first, DigitBits operand bits per cycle (2: radix 4, 4: radix 16), for the three
// edges at once:  E_L = A*dxL + B*dy - bias,  dxL = cx0 - vx, dy = cy0 - vy.
// The vertex of an edge: edge k runs from v_k to v_k+1, and v0 lies on edges 0 and 2, so both
// take their operands from v0 and edge 1 from v1 (E is the same from any point of the edge's
// line: A and B must be the vertices' edge coefficients, A_k = y_k - y_k+1, B_k = x_k+1 - x_k):
// two operand pairs, not three, and v2 is not read.
// Per cycle and edge: acc = (acc << DigitBits) +- A*digit(|dxL|) +- B*digit(|dy|) (the operand's
// sign picks add or subtract; A*digit by shift-and-add). Starts at the top non-zero digit of the
// largest operand (of v0's and v1's), so it takes ceil(bits / DigitBits) cycles (at least one)
// after the start cycle. Against g2_corner_digit (LSB first) it keeps no shifted multiplicands:
// the registers are the two operand magnitudes per vertex, the accumulator per edge, and a digit
// counter.
// SignFold 1 (the iCE40 fit, docs/gen2-design.md "Fitting the HX8K"; the same values and cycles):
// the operand's sign is applied to the 25-bit multiplicand (A' = +-A, B' = +-B, each cycle from
// the held sign) instead of to the 50-bit partial product, and the bias enters the last digit's
// B' * digit sum, so a digit costs two 26-bit negations and one 50-bit three-operand sum instead
// of two 50-bit negations, their selects and a four-operand sum.
// run_i with start_i: the edges whose accumulators this run clears and forms; an edge not in it
// holds its accumulator through the run (trirast_improved2_top's second run forms E_R only for the
// edges whose lane reads it, so each accumulator ends with the value its lane loads). The run's
// digit count still covers all three edges' operands: the same cycles whatever the mask.
// second_i with start_i: the second run, at x1 = x0 + Xmax: dx = cx1 - vx = dxL + Xmax * 2^F is
// formed from the first run's dxL, which the operand registers still hold (magnitude and sign),
// and xmax_i; the y operands are the first run's (cy0 - vy): the y magnitudes and signs are not
// reloaded, and the y part of the digit count is the one registered then. So a second start reads
// neither the vertices nor x0_i, y0_i.
module g2_corner_signmag #(
  parameter int DigitBits = 4,
  parameter bit SignFold  = 1'b0,
  // 1 (with SignFold): the sign-applied multiplicands A' = +-A, B' = +-B are registered at the
  // start (a_i, b_i are read only in the start cycle; with second_i B' is kept too), so a digit
  // cycle has no negation: six adder levels from a register to the accumulator, not seven.
  parameter bit RegMult   = 1'b0
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 start_i,
  input  logic                                 second_i,
  input  logic [2:0]                           run_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] vx_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] vy_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]   a_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]   b_i,
  input  logic [2:0]                           bias_i,
  input  logic [trirast_pkg::PixBits-1:0]      x0_i,
  input  logic [trirast_pkg::PixBits-1:0]      y0_i,
  input  logic [trirast_pkg::BoxBits-1:0]      xmax_i,   // second_i: Xmax
  output logic                                 busy_o,
  output logic [3*trirast_pkg::EdgeBits-1:0]   el_o
);
  localparam int F = trirast_pkg::FracBits;
  localparam int P = trirast_pkg::VertexBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int DW = P + 2;                        // cx - vx, signed
  localparam int MW = P + 1;                        // its magnitude
  localparam int DB = DigitBits;
  localparam int ND = (MW + DB - 1) / DB;           // digits of a magnitude
  localparam int NB = $clog2(ND + 1);
  localparam int PW = CB + DB + 1;                  // A * digit, signed

  logic signed [DW-1:0] cx0, cy0, xs;
  assign cx0 = $signed(DW'({x0_i, 1'b1}) << (F - 1));
  assign cy0 = $signed(DW'({y0_i, 1'b1}) << (F - 1));
  assign xs  = $signed(DW'({xmax_i, F'(0)}));       // second run: Xmax * 2^F

  logic [NB-1:0] cnt_q, cnt_d;        // digits left; the current digit is cnt_q - 1
  logic last_q;                       // RegMult: cnt_q == 1 (the last digit), from a register
  logic [ND*DB-1:0] any_x, any_y;     // OR of the start magnitudes of x, of y (the top digit)
  logic [NB-1:0] ny_q, ny_d;          // digits of the y magnitudes at the last first start

  function automatic logic signed [PW-1:0] pp(input logic signed [CB-1:0] m,
                                              input logic [DB-1:0] digit);
    logic signed [PW-1:0] sum;
    sum = '0;
    for (int i = 0; i < DB; i++) begin
      if (digit[i]) sum = sum + (PW'(m) <<< i);
    end
    pp = sum;
  endfunction

  // init + m * digit (SignFold: the multiplicand carries the sign; a function, so that no
  // always_comb block reads the variable it accumulates: Icarus re-runs such a block forever).
  function automatic logic signed [PW:0] pp_sum(input logic signed [PW:0] m,
                                                input logic [DB-1:0] digit,
                                                input logic signed [PW:0] init);
    logic signed [PW:0] sum;
    sum = init;
    for (int i = 0; i < DB; i++) begin
      if (digit[i]) sum = sum + (m <<< i);
    end
    pp_sum = sum;
  endfunction

  // ---- the operands of the two vertices (v0: edges 0 and 2; v1: edge 1) ----
  logic [ND*DB-1:0] mag_k [2][2];
  logic [2*DB-1:0] dgx_v, dgy_v;         // the current digits
  logic [1:0] sx_v, sy_v;                // the operands' signs (held)
  logic [1:0] dxs_v, dys_v;              // the signs of the operands being loaded
  for (genvar k = 0; k < 2; k++) begin : g_vertex
    logic [ND*DB-1:0] mx_q, mx_d, my_q, my_d;
    logic sx_q, sx_d, sy_q, sy_d;
    logic [DB-1:0] dgx, dgy;
    logic signed [DW-1:0] dxl, dy, mxw, vxw;
    logic [DW:0] dsum;
    // dxl: first run cx0 - vx = cx0 + ~vx + 1; second run Xmax * 2^F +- |dxL| (the held
    // magnitude and sign): one adder, its carry-in from the low bit of {.., 1} + {.., cin}.
    assign mxw  = $signed(DW'(mx_q[MW-1:0]));
    assign vxw  = DW'($signed(vx_i[k*P +: P]));
    assign dsum = {second_i ? xs : cx0, 1'b1}
                  + {second_i ? (sx_q ? ~mxw : mxw) : ~vxw, second_i ? sx_q : 1'b1};
    assign dxl  = $signed(dsum[DW:1]);
    logic unused_cin;   // the carry-in's own sum bit
    assign unused_cin = dsum[0];
    assign dy   = cy0 - DW'($signed(vy_i[k*P +: P]));
    logic [MW-1:0] amx, amy;
    assign amx = dxl[DW-1] ? MW'(-dxl) : MW'(dxl);
    assign amy = dy[DW-1] ? MW'(-dy) : MW'(dy);
    assign mag_k[k][0] = (ND * DB)'(amx);
    assign mag_k[k][1] = (ND * DB)'(amy);
    // The current digit of each operand: a ND-way select by the counter.
    always_comb begin
      dgx = '0;
      dgy = '0;
      for (int i = 0; i < ND; i++) begin
        if (cnt_q == NB'(i + 1)) begin
          dgx = mx_q[i*DB +: DB];
          dgy = my_q[i*DB +: DB];
        end
      end
    end
    assign dgx_v[k*DB +: DB] = dgx;
    assign dgy_v[k*DB +: DB] = dgy;
    always_comb begin
      mx_d = mx_q;  my_d = my_q;  sx_d = sx_q;  sy_d = sy_q;
      if (start_i) begin
        mx_d = mag_k[k][0];
        sx_d = dxl[DW-1];
        if (!second_i) begin
          my_d = mag_k[k][1];
          sy_d = dy[DW-1];
        end
      end
    end
    always_ff @(posedge clk_i) begin
      mx_q <= mx_d;  my_q <= my_d;  sx_q <= sx_d;  sy_q <= sy_d;
    end
    assign sx_v[k] = sx_q;
    assign sy_v[k] = sy_q;
    assign dxs_v[k] = dxl[DW-1];
    assign dys_v[k] = dy[DW-1];
  end
  logic unused_v2;   // v2: no edge takes its operands from it; the loading signs: RegMult's
  assign unused_v2 = ^{vx_i[2*P +: P], vy_i[2*P +: P], dxs_v, dys_v};

  // ---- the three edges: multiplicands, digit products, accumulators ----
  for (genvar k = 0; k < 3; k++) begin : g_edge
    localparam int V = (k == 1) ? 1 : 0;   // the edge's vertex
    logic run_q, run_d;
    logic sx_q, sy_q;
    logic signed [CB-1:0] ak, bk;
    logic signed [EB-1:0] acc_q, acc_d, tx, ty;
    logic [DB-1:0] dgx, dgy;
    assign sx_q = sx_v[V];
    assign sy_q = sy_v[V];
    assign dgx  = dgx_v[V*DB +: DB];
    assign dgy  = dgy_v[V*DB +: DB];
    assign ak  = $signed(a_i[k*CB +: CB]);
    assign bk  = $signed(b_i[k*CB +: CB]);
    // The multiplicands A, B: held by the unit's corner-stage input register (here the inputs).
    if (!SignFold) begin : g_pp
      assign tx = EB'(pp(ak, dgx));
      assign ty = EB'(pp(bk, dgy));
    end else begin : g_pps
      // A' * digit + B' * digit - bias_last: signs on the multiplicands (CB + 1 bits: -(-2^24)).
      // RegMult: A' and B' registered at the start, the last digit flagged by a register.
      logic signed [CB:0] ake, bke, as, bs;
      logic signed [PW:0] pxe, pye, px, py, nb;
      logic last;
      /* verilator lint_off WIDTH */   // sign extensions by assignment
      assign ake = ak;
      assign bke = bk;
      assign pxe = as;
      assign pye = bs;
      /* verilator lint_on WIDTH */
      if (RegMult) begin : g_reg
        logic signed [CB:0] as_q, bs_q;
        always_ff @(posedge clk_i) begin
          if (start_i) as_q <= dxs_v[V] ? -ake : ake;
          if (start_i && !second_i) bs_q <= dys_v[V] ? -bke : bke;
        end
        assign as = as_q;
        assign bs = bs_q;
        assign last = last_q;
      end else begin : g_comb
        assign as = sx_q ? -ake : ake;
        assign bs = sy_q ? -bke : bke;
        assign last = cnt_q == NB'(1);
      end
      assign nb  = (last && bias_i[k]) ? '1 : '0;   // -bias on the last digit
      assign px = pp_sum(pxe, dgx, '0);
      assign py = pp_sum(pye, dgy, nb);
      assign tx = EB'(px);
      assign ty = EB'(py);
    end
    always_comb begin
      acc_d = acc_q;  run_d = run_q;
      if (start_i) begin
        run_d = run_i[k];
        if (run_i[k]) acc_d = '0;
      end else if (cnt_q != '0 && run_q) begin
        if (SignFold) acc_d = ((acc_q <<< DB) + tx) + ty;
        else acc_d = (acc_q <<< DB) + (sx_q ? -tx : tx) + (sy_q ? -ty : ty)
                     - ((cnt_q == NB'(1)) ? EB'(bias_i[k]) : '0);
      end
    end
    always_ff @(posedge clk_i) begin
      acc_q <= acc_d;  run_q <= run_d;
    end
    assign el_o[k*EB +: EB] = acc_q;
  end

  // The number of digits of the largest operand (priority encoders: x's, y's, the larger).
  function automatic logic [NB-1:0] digits(input logic [ND*DB-1:0] v);
    digits = NB'(1);
    for (int i = 1; i < ND; i++) begin
      if (v[i*DB +: DB] != '0) digits = NB'(i + 1);
    end
  endfunction
  logic [NB-1:0] nx, ny;
  always_comb begin
    any_x = mag_k[0][0] | mag_k[1][0];
    any_y = mag_k[0][1] | mag_k[1][1];
    nx = digits(any_x);
    ny = second_i ? ny_q : digits(any_y);
    ny_d = (start_i && !second_i) ? ny : ny_q;
    cnt_d = (cnt_q != '0) ? cnt_q - 1'b1 : cnt_q;
    if (start_i) cnt_d = (nx > ny) ? nx : ny;
  end
  always_ff @(posedge clk_i) begin
    ny_q <= ny_d;
  end
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) cnt_q <= '0;
    else cnt_q <= cnt_d;
  end
  if (RegMult) begin : g_last
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) last_q <= 1'b0;
      else last_q <= cnt_d == NB'(1);
    end
  end else begin : g_nolast
    assign last_q = 1'b0;   // not read: the last digit is the counter's decode
    logic unused_last;
    assign unused_last = last_q;
  end
  assign busy_o = cnt_q != '0;

endmodule
