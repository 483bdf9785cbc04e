// gen2 study prototype (not a unit; scripts/gen2_study.sh): vertex-relative corner values by
// adder-based shift-add, DigitBits bits of the operands per cycle (1: radix 2, 2: radix 4), LSB
// first, stopping when the remaining operand bits are zero: iterations = ceil(bits(max(|dxL|,
// |dxR|, |dy|)) / DigitBits) per edge, the three edges in parallel (the slowest one sets done).
//   E_L = A*dxL + B*dy - bias,  E_R = A*dxR + B*dy - bias,  dxL = cx0 - vx, dxR = cx1 - vx,
//   dy = cy0 - vy (sign-magnitude: the multiplicand takes the operand's sign).
// WithER = 0 computes E_L only (E_R then comes from E_L + Xmax*a in the lanes).
module g2_corner_digit #(
  parameter int DigitBits = 1,
  parameter int WithER = 1
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
  input  logic [trirast_pkg::BoxBits-1:0]      xmax_i,
  output logic                                 busy_o,
  output logic [3*trirast_pkg::EdgeBits-1:0]   el_o,
  output logic [3*trirast_pkg::EdgeBits-1:0]   er_o
);
  localparam int F = trirast_pkg::FracBits;
  localparam int P = trirast_pkg::VertexBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int PB = trirast_pkg::PixBits;
  localparam int DW = P + 2;   // cx - vx, signed
  localparam int MW = P + 1;   // its magnitude
  localparam int DB = DigitBits;

  logic signed [DW-1:0] cx0, cx1, cy0;
  logic [PB-1:0] x1;
  assign x1  = x0_i + PB'(xmax_i);
  assign cx0 = $signed(DW'({x0_i, 1'b1, (F - 1)'(0)}));
  assign cx1 = $signed(DW'({x1, 1'b1, (F - 1)'(0)}));
  assign cy0 = $signed(DW'({y0_i, 1'b1, (F - 1)'(0)}));

  logic [2:0] busy_k;
  for (genvar k = 0; k < 3; k++) begin : g_edge
    logic signed [DW-1:0] dxl, dxr, dy;
    logic signed [EB-1:0] ae, be;
    logic [MW-1:0] ml_q, ml_d, mr_q, mr_d, my_q, my_d;       // remaining operand bits
    logic signed [EB-1:0] ml_mc_q, ml_mc_d, mr_mc_q, mr_mc_d, my_mc_q, my_mc_d;  // shifted +-A, +-B
    logic signed [EB-1:0] accl_q, accl_d, accr_q, accr_d;
    logic signed [EB-1:0] ppl, ppr, ppy;

    assign dxl = cx0 - DW'($signed(vx_i[k*P +: P]));
    assign dxr = cx1 - DW'($signed(vx_i[k*P +: P]));
    assign dy  = cy0 - DW'($signed(vy_i[k*P +: P]));
    assign ae  = EB'($signed(a_i[k*CB +: CB]));
    assign be  = EB'($signed(b_i[k*CB +: CB]));

    // Partial products of this cycle's digit, written as shift-and-add (a `*` would make Yosys
    // infer a DSP on xc7 and a generic multiplier on iCE40): radix 2 an AND, radix 4
    // 0, M, 2M, 3M (one adder), radix 16 three adders.
    function automatic logic signed [EB-1:0] pp(input logic signed [EB-1:0] m,
                                                input logic [DB-1:0] digit);
      logic signed [EB-1:0] sum;
      sum = '0;
      for (int i = 0; i < DB; i++) begin
        if (digit[i]) sum = sum + (m <<< i);
      end
      pp = sum;
    endfunction
    assign ppl = pp(ml_mc_q, ml_q[DB-1:0]);
    assign ppr = pp(mr_mc_q, mr_q[DB-1:0]);
    assign ppy = pp(my_mc_q, my_q[DB-1:0]);

    always_comb begin
      ml_d = ml_q;  mr_d = mr_q;  my_d = my_q;
      ml_mc_d = ml_mc_q;  mr_mc_d = mr_mc_q;  my_mc_d = my_mc_q;
      accl_d = accl_q;  accr_d = accr_q;
      if (start_i) begin
        ml_d = dxl[DW-1] ? MW'(-dxl) : MW'(dxl);
        mr_d = (WithER != 0) ? (dxr[DW-1] ? MW'(-dxr) : MW'(dxr)) : '0;
        my_d = dy[DW-1] ? MW'(-dy) : MW'(dy);
        ml_mc_d = dxl[DW-1] ? -ae : ae;
        mr_mc_d = dxr[DW-1] ? -ae : ae;
        my_mc_d = dy[DW-1] ? -be : be;
        accl_d = {EB{bias_i[k]}};  // -bias
        accr_d = {EB{bias_i[k]}};
      end else if (busy_k[k]) begin
        accl_d = accl_q + ppl + ppy;
        accr_d = accr_q + ppr + ppy;
        ml_d = ml_q >> DB;  mr_d = mr_q >> DB;  my_d = my_q >> DB;
        ml_mc_d = ml_mc_q <<< DB;  mr_mc_d = mr_mc_q <<< DB;  my_mc_d = my_mc_q <<< DB;
      end
    end

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        ml_q <= '0;  mr_q <= '0;  my_q <= '0;
      end else begin
        ml_q <= ml_d;  mr_q <= mr_d;  my_q <= my_d;
      end
    end
    always_ff @(posedge clk_i) begin
      ml_mc_q <= ml_mc_d;  my_mc_q <= my_mc_d;  accl_q <= accl_d;
      if (WithER != 0) begin
        mr_mc_q <= mr_mc_d;  accr_q <= accr_d;
      end else begin
        mr_mc_q <= '0;  accr_q <= '0;
      end
    end
    assign busy_k[k] = (ml_q != '0) || (mr_q != '0) || (my_q != '0);
    assign el_o[k*EB +: EB] = accl_q;
    assign er_o[k*EB +: EB] = accr_q;
  end
  assign busy_o = |busy_k;

endmodule
