// Stage 3, adder_divider (docs/unit.md, section 3): a restoring divider, one quotient bit per
// iteration, MSB first, m iterations for an m-bit quotient (m = bits_i: Q with the fixed
// divider, Qx or Qy with the adaptive one). One per edge lane. The lane drives en_i for m
// consecutive cycles; the operands are taken in the first of them (so a division can follow
// another without a gap) and the results leave combinationally with last_o, for the lane to
// register at the end of that cycle.
// Saturation (n >= d * 2^m) is read off the final remainder: a saturated division sets every
// quotient bit and leaves r = n - (2^m - 1)*d >= d, an unsaturated one leaves r < d; this is the
// model's compare n >> m >= d without a second shifter.
`include "trirast_ports.svh"

`include "trirast_assert.svh"
module trirast_improved_adder_divider (
  input  logic                               clk_i,
  input  logic                               rst_ni,
  input  logic                               en_i,       // do one iteration this cycle
  input  logic [trirast_pkg::NumerBits-1:0]  numer_i,    // n >= 0, taken in the first iteration
  input  logic [trirast_pkg::StepBits-1:0]   divisor_i,  // d > 0, taken in the first iteration
  input  logic [$clog2(trirast_pkg::QuotBits+1)-1:0] bits_i,  // m: 2..Q, taken with the operands
  output logic                               busy_o,     // a division is under way
  output logic                               last_o,     // this cycle's iteration is its last
  output logic [trirast_pkg::QuotBits-1:0]   quot_o,     // q (all ones when saturated), at last_o
  output logic [trirast_pkg::RemBits-1:0]    rem_o,      // r = n - q*d (unsaturated: r < d)
  output logic                               sat_o       // n >= d * 2^m, at last_o
`ifdef FORMAL
  ,
  // Formal proofs only (tb/formal/formal_adder_divider.sv, docs/formal.md; FORMAL is defined by
  // Yosys's read_verilog -formal and by no simulation or synthesis flow): the registers, read by
  // the proof's invariants.
  output logic [$clog2(trirast_pkg::QuotBits+1)-1:0] f_iter_o,
  output logic [$clog2(trirast_pkg::QuotBits+1)-1:0] f_bits_o,
  output logic [trirast_pkg::NumerBits-1:0]  f_rem_o,
  output logic [trirast_pkg::StepBits+trirast_pkg::QuotBits-2:0] f_shift_o,
  output logic [trirast_pkg::QuotBits-1:0]   f_quot_o
`endif
);
  `TRIRAST_PKG_NAMES
  // The divisor shifted to the quotient's MSB, d << (Q - 1), and the width both fit in.
  localparam int ShiftBits = StepBits + QuotBits - 1;
  localparam int WideBits = (NumerBits > ShiftBits ? NumerBits : ShiftBits) + 1;
  localparam int IterBits = $clog2(QuotBits + 1);

  logic                 busy_q, busy_d;
  logic [IterBits-1:0]  iter_q, iter_d;    // iterations done in the current division
  logic [NumerBits-1:0] rem_q, rem_d;      // partial remainder
  logic [ShiftBits-1:0] shift_q, shift_d;  // d << k for the current bit k
  logic [QuotBits-1:0]  quot_q, quot_d;    // quotient bits so far
  logic [IterBits-1:0]  bits_q, bits_d;    // m of the current division

  // The operands of this iteration: the ports in the first one, the registers afterwards.
  logic [NumerBits-1:0] rem_in;
  logic [ShiftBits-1:0] shift_in;
  /* verilator lint_off UNUSEDSIGNAL */  // quot_in's MSB shifts out (see below)
  logic [QuotBits-1:0]  quot_in;
  /* verilator lint_on UNUSEDSIGNAL */
  logic [IterBits-1:0]  iter_in;
  logic [IterBits-1:0]  bits_in;
  logic [WideBits-1:0]  trial;  // the adder: partial remainder minus shifted divisor
  logic                 fits;   // its sign: the quotient bit
  logic                 last;   // this iteration is the division's last

  always_comb begin
    rem_in   = busy_q ? rem_q : numer_i;
    // The first iteration aligns the divisor with the quotient's MSB: d << (m - 1).
    shift_in = busy_q ? shift_q : (ShiftBits'(divisor_i) << (bits_i - 1'b1));
    quot_in  = busy_q ? quot_q : '0;
    iter_in  = busy_q ? iter_q : '0;
    bits_in  = busy_q ? bits_q : bits_i;
    trial    = WideBits'(rem_in) - WideBits'(shift_in);
    fits     = ~trial[WideBits-1];
    last     = en_i && (iter_in == bits_in - 1'b1);

    // Next state (each variable assigned once: Icarus re-evaluates a block on its own writes).
    busy_d  = en_i ? !last : busy_q;
    iter_d  = en_i ? (last ? '0 : iter_in + 1'b1) : iter_q;
    rem_d   = en_i ? (fits ? NumerBits'(trial) : rem_in) : rem_q;  // restore when it did not fit
    shift_d = en_i ? shift_in >> 1 : shift_q;
    // The MSB shifts out unused: it is 0 until the last iteration has shifted m bits in.
    quot_d  = en_i ? {quot_in[QuotBits-2:0], fits} : quot_q;
    bits_d  = en_i ? bits_in : bits_q;
    // Results of the last iteration (the remainder of an unsaturated division is < d; in the
    // last iteration the shifted divisor is d itself).
  end
  // Outputs as continuous assignments (see trirast_improved_edge_lane.sv).
  assign last_o = last;
  assign busy_o = busy_q;
  assign quot_o = quot_d;
  assign rem_o  = rem_d[RemBits-1:0];
  assign sat_o  = WideBits'(rem_d) >= WideBits'(shift_in);

  `TRIRAST_FLOP_AR({busy_q, iter_q}, {busy_d, iter_d}, '0)
`ifdef FORMAL
  assign {f_iter_o, f_bits_o, f_rem_o, f_shift_o, f_quot_o} = {iter_q, bits_q, rem_q, shift_q, quot_q};
`endif

  // Datapath registers: no reset (written by the first iteration before they are read).
  always_ff @(posedge clk_i) begin
    {rem_q, shift_q, quot_q, bits_q} <= {rem_d, shift_d, quot_d, bits_d};
  end

  // Cover points (docs/coverage.md): divisions by their iteration count m (at the last
  // iteration), in buckets up to the longest, m = Q (fixed mode, or adaptive with a box of
  // 2^(Q-1) or more pixels).
  `COVER(DivLen2to4_C, last && bits_in <= IterBits'(4), clk_i, !rst_ni)
  `COVER(DivLen5to8_C, last && bits_in >= IterBits'(5) && bits_in <= IterBits'(8), clk_i, !rst_ni)
  `COVER(DivLen9toQm1_C, last && bits_in >= IterBits'(9) && bits_in < IterBits'(QuotBits), clk_i,
         !rst_ni)
  `COVER(DivLenQ_C, last && bits_in == IterBits'(QuotBits), clk_i, !rst_ni)

endmodule
