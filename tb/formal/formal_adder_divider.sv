// Formal harness of the improved unit's adder divider (rtl/improved/trirast_improved_adder_divider.sv;
// docs/unit.md, section 3; docs/formal.md, "Adder divider"). The operands are free at the
// package's full widths (numerator NumerBits = 50, divisor StepBits = 32 > 0, m = bits_i from 2
// to QuotBits = 15: anyconst, one set per trace, see below); en_i is free in every cycle (the
// lane drives it for m consecutive cycles; a gap only pauses the divider, so this is more
// general). The properties:
//   Sat         at the m-th iteration (last_o; the results leave combinationally): sat_o
//               exactly when n >= d * 2^m
//   QuotSat     ... saturated: q = 2^m - 1 (every quotient bit set)
//   RemBelowD   ... not saturated: r < d
//   QuotRem     not saturated: q * d + r = n, checked in the cycle after the m-th iteration on
//               the results held there (the quotient in the divider's register, QuotHeld: equal
//               to the output q); q * d is A_0, the end of a shift-and-add (Horner) chain over
//               q's bits: A_15 = 0, A_j = 2 A_(j+1) + q_j d (InvProdH, asserted in the same
//               cycle), so with RemBelowD q = floor(n / d) and r = n mod d
//   LastAfterM  last_o exactly in the m-th iteration; NotLast: never without an iteration
// The invariants on the divider's registers (its formal-only ports; after k iterations) that
// make them 1-inductive: InvIdle/InvIter (the iteration count and m), InvShift (the shifted
// divisor is d * 2^(m-1-k)), InvQuot (q_k < 2^k), InvRem (rem = n - S, S the sum of the shifted
// divisors subtracted so far: a ghost register), InvSatClass/InvSatQuot (saturated exactly when
// rem >= d * 2^(m-k), and then every bit so far set), FitsBit (the harness's compare is the
// divider's quotient bit), InvProdH (ghost registers A_j: the Horner chain of the quotient
// register times d; they move up with the register), InvSubP (S = A_0 * 2^(m-k)), and in the
// cycle after the last iteration QuotHeld, RemAfter (r = n - S) and SubAfter (S = A_0).
// Four proofs of this harness (tb/formal/proofs.json), so that each solver query stays small,
// each assuming only what earlier ones proved (sound: none assumes its own properties or a later
// one's):
//   adder_divider          (no define)        asserts the LEMMA properties
//   adder_divider_product  DIVIDER_PRODUCT    assumes them, asserts InvProdH (HLEMMA)
//   adder_divider_shift    DIVIDER_SUB        assumes the LEMMAs, asserts InvSubP, SubAfter (SLEMMA)
//   adder_divider_quot     DIVIDER_QUOT       assumes all of them, asserts QuotRem
// (All in one proof, or q * d as a combinational shift-and-add function of q, did not finish in
// 150-300 s with z3 or cvc5: the solvers then have to prove a shift-and-add multiplier's step
// identity on the bit level.)
`ifdef DIVIDER_QUOT
`define LEMMA assume
`define HLEMMA assume
`define SLEMMA assume
`elsif DIVIDER_PRODUCT
`define LEMMA assume
`define HLEMMA assert
`elsif DIVIDER_SUB
`define LEMMA assume
`define SLEMMA assert
`else
`define LEMMA assert
`endif
module formal_adder_divider (
  input logic clk_i
);
  localparam int NB = trirast_pkg::NumerBits;   // 50
  localparam int DB = trirast_pkg::StepBits;    // 32
  localparam int QB = trirast_pkg::QuotBits;    // 15
  localparam int RB = trirast_pkg::RemBits;     // 32
  localparam int IB = $clog2(QB + 1);           // 4
  // The width of the harness's arithmetic: every value below is < 2^(NB+1) or < 2^(DB+QB+1)
  // (n, d * 2^m, the product, the sums), so the equalities modulo 2^W are exact.
  localparam int W = (NB > DB + QB ? NB : DB + QB) + 2;

  (* anyseq *) logic rst_ni;
  (* anyseq *) logic en_i;
  (* anyseq *) logic [NB-1:0] numer_i;
  (* anyseq *) logic [DB-1:0] divisor_i;
  (* anyseq *) logic [IB-1:0] bits_i;
  // The operands of every division in a trace: arbitrary, fixed for the trace. No generality is
  // lost: a division's first iteration reads only the ports (numer_i, divisor_i, bits_i) and the
  // idle state (busy 0, iteration count 0; InvIdle), so each division behaves as the first.
  (* anyconst *) logic [NB-1:0] f_n;
  (* anyconst *) logic [DB-1:0] f_d;
  (* anyconst *) logic [IB-1:0] f_m;

  logic busy_o, last_o, sat_o;
  logic [QB-1:0] quot_o;
  logic [RB-1:0] rem_o;
  logic [IB-1:0] f_iter, f_bits;
  logic [NB-1:0] f_rem;
  logic [DB+QB-2:0] f_shift;
  logic [QB-1:0] f_quot;

  trirast_improved_adder_divider dut (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (en_i), .numer_i (numer_i), .divisor_i (divisor_i),
    .bits_i (bits_i), .busy_o (busy_o), .last_o (last_o), .quot_o (quot_o), .rem_o (rem_o),
    .sat_o (sat_o), .f_iter_o (f_iter), .f_bits_o (f_bits), .f_rem_o (f_rem),
    .f_shift_o (f_shift), .f_quot_o (f_quot));

  // ---- the environment: reset first; a division starts with the operands: d > 0, 2 <= m <= Q
  logic f_first_q = 1'b1;
  always @(posedge clk_i) f_first_q <= 1'b0;
  logic f_start;
  assign f_start = rst_ni && en_i && !busy_o;
  always @* begin
    if (f_first_q) assume (!rst_ni);
    assume (f_d != '0 && f_m >= IB'(2) && 32'(f_m) <= QB);
    if (f_start) assume (numer_i == f_n && divisor_i == f_d && bits_i == f_m);
  end

  logic [IB-1:0] f_k;   // iterations before this cycle's
  logic [W-1:0] n_w, d_w;
  assign n_w = W'(f_n);
  assign d_w = W'(f_d);
  assign f_k = f_iter;

  // ---- this cycle's iteration as the harness sees it: the shifted divisor, whether it fits,
  // what it subtracts and the place of its quotient bit ----
  logic [W-1:0] f_shift_in, f_rem_in, f_x;
  logic f_fits;
  logic [IB-1:0] f_p;
  assign f_shift_in = busy_o ? W'(f_shift) : (W'(divisor_i) << (bits_i - 1'b1));
  assign f_rem_in   = busy_o ? W'(f_rem) : W'(numer_i);
  assign f_fits     = f_rem_in >= f_shift_in;
  assign f_x        = f_fits ? f_shift_in : '0;
  assign f_p        = f_m - f_k - 1'b1;

  // ---- the ghosts: S (f_sub_q), the sum of the shifted divisors subtracted so far (n - rem);
  // A_j (f_acc[j]), the steps of the Horner product of the quotient register and d: A_15 = 0,
  // A_j = 2 A_(j+1) + q_j d, so A_0 = q_k * d (f_prod). As the quotient register moves up a bit,
  // the steps move with it (A_j <- A_(j-1)) and A_0 takes one more step. ----
  logic [W-1:0] f_sub_q, f_sub_next, f_prod, f_prod_next;
  logic [W-1:0] f_acc [QB+1];
  assign f_sub_next = (busy_o ? f_sub_q : '0) + f_x;
  assign f_acc[QB] = '0;
  assign f_prod = f_acc[0];
  assign f_prod_next = ((busy_o ? f_acc[0] : '0) << 1) + (f_fits ? d_w : '0);
  always @(posedge clk_i) begin
    if (en_i) f_sub_q <= f_sub_next;
  end
  for (genvar j = 0; j < QB; j++) begin : g_acc
    logic [W-1:0] acc_q;
    assign f_acc[j] = acc_q;
    always @(posedge clk_i) begin
      if (en_i) begin
        if (j == 0) acc_q <= f_prod_next;
        else acc_q <= busy_o ? f_acc[j > 0 ? j - 1 : 0] : '0;
      end
    end
  end

  // ---- the results of the last iteration, held for the cycle after it (f_after_q) ----
  logic f_after_q, f_sat_out;
  logic [QB-1:0] f_q_out;
  logic [RB-1:0] f_r_out;
  always @(posedge clk_i) begin
    f_after_q <= rst_ni && last_o;
    f_q_out   <= quot_o;
    f_r_out   <= rem_o;
    f_sat_out <= sat_o;
  end


  always @* begin
    if (rst_ni) begin
      // the properties: the results of the m-th iteration
      if (en_i) LastAfterM: `LEMMA (last_o == (f_k == f_m - 1'b1));
      if (!en_i) NotLast: `LEMMA (!last_o);
      if (en_i) FitsBit: `LEMMA (quot_o[0] == f_fits);
      if (last_o) begin
        Sat: `LEMMA (sat_o == (n_w >= (d_w << f_m)));
        if (!sat_o) RemBelowD: `LEMMA (W'(rem_o) < d_w);

        if (sat_o) QuotSat: `LEMMA (W'(quot_o) == (W'(1) << f_m) - 1'b1);
      end
      // invariants: idle, the iteration count is 0; while a division is under way, after
      // k = f_k iterations:
      // the cycle after the last iteration: the divider's quotient register holds the quotient
      // output, and the output remainder is n minus the subtracted divisors S
      if (f_after_q) begin
        QuotHeld: `LEMMA (f_quot == f_q_out);
        if (!f_sat_out) RemAfter: `LEMMA (W'(f_r_out) + f_sub_q == n_w);
`ifdef DIVIDER_QUOT
        // q * d + r = n for the output q and r: q * d is A_0, the end of the Horner chain over
        // q's bits (q: the register that holds it, QuotHeld; the chain's steps are InvProdH)
        if (!f_sat_out) QuotRem: assert (f_prod + W'(f_r_out) == n_w);
`endif
      end
      if (!busy_o) InvIdle: `LEMMA (f_iter == '0);
      if (busy_o) begin
        InvIter: `LEMMA (f_bits == f_m && f_k >= IB'(1) && f_k < f_m);
        InvShift: `LEMMA (W'(f_shift) == (d_w << (f_m - f_k - 1'b1)));
        InvQuot: `LEMMA (f_quot < (QB'(1) << f_k));
        InvRem: `LEMMA (W'(f_rem) + f_sub_q == n_w);
        InvSatClass: `LEMMA ((W'(f_rem) >= (W'(f_shift) << 1)) == (n_w >= (d_w << f_m)));
        if (n_w >= (d_w << f_m)) InvSatQuot: `LEMMA (f_quot == (QB'(1) << f_k) - 1'b1);
      end
    end
  end
`ifdef HLEMMA
  // the Horner steps of the quotient register times d, while a division is under way and in
  // the cycle after its last iteration (InvProdH; per j, unlabelled: Yosys 0.23 names a cell by
  // its label, the same in every generate iteration)
  for (genvar j = 0; j < QB; j++) begin : g_inv_h
    always @* begin
      if (rst_ni && (busy_o || f_after_q))
        `HLEMMA (f_acc[j] == (f_acc[j+1] << 1) + (f_quot[j] ? d_w : '0));
    end
  end
`endif
`ifdef SLEMMA
  // S is P shifted to the current divisor's place: S = P * 2^(m-k), and S = P after the last
  always @* begin
    if (rst_ni && busy_o) InvSubP: `SLEMMA (f_sub_q == (f_prod << (f_m - f_k)));
    if (rst_ni && f_after_q) SubAfter: `SLEMMA (f_sub_q == f_prod);
  end
`endif

  always @* begin
    if (rst_ni) begin
      CoverQuot: cover (last_o && !sat_o && quot_o == 15'h1234 && f_m == 4'd15);
      CoverSat: cover (last_o && sat_o && f_m == 4'd3);
    end
  end
endmodule
