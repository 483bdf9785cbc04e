// The second-generation improved unit's edge lane (rtl/improved2/trirast_improved2.f;
// docs/improved2.md, "Architecture", L: the lanes): one edge normalizer and one edge lane of the
// improved unit, redesigned for area and speed. Same results as
// rtl/improved/trirast_improved_edge_normalizer.sv + rtl/improved/trirast_improved_edge_lane.sv
// in boundary mode `step` (the mode is a build choice here: `divide` is not built), in a
// different number of cycles.
//
// What differs from gen1:
//  - The operation is a registered state; every next-state decision reads registers only (the
//    column value's sign, j <= Ymax, the iteration counter, the registered saturation flag).
//  - Each division has a set-up cycle that aligns the numerator: R = n >> m (one shifter, n
//    muxed between s and the column value). R is held without its F low bits: D's are zero, so
//    R's are the numerator's bits m + F - 1 .. m in every iteration, and the bit that enters R's
//    high part is picked by the counter from the register that holds it (s, or the column
//    value, frozen by then); the shifter forms R's high bits only. The iteration is then
//    {R, bit} - D at the divisor's width + 1 (25 bits), with no shifter in its path. Saturation
//    (n >> m >= D) is the sign of R - D (plus the bits shifted out above R) in the first
//    iteration, registered; a saturated division stops after its second cycle (its quotient and
//    remainder are not used by the walker).
//  - The boundary traversal (one add per row) runs at the same time as the slope division
//    (separate adder and registers); the entry-x division starts when both are done.
//  - dir - edges keep u = ~v = -v - 1 (so the traversal always adds s and "entered" is always
//    u >= 0) and divide u instead of -v = u + 1: X' = Xmax - 1 - q and e = D - 1 - r follow
//    from u's q, r without a correction, and the lane hands off r itself in both directions
//    (entry_e_o: the gen2 walker's direction-free error term f, e for dir + and D - 1 - e for
//    dir -), and X' as the walker's leave offset q - Xmax, the same in both directions (one
//    subtraction from Xmax registered the cycle after the load). The entry test q >= Xmax (both
//    directions) is formed bit-serially during the iterations.
//  - D, s, r_s, R and the column value are held without their F low bits: D's and s's are zero,
//    R's are the numerator's, and the column value's never change (s's are zero), so r's low
//    bits are u's from the load (E's for dir +, ~E's for dir -).
//  - The lane loads one edge value, e_i: E at the column it traverses, E_R (x0 + Xmax) when
//    dir == mirror, else E_L (x0); the unit's corner stage forms just that one per edge.
// Cycles (m = Qx, or Q with FixedM; P = PreIter; T = traversal steps; from the cycle after the
// load to the first cycle with done_o): a horizontal edge T + 1; otherwise
// max(m + P + 1, T + 1) + m + P when it enters the box, max(m + P + 1, T + 1) when it does not
// (a saturated division stops after 2 of its m + P iterations). gen1: T, T + 2m, T + m.
`include "trirast_ports.svh"

`include "trirast_assert.svh"
module trirast_improved2_edge_lane #(
  parameter int FixedM = 0,  // 0: m from m_i (adaptive divider); else m = FixedM (fixed divider)
  // 1: every division starts with a pre-iteration that tests R_0 = n >> m against D through the
  // trial subtractor (the saturation test) and, for a dir - entry, continues from D - 1 - R_0
  // with complemented numerator bits, which leaves e = D - 1 - r in R (no select for e; R - D is
  // then unused); one more cycle per division.
  parameter int PreIter = 0
) (
  input  logic                                    clk_i,
  input  logic                                    rst_ni,
  input  logic [$clog2(trirast_pkg::QuotBits+1)-1:0] m_i,  // iterations of an x division (2..Q),
                                                           // stable from the cycle after load_i
  // ---- load: the edge as the interface gives it ----
  input  logic                                    load_i,
  input  logic signed [trirast_pkg::CoefBits-1:0] a_i,
  input  logic signed [trirast_pkg::CoefBits-1:0] b_i,
  input  logic signed [trirast_pkg::EdgeBits-1:0] e_i,   // E_R when dir == mirror, else E_L
  // ---- the triangle's box (held while the lane works) ----
  input  logic [trirast_pkg::BoxBits-1:0]         xmax_i,
  input  logic [trirast_pkg::BoxBits-1:0]         ymax_i,
  // ---- progress ----
  output logic                                    busy_o,
  output logic                                    done_o,   // results valid (registered state)
  output logic                                    div_o,    // observation: a divider iteration
  output logic                                    step_o,   // ... a traversal row step
  // ---- results (as rtl/improved/trirast_improved_edge_lane.sv) ----
  output logic                                    horiz_o,
  `TRIRAST_IMPROVED_EDGE_RESULT(output, _o),  // entry_x_o: gen2: q - Xmax (not X')
  output logic [trirast_pkg::BoxBits:0]           entry_b_o,  // gen2: the entry row's span bound
                                                              // - 1 (rtl/improved2/trirast_improved2_edge_walker.sv)
  output logic [trirast_pkg::RemBits-1:0]         entry_e_o  // gen2: f, e for dir +, D - 1 - e
                                                             // for dir - (not gen1's e)
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  localparam int MB = SB - F;               // significant bits of D and s (|A|, |B| < 2^p)
  localparam int NB = EB - 1;               // numerator bits (a non-negative column value)
  localparam int IB = $clog2(QB + 1);

  // Operation states (registered).
  localparam logic [2:0] OpSlopeSet = 3'd0;  // align s for the slope division
  localparam logic [2:0] OpSlope    = 3'd1;  // slope iterations
  localparam logic [2:0] OpWait     = 3'd2;  // wait for the traversal; entry set-up when done
  localparam logic [2:0] OpEntry    = 3'd3;  // entry-x iterations
  localparam logic [2:0] OpDone     = 3'd4;

  logic [IB-1:0] m;
  assign m = (FixedM != 0) ? IB'(FixedM) : m_i;

  logic [2:0] op_q, op_d;
  logic horiz_q, mirror_q, dir_q;
  logic [MB-1:0] dhn_q, sh_q;                // ~|A|, |B| (D and s without their F zero bits; D
                                             // complemented, so the subtractions of D need no
                                             // inverter LUTs)
  logic signed [EB-F-1:0] u_q, u_d;          // column value v (dir +) or ~v (dir -) without its F
                                             // low bits (s's are zero: they never change)
  logic [F-1:0] elo_q;                       // E's F low bits: e's (r's low bits are u's; dir -
                                             // e's are ~u's, T1's)
  logic [WB-2:0] j_q;                        // row (at most Ymax + 1 < 2^(WB-1))
  logic [IB-1:0] cnt_q, cnt_d;               // bit of the quotient this iteration makes
  logic first_q, first_d;                    // first iteration of a division
  logic [MB-1:0] rh_q, rh_d;                 // partial remainder R without its F low bits
                                             // (< |A| when not saturated; R's low bits are
                                             // the numerator's, read from u_q or sh_q)
  logic stk_q, stk_d, sat_q, sat_d;          // bits above R at the set-up; saturated
  logic [QB-1:0] qs_q, qs_d, qe_q, qe_d;     // slope and entry quotients (shifted in MSB first)
  logic [MB-1:0] rsh_q, rsh_d;               // r_s without its F zero bits
  logic ssat_q, ssat_d;
  logic gt_q, gt_d, eq_q, eq_d;              // entry quotient vs Xmax, MSB first
  logic [BB-1:0] xmn_q;                      // ~Xmax, registered the cycle after the load (xmax_i
                                             // itself holds; reading it measured no smaller:
                                             // CHANGELOG.md, "Tried and not kept");
                                             // complemented, so the subtraction from q needs no
                                             // inverter LUTs
  logic ld_q;                                // the cycle after the load (Xmax is valid)

  // ---- normalizer (gen1's, folded into the load) ----
  logic horiz_n, mirror_n, dir_n;
  assign horiz_n  = a_i == '0;
  assign mirror_n = !a_i[CB-1] && !horiz_n;
  assign dir_n    = !b_i[CB-1];
  // |x| = (x - s) ^ s for the sign s (x - 1 complemented when negative): one adder whose carry
  // chain takes s as its other operand and whose sum LUTs absorb the complement (a negation and
  // a select map to three LUT4 per bit). |A|, |B| < 2^p: MB bits (a function, so that a
  // Verilated model forms them at the load only).
  function automatic logic [MB-1:0] abs_low(input logic signed [CB-1:0] x);
    /* verilator lint_off UNUSEDSIGNAL */
    logic [CB-1:0] ax;
    /* verilator lint_on UNUSEDSIGNAL */
    ax = (x + {CB{x[CB-1]}}) ^ {CB{x[CB-1]}};
    abs_low = ax[MB-1:0];
  endfunction
  // dir +: v = T (E_R when mirrored, else E_L); dir -: ~T1 (T1 = E_L when mirrored, else E_R):
  // in both cases e_i, the value at the column the lane traverses (without its F low bits).
  function automatic logic signed [EB-F-1:0] u_load(input logic signed [EB-1:0] e,
                                                   input logic dir);
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [EB-1:0] u;
    /* verilator lint_on UNUSEDSIGNAL */
    u = dir ? e : ~e;
    u_load = u[EB-1:F];
  endfunction

  // ---- traversal: registers only decide ----
  logic entered, in_box, trav_done, need_entry;
  assign entered    = !u_q[EB-F-1];
  assign in_box     = j_q <= (WB-1)'(ymax_i);
  assign trav_done  = entered || !in_box;
  assign need_entry = !horiz_q && entered && in_box;
  assign u_d        = u_q + (EB-F)'(sh_q);

  // ---- divider: set-up (shifter) and iteration ----
  localparam int HB = NB - F;               // numerator bits above its F low bits
  logic [HB-1:0] num, shifted;
  logic [MB-1:0] rh_set, rh_iter;
  logic stk_set;
  logic nbit, fits, sat_now, xbit;
  logic [MB:0] x_hi;                         // {R, bit}[RB:F]
  logic [MB+1:0] trial;
  logic pre, cmpl, qbit;
  localparam bit Pre = PreIter != 0;
  // With the pre-iteration: its cycle, and a dir - entry dividing D - 1 - R.
  assign pre  = Pre && first_q;
  assign cmpl = Pre && (op_q == OpEntry) && !dir_q;
  // R - D on R's high bits: its sign is the saturation test (first iteration) and, in the
  // end, ~(r - D) = D - 1 - r is a dir - edge's e.
  logic [MB:0] r_minus_d;
  logic [MB+1:0] rdsum;
  assign rdsum     = {1'b0, rh_q, 1'b1} + {1'b1, dhn_q, 1'b1};
  assign r_minus_d = rdsum[MB+1:1];
  assign sat_now = stk_q || !r_minus_d[MB];

  logic [MB+2:0] tsum;   // {R, bit} + ~D + 1, the carry-in from the low bit
  logic last, set_entry;
  // The divider's set-up and iteration are formed while the lane works only (op_q != OpDone;
  // 'x otherwise, where nothing reads them), so that a Verilated model skips them in idle cycles.
  always_comb begin
    op_d   = op_q;
    cnt_d  = cnt_q - 1'b1;
    first_d = 1'b0;
    rh_d   = rh_q;
    stk_d  = stk_q;
    {qs_d, qe_d, rsh_d, ssat_d, gt_d, eq_d} = {qs_q, qe_q, rsh_q, ssat_q, gt_q, eq_q};
    set_entry = 1'b0;
    {num, shifted, rh_set, stk_set, nbit, tsum, trial, fits, x_hi, qbit, rh_iter, xbit, last} = 'x;
    if (op_q != OpDone) begin
      // The set-up aligns n >> F (s's F low bits are zero): R[RB-1:F] = (n >> F) >> m.
      num     = (op_q == OpSlopeSet) ? HB'(sh_q) : u_q[HB-1:0];
      // With the pre-iteration, R = n >> (m + 1) and the pre-iteration shifts in n's bit m.
      shifted = Pre ? (num >> 1) >> m : num >> m;
      rh_set  = shifted[MB-1:0];
      stk_set = |shifted[HB-1:MB];
      // R's bit F - 1 in the iteration that makes quotient bit c is the numerator's bit c + F:
      // s's (bit c of |B|) or the column value's, which stays put while the entry division runs
      // (the traversal is over).
      nbit    = (op_q == OpSlope) ? sh_q[$clog2(MB)'(cnt_q)] : u_q[$clog2(EB - F)'(cnt_q)];
      x_hi    = {rh_q, nbit ^ (cmpl && !pre)};
      tsum    = {1'b0, x_hi, 1'b1} + {2'b11, dhn_q, 1'b1};
      trial   = tsum[MB+2:1];
      fits    = !trial[MB+1];
      qbit    = fits ^ cmpl;  // the quotient bit (complemented when dividing D - 1 - R)
      rh_iter = (pre && cmpl) ? ~trial[MB-1:0]
              : pre ? x_hi[MB-1:0]
              : fits ? trial[MB-1:0] : x_hi[MB-1:0];
      xbit    = (32'(cnt_q) < BB) ? xmax_i[cnt_q] : 1'b0;
      last    = (cnt_q == '0) || (!first_q && sat_q);
      unique case (op_q)
        OpSlopeSet: begin
          rh_d = rh_set; stk_d = stk_set; cnt_d = Pre ? m : m - 1'b1; first_d = 1'b1;
          qs_d = '0;
          op_d = OpSlope;
        end
        OpSlope: begin
          rh_d = rh_iter;
          if (!pre) qs_d = {qs_q[QB-2:0], qbit};
          if (last) begin
            rsh_d  = rh_iter;
            ssat_d = sat_q;
            op_d   = trav_done ? (need_entry ? OpEntry : OpDone) : OpWait;
            set_entry = trav_done && need_entry;
          end
        end
        OpWait: begin
          op_d = trav_done ? (need_entry ? OpEntry : OpDone) : OpWait;
          set_entry = trav_done && need_entry;
        end
        OpEntry: begin
          rh_d = rh_iter;
          if (!pre) qe_d = {qe_q[QB-2:0], qbit};
          // While equal so far: the first differing bit decides (gt is read only once eq is 0).
          if (eq_q && !pre) begin
            gt_d = qbit;
            eq_d = qbit == xbit;
          end
          if (last) op_d = OpDone;
        end
        default: op_d = OpDone;
      endcase
      if (set_entry) begin
        rh_d = rh_set; stk_d = stk_set; cnt_d = Pre ? m : m - 1'b1; first_d = 1'b1;
        qe_d = '0; gt_d = 1'b0; eq_d = 1'b1;
      end
    end
    sat_d  = first_q ? (Pre ? stk_q || fits : sat_now) : sat_q;
    if (load_i) op_d = horiz_n ? OpWait : OpSlopeSet;
  end

  `TRIRAST_FLOP_AR(op_q, op_d, OpDone)

  // Datapath registers: no reset (loaded before use).
  always_ff @(posedge clk_i) begin
    if (load_i) begin
      horiz_q  <= horiz_n;
      mirror_q <= mirror_n;
      dir_q    <= dir_n;
      dhn_q    <= ~abs_low(a_i);
      sh_q     <= abs_low(b_i);
      u_q      <= u_load(e_i, dir_n);
      elo_q    <= e_i[F-1:0];
      j_q      <= '0;
    end else if (!trav_done) begin
      u_q <= u_d;
      j_q <= j_q + 1'b1;
    end
    if (ld_q) xmn_q <= ~xmax_i;
    ld_q    <= load_i;
    {cnt_q, first_q, rh_q, stk_q, sat_q, qs_q, qe_q, rsh_q, ssat_q, gt_q, eq_q} <=
        {cnt_d, first_d, rh_d, stk_d, sat_d, qs_d, qe_d, rsh_d, ssat_d, gt_d, eq_d};
  end

  assign busy_o     = op_q != OpDone;
  assign done_o     = op_q == OpDone;
  assign div_o      = op_q == OpSlope || op_q == OpEntry;
  assign step_o     = busy_o && !trav_done;
  assign horiz_o    = horiz_q;
  assign mirror_o   = mirror_q;
  assign dir_down_o = dir_q;
  assign d_o        = {~dhn_q, {F{1'b0}}};
  assign qs_o       = qs_q;
  assign rs_o       = {rsh_q, {F{1'b0}}};
  assign ssat_o     = ssat_q;
  assign enters_o   = entered && in_box;
  assign j_entry_o  = WB'(j_q);
  // Past the entry a horizontal edge is clear (dir +) or out (dir -); otherwise the entry test.
  assign entry_state_o = (horiz_q || sat_q || gt_q || eq_q) ? (dir_q ? RowClear : RowOut)
                                                            : RowBound;
  // dir +: X' = q, e = r. dir -: X' = Xmax - 1 - q, e = D - 1 - r (q, r of u = -v - 1). The gen2
  // walker's leave offset (X' - Xmax for dir +, -X' - 1 for dir -) is q - Xmax in both.
  logic [XB:0] xsum;   // q + ~Xmax + 1, the carry-in from the low bit
  assign xsum       = {XB'(qe_q), 1'b1} + {{(XB-BB){1'b1}}, xmn_q, 1'b1};
  assign entry_x_o  = xsum[XB:1];
  // The walker's bound - 1 at the entry row: mirrored Xmax - X' - 1, else X': with o = q - Xmax,
  // ~o = Xmax - q - 1 when mirror == dir (mirrored dir +: X' = q; not mirrored dir -:
  // X' = Xmax - 1 - q), else q (mirrored dir -: Xmax - X' - 1 = q; not mirrored dir +: X' = q).
  assign entry_b_o  = (mirror_q == dir_q) ? ~entry_x_o[BB:0] : qe_q[BB:0];
  // The walker's error term f (rtl/improved2/trirast_improved2_edge_walker.sv): e for dir +, D - 1 - e for dir -,
  // which is the division's remainder r in both directions (r's low bits are u's: E's for dir +,
  // ~E's for dir -).
  if (Pre) begin : g_e_conv
    assign entry_e_o = {dir_q ? rh_q : ~r_minus_d[MB-1:0],   // R holds D - 1 - r for dir -
                        dir_q ? elo_q : ~elo_q};
  end else begin : g_e_direct
    assign entry_e_o = {rh_q, dir_q ? elo_q : ~elo_q};
  end

  // Bits no result reads: the complement flag without the pre-iteration, the carry-ins' sum bits.
  logic unused;
  assign unused = ^{cmpl, xsum[0], tsum[0], rdsum[0]};

  // Cover points (docs/coverage.md): every operation state; each boundary step kind (a row step
  // of a column value growing or falling down the box); divisions started (slope or entry x) by
  // their iteration count m, in buckets up to the longest (m = Q); the saturated slope and
  // entry-x divisions (they stop after two cycles); a horizontal edge (no slope division).
  `COVER(LaneOpSlopeSet_C, op_q == OpSlopeSet, clk_i, !rst_ni)
  `COVER(LaneOpSlope_C, op_q == OpSlope, clk_i, !rst_ni)
  `COVER(LaneOpWait_C, op_q == OpWait, clk_i, !rst_ni)
  `COVER(LaneOpEntry_C, op_q == OpEntry, clk_i, !rst_ni)
  `COVER(LaneOpDone_C, op_q == OpDone, clk_i, !rst_ni)
  `COVER(LaneStepDown_C, step_o && dir_q, clk_i, !rst_ni)
  `COVER(LaneStepUp_C, step_o && !dir_q, clk_i, !rst_ni)
  `COVER(DivLen2to4_C, (op_q == OpSlopeSet || set_entry) && m <= IB'(4), clk_i, !rst_ni)
  `COVER(DivLen5to8_C, (op_q == OpSlopeSet || set_entry) && m >= IB'(5) && m <= IB'(8), clk_i,
         !rst_ni)
  `COVER(DivLen9toQm1_C, (op_q == OpSlopeSet || set_entry) && m >= IB'(9) && m < IB'(QB), clk_i,
         !rst_ni)
  `COVER(DivLenQ_C, (op_q == OpSlopeSet || set_entry) && m == IB'(QB), clk_i, !rst_ni)
  `COVER(LaneSlopeSaturated_C, op_q == OpSlope && last && sat_q, clk_i, !rst_ni)
  `COVER(LaneEntryXSaturated_C, op_q == OpEntry && last && sat_q, clk_i, !rst_ni)
  `COVER(LaneHorizontalEdge_C, load_i && horiz_n, clk_i, !rst_ni)

endmodule
