// Formal harness of the improved2 unit's direct 2x2 test (rtl/improved2/trirast_improved2_direct_test_2x2.sv,
// docs/formal.md "The 2x2 direct test") against the coverage rule written here: for every input, one
// step (the block is combinational). Wired as trirast_improved2_top wires it: TestHi = 1 (the
// default build) the test runs on E_L >> F and on A, B, A + B (W = EdgeBits - F, SW = CoefBits);
// TestHi = 0 on E_L and a = A*u, b = B*u, ab = (A + B)*u (W = EdgeBits, SW = CoefBits + F). Both
// take the signs from SW + 5 low bits and far/fneg (the split form); Split = 0: SW = 0, the
// block's form with full-width sums (far/fneg not read), which no top instantiates.
// Free: an edge's value E at the box's first pixel centre (x0, y0) without the bias, the bias
// (0 or -1), A and B (|A|, |B| < 2^(CoefBits-1), as the vertices' differences are), Xmax, Ymax
// (0 or 1), x0, y0, and far/fneg within the corner unit's contract
// (trirast_corner_serial.sv): far -> |E_L| >= 2^(F+CoefBits) and fneg = E_L < 0;
// not far -> |E_L| < 2^(F+CoefBits+3).
// The specification (docs/coverage-rule.md, section 5): pixel (x0 + i, y0 + j), i <= Xmax,
// j <= Ymax, is covered when E + bias + i*A*u + j*B*u >= 0 for all three edges (u = 2^F),
// computed without overflow; row j has a span when a pixel of it is covered, from its first
// covered pixel to one past its last.
//   Covered0/1  row j has a span exactly when the specification's row j has a covered pixel
//   Row0Y, Row0Begin, Row0End, Row1...  and then its y, x_begin, x_end are the specification's
module formal_direct_test_2x2 #(
  parameter bit TestHi = 1'b1,
  parameter bit Split = 1'b1
) (
  input logic clk_i
);
  localparam int F = trirast_pkg::FracBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int PB = trirast_pkg::PixBits;
  localparam int W = TestHi ? EB - F : EB;
  localparam int SW = !Split ? 0 : TestHi ? CB : CB + F;
  localparam int XW = EB + 4;   // the specification's sums: no overflow

  (* anyseq *) logic [3*EB-1:0] e_i;
  (* anyseq *) logic [2:0] bias_i;   // 1: bias -1
  (* anyseq *) logic [3*CB-1:0] a_i, b_i;
  (* anyseq *) logic [2:0] far_i, fneg_i;
  (* anyseq *) logic xmax_i, ymax_i;
  (* anyseq *) logic [PB-1:0] x0_i, y0_i;

  logic [3*EB-1:0] el;   // E_L = E + bias, the corner unit's output
  logic [3*W-1:0] t_el, t_a, t_b, t_ab;
  logic signed [XW-1:0] f_e [3][2][2];   // E + bias at pixel (i, j), exact
  always @* begin
    for (int k = 0; k < 3; k++) begin
      logic signed [EB-1:0] ek, elk;
      logic signed [CB-1:0] ak, bk;
      ek = $signed(e_i[k*EB +: EB]);
      ak = $signed(a_i[k*CB +: CB]);
      bk = $signed(b_i[k*CB +: CB]);
      elk = ek - EB'(bias_i[k]);
      el[k*EB +: EB] = elk;
      for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
          f_e[k][i][j] = XW'(ek) - XW'(bias_i[k]) + (XW'(i) * XW'(ak) + XW'(j) * XW'(bk)) * (XW'(1) <<< F);
      t_el[k*W +: W] = TestHi ? W'(elk >>> F) : W'(elk);
      t_a[k*W +: W]  = W'(ak) <<< (TestHi ? 0 : F);
      t_b[k*W +: W]  = W'(bk) <<< (TestHi ? 0 : F);
      t_ab[k*W +: W] = (W'(ak) + W'(bk)) <<< (TestHi ? 0 : F);
    end
  end

  logic [1:0] valid_o;
  logic [2*PB-1:0] y_o, xb_o;
  logic [2*(PB+1)-1:0] xe_o;
  trirast_improved2_direct_test_2x2 #(.W (W), .SW (SW)) dut (
    .el_i (t_el), .a_i (t_a), .b_i (t_b), .ab_i (t_ab), .far_i (far_i), .fneg_i (fneg_i),
    .xmax_i (xmax_i), .ymax_i (ymax_i), .x0_i (x0_i), .y0_i (y0_i), .valid_o (valid_o),
    .y_o (y_o), .xb_o (xb_o), .xe_o (xe_o));

  // ---- the environment ----
  always @* begin
    for (int k = 0; k < 3; k++) begin
      logic signed [EB-1:0] elk;
      logic signed [CB-1:0] ak, bk;
      logic signed [EB:0] mag;
      elk = $signed(el[k*EB +: EB]);
      ak = $signed(a_i[k*CB +: CB]);
      bk = $signed(b_i[k*CB +: CB]);
      // A, B are differences of VertexBits coordinates: never -2^(CB-1); E_L fits EdgeBits
      assume (ak != $signed({1'b1, (CB-1)'(0)}) && bk != $signed({1'b1, (CB-1)'(0)}));
      assume (!(bias_i[k] && e_i[k*EB +: EB] == {1'b1, (EB-1)'(0)}));
      mag = elk < 0 ? -((EB+1)'(elk)) : (EB+1)'(elk);   // -(W'(x)): Yosys 0.23 reads -W'(x) wrongly
      // the corner unit's far/fneg contract
      if (far_i[k]) assume (mag >= ((EB+1)'(1) << (F + CB)) && fneg_i[k] == (elk < 0));
      else assume (mag < ((EB+1)'(1) << (F + CB + 3)));
    end
  end

  // ---- the specification ----
  logic [1:0] f_cov [2];   // f_cov[j][i]: pixel (i, j) covered
  always @* begin
    for (int j = 0; j < 2; j++)
      for (int i = 0; i < 2; i++)
        f_cov[j][i] = f_e[0][i][j] >= 0 && f_e[1][i][j] >= 0 && f_e[2][i][j] >= 0 &&
                      (i == 0 || xmax_i) && (j == 0 || ymax_i);
  end
  // per row j: the expected valid, x_begin, x_end (labels per row: Yosys 0.23 names a labelled
  // assertion in a loop without its index)
  logic [1:0] f_valid;
  logic [PB-1:0] f_xb [2];
  logic [PB:0] f_xe [2];
  always @* begin
    for (int j = 0; j < 2; j++) begin
      f_valid[j] = f_cov[j] != 2'b00;
      f_xb[j] = x0_i + PB'(!f_cov[j][0]);
      f_xe[j] = (PB+1)'(x0_i) + (PB+1)'(f_cov[j][1] ? 2 : 1);
    end
  end
  always @* begin
    Covered0: assert (valid_o[0] == f_valid[0]);
    Covered1: assert (valid_o[1] == f_valid[1]);
    if (valid_o[0]) begin
      Row0Y: assert (y_o[0 +: PB] == y0_i);
      Row0Begin: assert (xb_o[0 +: PB] == f_xb[0]);
      Row0End: assert (xe_o[0 +: PB+1] == f_xe[0]);
    end
    if (valid_o[1]) begin
      Row1Y: assert (y_o[PB +: PB] == PB'(y0_i + 1'b1));
      Row1Begin: assert (xb_o[PB +: PB] == f_xb[1]);
      Row1End: assert (xe_o[PB+1 +: PB+1] == f_xe[1]);
    end
  end

  // ---- reachability (yosys-smtbmc -c): each row's cases, near the edges (not far) ----
  always @* begin
    CoverRowRight: cover (f_cov[1] == 2'b10 && far_i == 3'b000);
    CoverRowLeft: cover (f_cov[0] == 2'b01 && xmax_i && far_i == 3'b000);
    CoverAll: cover (f_cov[0] == 2'b11 && f_cov[1] == 2'b11 && far_i == 3'b000);
    CoverNone: cover (f_cov[0] == 2'b00 && f_cov[1] == 2'b00 && far_i == 3'b000);
  end
endmodule
