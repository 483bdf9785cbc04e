// gen2 study prototype (not a unit; scripts/gen2_study.sh, docs/gen2-design.md section 2): one
// edge normalizer and one edge lane of the improved unit, redesigned for area and speed. Same
// results as rtl/trirast_edge_normalizer.sv + rtl/trirast_edge_lane.sv in boundary mode `step`
// (the mode is a build choice here: `divide` is not built), in a different number of cycles.
//
// What differs from gen1:
//  - The operation is a registered state; every next-state decision reads registers only (the
//    column value's sign, j <= Ymax, the iteration counter, the registered saturation flag).
//  - Each division has a set-up cycle that aligns the numerator: R = n >> m (one shifter, n
//    muxed between s and the column value), the low numerator bits picked one per iteration by the
//    counter from the registers that hold them (s, or the column value, frozen by then). The iteration is then
//    {R, bit} - D at the divisor's width + 1 (25 bits: D's F zero low bits pass as wires), with no
//    shifter in its path. Saturation (n >> m >= D) is a compare of the registered R (plus the
//    bits shifted out above it) in the first iteration, registered; a saturated division stops
//    after its second cycle (its quotient and remainder are not used by the walker).
//  - The boundary traversal (one add per row) runs at the same time as the slope division
//    (separate adder and registers); the entry-x division starts when both are done.
//  - dir - edges keep u = ~v = -v - 1 (so the traversal always adds s and "entered" is always
//    u >= 0) and divide u instead of -v = u + 1: X' = Xmax - 1 - q and e = D - 1 - r follow
//    from u's q, r without a correction (two adders on the outputs). The entry test
//    q >= Xmax (both directions) is formed bit-serially during the iterations.
//  - D, s and r_s are held without their F constant zero low bits.
// Cycles (m = Qx, or Q with FixedM; T = traversal steps; from the cycle after the load to the
// first cycle with done_o): a horizontal edge T + 1; otherwise max(m + 1, T + 1) + m when it
// enters the box, max(m + 1, T + 1) when it does not (a saturated division stops after 2 of its
// m iterations). gen1: T, T + 2m, T + m.
module g2_lane #(
  parameter int FixedM = 0  // 0: m from m_i (adaptive divider); else m = FixedM (fixed divider)
) (
  input  logic                                    clk_i,
  input  logic                                    rst_ni,
  input  logic [$clog2(trirast_pkg::QuotBits+1)-1:0] m_i,  // iterations of an x division (2..Q),
                                                           // stable from the cycle after load_i
  // ---- load: the edge as the interface gives it ----
  input  logic                                    load_i,
  input  logic signed [trirast_pkg::CoefBits-1:0] a_i,
  input  logic signed [trirast_pkg::CoefBits-1:0] b_i,
  input  logic signed [trirast_pkg::EdgeBits-1:0] el_i,
  input  logic signed [trirast_pkg::EdgeBits-1:0] er_i,
  // ---- the triangle's box (held while the lane works) ----
  input  logic [trirast_pkg::BoxBits-1:0]         xmax_i,
  input  logic [trirast_pkg::BoxBits-1:0]         ymax_i,
  // ---- progress ----
  output logic                                    busy_o,
  output logic                                    done_o,   // results valid (registered state)
  // ---- results (as rtl/trirast_edge_lane.sv) ----
  output logic                                    horiz_o,
  output logic                                    mirror_o,
  output logic                                    dir_down_o,
  output logic [trirast_pkg::StepBits-1:0]        d_o,
  output logic [trirast_pkg::QuotBits-1:0]        qs_o,
  output logic [trirast_pkg::RemBits-1:0]         rs_o,
  output logic                                    ssat_o,
  output logic                                    enters_o,
  output logic [trirast_pkg::RowBits-1:0]         j_entry_o,
  output logic [1:0]                              entry_state_o,
  output logic signed [trirast_pkg::WalkerXBits-1:0] entry_x_o,
  output logic [trirast_pkg::RemBits-1:0]         entry_e_o
);
  localparam int F = trirast_pkg::FracBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int SB = trirast_pkg::StepBits;
  localparam int QB = trirast_pkg::QuotBits;
  localparam int RB = trirast_pkg::RemBits;
  localparam int WB = trirast_pkg::RowBits;
  localparam int XB = trirast_pkg::WalkerXBits;
  localparam int BB = trirast_pkg::BoxBits;
  localparam int MB = SB - F;               // significant bits of D and s (|A|, |B| < 2^p)
  localparam int NB = EB - 1;               // numerator bits (a non-negative column value)
  localparam int IB = $clog2(QB + 1);
  localparam logic [1:0] RowOut = trirast_pkg::RowOut;
  localparam logic [1:0] RowBound = trirast_pkg::RowBound;
  localparam logic [1:0] RowClear = trirast_pkg::RowClear;

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
  logic [MB-1:0] dh_q, sh_q;                 // |A|, |B| (D and s without their F zero bits)
  logic signed [EB-1:0] u_q, u_d;            // column value: v (dir +) or ~v (dir -)
  logic [WB-1:0] j_q;
  logic [IB-1:0] cnt_q, cnt_d;               // bit of the quotient this iteration makes
  logic first_q, first_d;                    // first iteration of a division
  logic [RB-1:0] r_q, r_d;                   // partial remainder (< D when not saturated)
  logic stk_q, stk_d, sat_q, sat_d;          // bits above R at the set-up; saturated
  logic [QB-1:0] qs_q, qs_d, qe_q, qe_d;     // slope and entry quotients (shifted in MSB first)
  logic [MB-1:0] rsh_q, rsh_d;               // r_s without its F zero bits
  logic ssat_q, ssat_d;
  logic gt_q, gt_d, eq_q, eq_d;              // entry quotient vs Xmax, MSB first

  // ---- normalizer (gen1's, folded into the load) ----
  logic [CB-1:0] abs_a, abs_b;
  logic horiz_n, mirror_n, dir_n;
  logic signed [EB-1:0] u_load;
  assign abs_a    = a_i[CB-1] ? CB'(-a_i) : CB'(a_i);
  assign abs_b    = b_i[CB-1] ? CB'(-b_i) : CB'(b_i);
  assign horiz_n  = a_i == '0;
  assign mirror_n = !a_i[CB-1] && !horiz_n;
  assign dir_n    = !b_i[CB-1];
  // dir +: v = T (E_R when mirrored, else E_L); dir -: ~T1 (T1 = E_L when mirrored, else E_R).
  assign u_load   = (dir_n == mirror_n) ? (dir_n ? er_i : ~er_i) : (dir_n ? el_i : ~el_i);

  // ---- traversal: registers only decide ----
  logic entered, in_box, trav_done, need_entry;
  assign entered    = !u_q[EB-1];
  assign in_box     = j_q <= WB'(ymax_i);
  assign trav_done  = entered || !in_box;
  assign need_entry = !horiz_q && entered && in_box;
  assign u_d        = u_q + EB'({sh_q, {F{1'b0}}});

  // ---- divider: set-up (shifter) and iteration ----
  logic [NB-1:0] num, shifted;
  logic [RB-1:0] r_set;
  logic stk_set;
  logic nbit, fits, sat_now, xbit;
  logic [MB:0] x_hi;                         // {R, bit}[RB:F]
  logic [MB+1:0] trial;
  logic [RB-1:0] r_iter;
  assign num     = (op_q == OpSlopeSet) ? NB'({sh_q, {F{1'b0}}}) : NB'(u_q);
  assign shifted = num >> m;
  assign r_set   = shifted[RB-1:0];
  assign stk_set = |shifted[NB-1:RB];
  // The numerator's bit below R: s's (its F low bits are zero) or the column value's, which
  // stays put while the entry division runs (the traversal is over).
  assign nbit    = (op_q == OpSlope) ? ((32'(cnt_q) >= F) ? sh_q[cnt_q - IB'(F)] : 1'b0)
                                     : u_q[cnt_q];
  assign x_hi    = r_q[RB-1:F-1];
  assign trial   = {1'b0, x_hi} - {2'b0, dh_q};
  assign fits    = !trial[MB+1];
  assign r_iter  = {fits ? trial[MB-1:0] : x_hi[MB-1:0], r_q[F-2:0], nbit};
  assign sat_now = stk_q || (r_q[RB-1:F] >= dh_q);
  assign xbit    = (32'(cnt_q) < BB) ? xmax_i[cnt_q] : 1'b0;

  logic last, set_entry;
  always_comb begin
    op_d   = op_q;
    cnt_d  = cnt_q - 1'b1;
    first_d = 1'b0;
    r_d    = r_q;
    stk_d  = stk_q;
    sat_d  = first_q ? sat_now : sat_q;
    qs_d   = qs_q;
    qe_d   = qe_q;
    rsh_d  = rsh_q;
    ssat_d = ssat_q;
    gt_d   = gt_q;
    eq_d   = eq_q;
    last      = (cnt_q == '0) || (!first_q && sat_q);
    set_entry = 1'b0;
    unique case (op_q)
      OpSlopeSet: begin
        r_d = r_set; stk_d = stk_set; cnt_d = m - 1'b1; first_d = 1'b1;
        qs_d = '0;
        op_d = OpSlope;
      end
      OpSlope: begin
        r_d  = r_iter;
        qs_d = {qs_q[QB-2:0], fits};
        if (last) begin
          rsh_d  = r_iter[RB-1:F];
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
        r_d  = r_iter;
        qe_d = {qe_q[QB-2:0], fits};
        // While equal so far: the first differing bit decides (gt is read only once eq is 0).
        if (eq_q) begin
          gt_d = fits;
          eq_d = fits == xbit;
        end
        if (last) op_d = OpDone;
      end
      default: op_d = OpDone;
    endcase
    if (set_entry) begin
      r_d = r_set; stk_d = stk_set; cnt_d = m - 1'b1; first_d = 1'b1;
      qe_d = '0; gt_d = 1'b0; eq_d = 1'b1;
    end
    if (load_i) op_d = horiz_n ? OpWait : OpSlopeSet;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      op_q <= OpDone;
    end else begin
      op_q <= op_d;
    end
  end

  // Datapath registers: no reset (loaded before use).
  always_ff @(posedge clk_i) begin
    if (load_i) begin
      horiz_q  <= horiz_n;
      mirror_q <= mirror_n;
      dir_q    <= dir_n;
      dh_q     <= abs_a[MB-1:0];
      sh_q     <= abs_b[MB-1:0];
      u_q      <= u_load;
      j_q      <= '0;
    end else if (!trav_done) begin
      u_q <= u_d;
      j_q <= j_q + 1'b1;
    end
    cnt_q   <= cnt_d;
    first_q <= first_d;
    r_q     <= r_d;
    stk_q   <= stk_d;
    sat_q   <= sat_d;
    qs_q    <= qs_d;
    qe_q    <= qe_d;
    rsh_q   <= rsh_d;
    ssat_q  <= ssat_d;
    gt_q    <= gt_d;
    eq_q    <= eq_d;
  end

  assign busy_o     = op_q != OpDone;
  assign done_o     = op_q == OpDone;
  assign horiz_o    = horiz_q;
  assign mirror_o   = mirror_q;
  assign dir_down_o = dir_q;
  assign d_o        = {dh_q, {F{1'b0}}};
  assign qs_o       = qs_q;
  assign rs_o       = {rsh_q, {F{1'b0}}};
  assign ssat_o     = ssat_q;
  assign enters_o   = entered && in_box;
  assign j_entry_o  = j_q;
  // Past the entry a horizontal edge is clear (dir +) or out (dir -); otherwise the entry test.
  assign entry_state_o = (horiz_q || sat_q || gt_q || eq_q) ? (dir_q ? RowClear : RowOut)
                                                            : RowBound;
  // dir +: X' = q, e = r. dir -: X' = Xmax - 1 - q, e = D - 1 - r (q, r of u = -v - 1).
  // (Written as one adder with muxed operands, so the muxes fold into its bit cells.)
  assign entry_x_o  = (dir_q ? XB'(0) : XB'(xmax_i)) + (dir_q ? XB'(qe_q) : ~(XB'(qe_q)));
  assign entry_e_o  = {(dir_q ? MB'(0) : dh_q) + (dir_q ? r_q[RB-1:F] : ~r_q[RB-1:F]),
                       dir_q ? r_q[F-1:0] : ~r_q[F-1:0]};

endmodule
