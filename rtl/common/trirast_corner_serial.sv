// The digit-serial corner unit, shared by two units: the second-generation improved unit's
// CornerForm 1 (rtl/improved2/trirast_improved2_top.sv, the iCE40 form) and the half-space unit's
// set-up stage (rtl/halfspace/trirast_halfspace_setup_stage.sv). Vertex-relative corner values by
// digit-serial shift-add, MSB first, DigitBits operand bits per cycle (4: radix 16), for the three
// edges at once:
//   E_L = A*dx + B*dy - bias,  dx = cx0 - vx, dy = cy0 - vy.
// The vertex of an edge: edge k runs from v_k to v_k+1, and v0 lies on edges 0 and 2, so both
// take their operands from v0 and edge 1 from v1 (E is the same from any point of the edge's
// line: A and B must be the vertices' edge coefficients, A_k = y_k - y_k+1, B_k = x_k+1 - x_k):
// two operand pairs, not three, and v2 is not read.
//
// Signed-digit pairs (docs/improved2.md, "Architecture", C: the corner stage): the operands
// are two's complement, n digits of DigitBits bits each (n from the operands, below). Read with
// every bit as a digit s = 2b - 1 in {-1, +1}, and the top bit's sign flipped (b -> !b), the n*D
// bits of an operand d stand for sum(s_i * 2^i) = 2d + 1. So bit i of dx and bit i of dy together
// contribute 2^i * (s_x * A + s_y * B), which is one of +-(A + B), +-(A - B): the edge keeps
// P = A + B (p_i: the unit forms it, for its 2x2 test too) and M = A - B, registered at the first
// start (P complemented: E's subtraction of P then needs no inverters), and a bit pair selects P
// (bits equal) or M (bits differ), complemented when the x bit is 0 (one LUT4 per bit: the two
// bits, P's and M's). The complement's + 1 of the D bits of a digit is the x digit's
// complement, which fills the D free low bits of the shifted accumulator. Per cycle and edge:
//   acc = {acc, ~x digit} + (u_0 + 2 u_1 + 4 u_2 + 8 u_3)    (u_j the selected, complemented term)
// So after n digits acc = A(2dx + 1) + B(2dy + 1) = 2 (A dx + B dy) + P, and the unit's value is
// E = (acc - P) / 2 - bias (el_o: acc - P is even, so it is acc's bits above bit 0 minus P's,
// with the carry-in !bias). Four terms and one accumulator add per cycle, where the magnitudes'
// shift-and-add needs eight gated terms and two accumulator adds.
// The digit count: each operand must fit in n * D signed bits; n is the smallest count for which
// all four operands (v0's and v1's dx, dy) do, at least 1 (ceil((bits(d') + 1) / D), d' = d or
// ~d for d < 0: the sign bit counts). The run takes n cycles after the start cycle.
// run_i with start_i: the edges whose accumulators this run clears and forms; an edge not in it
// holds its accumulator through the run (trirast_improved2_top's second run forms E_R only for the
// edges whose lane reads it, so each accumulator ends with the value its lane loads). The run's
// digit count still covers all operands: the same cycles whatever the mask.
// second_i with start_i: the second run, at x1 = x0 + xmax_i (improved2: Xmax, for E_R; the
// half-space set-up: Xmax rounded down to its unit, for E_end): dx = cx1 - vx =
// dxL + xmax_i * 2^F is formed from the first run's dxL, which the operand registers still hold,
// and xmax_i; the y operands are the first run's (cy0 - vy): they are not reloaded, and the y
// part of the digit count is the one registered then; P and M are kept. So a second start reads
// neither the vertices, x0_i, y0_i, a_i nor b_i.
`include "trirast_assert.svh"
`include "trirast_ports.svh"

module trirast_corner_serial #(
  parameter int DigitBits = 4
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 start_i,
  input  logic                                 second_i,
  input  logic [2:0]                           run_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] vx_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] vy_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]   a_i,      // read at a first start only
  input  logic [3*trirast_pkg::CoefBits-1:0]   b_i,
  input  logic [3*(trirast_pkg::CoefBits+1)-1:0] p_i,    // A + B (a first start only)
  input  logic [2:0]                           bias_i,   // read while the value is out (el_o)
  input  logic [trirast_pkg::PixBits-1:0]      x0_i,
  input  logic [trirast_pkg::PixBits-1:0]      y0_i,
  input  logic [trirast_pkg::BoxBits-1:0]      xmax_i,   // second_i: Xmax
  output logic                                 busy_o,
  output logic [3*trirast_pkg::EdgeBits-1:0]   el_o,
  // E far from 0, read from the accumulator (so before E's carry chain ends): acc = 2E + P + 2 bias
  // outside [-2^K, 2^K), K = F + CoefBits + 3, so |E| >= 2^(K-1) - 2^(CoefBits-1) - 1 >=
  // 2^(F+CoefBits); else |E| < 2^(K-1) + 2^(CoefBits-1) + 1 < 2^(F+CoefBits+3) (|P| < 2^CoefBits;
  // rtl/improved2/trirast_improved2_direct_test_2x2.sv's far_i); fneg_o: acc < 0 (E < 0 when far).
  output logic [2:0]                           far_o,
  output logic [2:0]                           fneg_o
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  localparam int DB = DigitBits;
  localparam int DW = P + 2;                        // cx - vx, signed
  localparam int ND = (DW + DB - 1) / DB;           // digits of an operand
  localparam int SW = ND * DB;                      // an operand sign-extended to whole digits
  localparam int MW = CB + 1;                       // P = A + B, M = A - B, signed
  localparam int TW = MW + DB;                      // a cycle's sum of the DB terms, signed
  localparam int AW = EB + 1;                       // the accumulator: 2E + P, modulo 2^AW

  logic signed [DW-1:0] cx0, cy0, xs;
  assign cx0 = $signed(DW'({x0_i, 1'b1}) << (F - 1));
  assign cy0 = $signed(DW'({y0_i, 1'b1}) << (F - 1));
  assign xs  = $signed(DW'({xmax_i, F'(0)}));       // second run: Xmax * 2^F

  // The digit pointer, one-hot: the current digit (ptr_q) and the next one (ptr_d). The digits are
  // selected a cycle ahead (an AND-OR by ptr_d) into registers, so a digit cycle starts from the
  // digit registers; the first digit's top bit is the flipped sign, !d's sign bit (the operand
  // fits in n * D bits), set at the start.
  logic [ND-1:0] ptr_q, ptr_d, top;
  logic [ND-1:1] gy_q;                // the y operands' digit groups at the last first start

  // The digit groups of z = a value's adjacent bits' XOR (d fits in m signed bits exactly when z's
  // bits m - 1 and up are 0): group k (k >= 1) holds z's bits D*k - 1 .. D*k + D - 2, so a value
  // needs more than k digits exactly when a group k or above is not 0.
  function automatic logic [ND-1:1] groups(input logic [DW-2:0] z);
    for (int k = 1; k < ND; k++) groups[k] = |((z >> (DB * k - 1)) & (DW-1)'((1 << DB) - 1));
  endfunction

  // ---- the operands of the two vertices (v0: edges 0 and 2; v1: edge 1) ----
  logic [2*DB-1:0] dgx_v, dgy_v;         // the current digits (registers)
  logic [DW-2:0] zx_v [2];
  logic [DW-2:0] zy_v [2];
  for (genvar k = 0; k < 2; k++) begin : g_vertex
    logic signed [DW-1:0] dx, dy, vxw;
    logic [SW-1:0] mx_q, my_q;           // the operands, sign-extended to whole digits
    logic [DW:0] dsum;
    // dx: first run cx0 - vx = cx0 + ~vx + 1; second run dxL + Xmax * 2^F: one adder, its
    // carry-in from the low bit of {.., 1} + {.., cin}.
    assign vxw  = DW'($signed(vx_i[k*P +: P]));
    assign dsum = {second_i ? xs : cx0, 1'b1} + {second_i ? DW'(mx_q) : ~vxw, !second_i};
    assign dx   = $signed(dsum[DW:1]);
    logic unused_cin;   // the carry-in's own sum bit
    assign unused_cin = dsum[0];
    assign dy   = cy0 - DW'($signed(vy_i[k*P +: P]));
    assign zx_v[k] = dx[DW-1:1] ^ dx[DW-2:0];
    assign zy_v[k] = dy[DW-1:1] ^ dy[DW-2:0];
    always_ff @(posedge clk_i) begin
      if (start_i) mx_q <= SW'(dx);
      if (start_i && !second_i) my_q <= SW'(dy);
    end
    // The next digit of each operand: AND-OR by the next pointer, from the operands being loaded
    // at a start (the y operands of a second run are held), else the held ones.
    logic [SW-1:0] ox, oy;
    logic [DB-1:0] dgx_d, dgy_d, dgx_q, dgy_q;
    assign ox = start_i ? SW'(dx) : mx_q;
    assign oy = (start_i && !second_i) ? SW'(dy) : my_q;
    always_comb begin
      dgx_d = '0;
      dgy_d = '0;
      for (int i = 0; i < ND; i++) begin   // word-wide, not bit by bit (Verilator's cost)
        dgx_d = dgx_d | ({DB{ptr_d[i]}} & ox[i*DB +: DB]);
        dgy_d = dgy_d | ({DB{ptr_d[i]}} & oy[i*DB +: DB]);
      end
      if (start_i) begin   // the first digit: its top bit is the flipped sign
        dgx_d[DB-1] = !ox[SW-1];
        dgy_d[DB-1] = !oy[SW-1];
      end
    end
    always_ff @(posedge clk_i) begin
      dgx_q <= dgx_d;
      dgy_q <= dgy_d;
    end
    assign dgx_v[k*DB +: DB] = dgx_q;
    assign dgy_v[k*DB +: DB] = dgy_q;
  end
  logic unused_v2;   // v2: no edge takes its operands from it
  assign unused_v2 = ^{vx_i[2*P +: P], vy_i[2*P +: P]};

  // ---- the three edges: P, M, the digit terms, accumulators ----
  for (genvar k = 0; k < 3; k++) begin : g_edge
    localparam int V = (k == 1) ? 1 : 0;   // the edge's vertex
    logic run_q, run_d;   // reset: AccParity_A reads it
    logic signed [MW-1:0] ak, bk, pn_q, m_q;   // pn_q: ~P (no inverters at E's subtraction)
    logic [AW-1:0] acc_q, acc_d;
    logic [DB-1:0] dgx, dgy;
    logic signed [TW-1:0] tsum;
    assign dgx = dgx_v[V*DB +: DB];
    assign dgy = dgy_v[V*DB +: DB];
    assign ak  = MW'($signed(a_i[k*CB +: CB]));
    assign bk  = MW'($signed(b_i[k*CB +: CB]));
    always_ff @(posedge clk_i) begin
      if (start_i && !second_i) begin
        pn_q <= ~$signed(p_i[k*MW +: MW]);
        m_q <= ak - bk;
      end
    end
    // The terms: P or M by the bit pair, complemented when the x bit is 0.
    logic signed [MW-1:0] u [DB];
    for (genvar j = 0; j < DB; j++) begin : g_term
      assign u[j] = ((dgx[j] == dgy[j]) ? ~pn_q : m_q) ^ {MW{!dgx[j]}};
    end
    if (DB == 4) begin : g_tree4
      logic signed [MW+1:0] lo, hi;
      assign lo = (MW+2)'(u[0]) + ((MW+2)'(u[1]) <<< 1);
      assign hi = (MW+2)'(u[2]) + ((MW+2)'(u[3]) <<< 1);
      assign tsum = TW'(lo) + (TW'(hi) <<< 2);
    end else begin : g_chain
      always_comb begin
        tsum = '0;
        for (int j = 0; j < DB; j++) tsum = tsum + (TW'(u[j]) <<< j);
      end
    end
    always_comb begin
      acc_d = acc_q;  run_d = run_q;
      if (start_i) begin
        run_d = run_i[k];
        if (run_i[k]) acc_d = '0;
      end else if (ptr_q != '0 && run_q) begin
        acc_d = {acc_q[AW-DB-1:0], ~dgx} + AW'(tsum);
      end
    end
    always_ff @(posedge clk_i) begin
      acc_q <= acc_d;
    end
    `TRIRAST_FLOP_AR(run_q, run_d, 1'b0)
    // E = (acc - P) / 2 - bias: acc - P is even (acc's bit 0 is P's), so it is acc's bits above
    // bit 0 minus P's, and - bias the carry-in's complement.
    logic [EB:0] esum;
    logic signed [MW-2:0] phn;   // ~(P >> 1)
    assign phn  = pn_q[MW-1:1];
    assign esum = {acc_q[AW-1:1], 1'b1} + {EB'(phn), !bias_i[k]};
    assign el_o[k*EB +: EB] = esum[EB:1];
    localparam int K = F + CB + 3;
    assign far_o[k]  = !((&acc_q[AW-1:K]) || !(|acc_q[AW-1:K]));
    assign fneg_o[k] = acc_q[AW-1];
    logic unused_e;
    assign unused_e = ^{esum[0], acc_q[0]};
    `ASSERT_IMPLIES(AccParity_A, run_q && ptr_q == '0, acc_q[0] != pn_q[0], clk_i, !rst_ni)
  end

  // The run's top digit (one-hot): the highest group of any operand, digit 0 when none.
  logic [ND-1:1] gx, gy, g;
  // Formed in the start branch only (read nowhere else; gy only by gy_q at a first start).
  always_comb begin
    gx = 'x;  g = 'x;  top = 'x;
    gy = gy_q;
    ptr_d = ptr_q >> 1;
    if (start_i) begin
      gx = groups(zx_v[0] | zx_v[1]);
      if (!second_i) gy = groups(zy_v[0] | zy_v[1]);
      g = gx | gy;
      top = '0;
      top[0] = g == '0;
      for (int k = 1; k < ND; k++) top[k] = g[k] && (g >> k) == '0;   // no group above k
      ptr_d = top;
    end
  end
  always_ff @(posedge clk_i) begin
    if (start_i && !second_i) gy_q <= gy;
  end
  `TRIRAST_FLOP_AR(ptr_q, ptr_d, '0)
  assign busy_o = ptr_q != '0;

endmodule
