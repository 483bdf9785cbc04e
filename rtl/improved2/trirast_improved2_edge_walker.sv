// The second-generation improved unit's edge walker (rtl/improved2/trirast_improved2.f), retimed.
// The same row sequence as rtl/improved/trirast_improved_edge_walker.sv (docs/unit.md, section 4), but every test of
// a step is computed beside its add instead of after it:
//  - carry-select Bresenham step: both X' + inc and X' + inc + 1 (dir +; dir -: - q_s, - q_s - 1)
//    and both e + de_a and e + de_b, the sign of one sum selecting the pair;
//  - one step for both directions: the walker keeps the error term as f = e (dir +) or
//    D - 1 - e (dir -), the entry division's remainder r as the lane leaves it, so a row adds r_s
//    and r_s - D (dir -: e - r_s < 0 exactly when f + r_s - D >= 0, and the two new e are f's two
//    sums mirrored), with no negation or select of the steps at the load;
//  - the leave test (dir +: X' >= Xmax, dir -: X' < 0) as the sign of the stepped X' itself: the
//    walker keeps X' as its leave offset o = X' - Xmax (dir +) or -X' - 1 (dir -), q - Xmax in
//    both directions for the lane's entry quotient q (the lane hands off o, entry_x_i), which
//    every row steps by + q_s (+ 1), so the row leaves exactly when the stepped o is >= 0: no
//    thresholds, no compares (the span generator reads the bound register below, so X' itself is
//    read nowhere else);
//  - the entry row from a down counter with a registered "next row enters" flag, not a compare of
//    the walk stage's row counter;
//  - the restored span bound minus one (mirrored: Xmax - X' - 1, else X') kept in its own
//    register, stepped with the same select, so the span generator starts from registers; the
//    lane hands off its entry value (entry_b_i), and the walk stage adds the one back with a
//    carry-in.
// The load-time preparation (a few subtractions) sits on the hand-off path, which a gen2 unit
// registers (hand-off buffer).
// CarrySelect 0 (the iCE40 fit, docs/improved2.md "Build choices"; the same rows): X' and the
// bound are not formed twice; each is one adder whose carry-in is the select (X' + inc or
// X' + inc +- 1 as X' + inc_m + t, inc_m = q_s or ~q_s prepared at the load, t = selb or !selb),
// so it follows the e sum's sign instead of running beside it; and the entry row takes X', e and
// the bound from the running registers, which hold the values loaded with the job until then (no
// copies ex, ee, bex).
// f without its F low bits: the lane hands off D and r_s with F zero low bits (D = |A| * 2^F, r_s
// the remainder of |B| * 2^F), so f's low bits are those of the entry f for ever and never carry
// into the sum whose sign decides a step (f + de >= 0 exactly when (f >> F) + (de >> F) >= 0):
// the walker keeps f >> F only (asserted at the load), in RB - F + 1 signed bits: f lies in
// [0, D), the sum whose sign is read (f + r_s - D) in (-D, D), and the other sum (f + r_s), which
// may overflow, is taken only when it lies in [0, D).
// NumEndpoints N > 1 (the walk stage's N rows per cycle, docs/timing.md): the step
// above is built N times in a chain, row r + 1 one step after row r (row 0: the registers), as
// rtl/improved/trirast_improved_edge_walker.sv's chain; the walker presents rows j .. j + N - 1 and advances by the
// runtime group size adv_rows_i (1..N; N = 1: one row, adv_rows_i unused).
`include "trirast_assert.svh"
`include "trirast_ports.svh"

module trirast_improved2_edge_walker #(
  parameter bit CarrySelect = 1'b1,
  parameter int NumEndpoints = 1   // rows presented per cycle (hardware)
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 load_i,
  `TRIRAST_IMPROVED_EDGE_RESULT(input, _i),  // entry_x_i: the leave offset o (below)
  input  logic [trirast_pkg::RemBits-1:0]      entry_e_i,   // f: e (dir +), D - 1 - e (dir -)
  input  logic [trirast_pkg::BoxBits:0]        entry_b_i,   // the entry row's bound - 1
  input  logic                                 adv_i,
  input  logic [2:0]                           adv_rows_i,   // rows per group (1..N)
  output logic                                 mirror_o,
  output logic [2*NumEndpoints-1:0]            row_state_o,  // row j + r: state
  output logic [NumEndpoints*(trirast_pkg::BoxBits+1)-1:0] row_bound_o  // row j + r: the
                                                                         // restored bound - 1
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  localparam int EW = RB - F + 1;   // f >> F, signed (see the header)

  logic mirror_q, dir_q, ssat_q, enters_q, ent_q, ent_d;
  logic [WB-1:0] cnt_q, cnt_d;
  logic [1:0] est_q, st_q, st_d;
  // x_q: the leave offset o (X' - Xmax for dir +, -X' - 1 for dir -; see the header). X' is in
  // [0, Xmax) on a bound row, so o is in [-Xmax, 0), and a step adds at most q_s + 1 <= 2^Q: the
  // stepped o lies in [-2^BB, 2^Q], which XB = Q + 2 signed bits hold.
  // The lane hands off the entry row's o, qe - Xmax in both directions (qe the entry quotient).
  logic signed [XB-1:0] ex_q, inca_q, incb_q, x_q, x_d;
  // The bound - 1 register and its steps, BB + 1 bits: the bound lies in [1, Xmax] on a bound row
  // (a leaving row's, outside, is not read), and its low bits do not depend on the ones above.
  logic [BB:0] bx_q, bx_d, binca_q, bincb_q, bex_q, bx_load;
  logic signed [EW-1:0] dea_q, deb_q, e_q, e_d;                // r_s >> F, (r_s - D) >> F, f >> F
  logic [EW-2:0] ee_q;

  // ---- the step: all in parallel; row r + 1 from row r (row 0: the registers) ----
  // CarrySelect 0: X' + inc + t and the bound + inc_m + t as one adder each, the carry-in t
  // from the low bit of {.., 1} + {.., t}.
  function automatic logic signed [XB-1:0] step_ci(input logic signed [XB-1:0] x,
      input logic signed [XB-1:0] inc, input logic t);
    /* verilator lint_off UNUSEDSIGNAL */
    logic [XB:0] sum;
    /* verilator lint_on UNUSEDSIGNAL */
    sum = {x, 1'b1} + {inc, t};
    step_ci = $signed(sum[XB:1]);
  endfunction
  function automatic logic [BB:0] bound_ci(input logic [BB:0] b, input logic [BB:0] inc,
                                           input logic t);
    /* verilator lint_off UNUSEDSIGNAL */
    logic [BB+1:0] sum;
    /* verilator lint_on UNUSEDSIGNAL */
    sum = {b, 1'b1} + {inc, t};
    bound_ci = sum[BB+1:1];
  endfunction
  logic [1:0] st_r [0:NumEndpoints] /* verilator split_var */;
  logic signed [XB-1:0] x_r [0:NumEndpoints] /* verilator split_var */;
  logic [BB:0] bx_r [0:NumEndpoints] /* verilator split_var */;
  logic signed [EW-1:0] e_r [0:NumEndpoints] /* verilator split_var */;
  logic [WB-1:0] cnt_r [0:NumEndpoints] /* verilator split_var */;
  logic ent_r [0:NumEndpoints] /* verilator split_var */;
  assign st_r[0]  = st_q;
  assign x_r[0]   = x_q;
  assign bx_r[0]  = bx_q;
  assign e_r[0]   = e_q;
  assign cnt_r[0] = cnt_q;
  assign ent_r[0] = ent_q;

  for (genvar r = 0; r < NumEndpoints; r++) begin : g_row
    // The step of a bound row, formed in that branch only ('x otherwise, where nothing reads it),
    // so that a Verilated model skips it for rows that do not step.
    logic [1:0] st_n;
    logic signed [XB-1:0] x_n;
    logic [BB:0] bx_n;
    logic signed [EW-1:0] e_n;
    logic signed [EW-1:0] ea, eb;
    logic signed [XB-1:0] xs;
    logic [BB:0] bs;
    logic selb, leave;
    if (!CarrySelect) begin : g_ci
      // inca_q = q_s, binca_q the bound's inc_m; incb_q / bincb_q are unused (the carry-in below).
      logic unused_ci;
      assign unused_ci = ^{incb_q, bincb_q};
    end
    always_comb begin
      st_n = st_r[r];  x_n = x_r[r];  e_n = e_r[r];  bx_n = bx_r[r];
      {ea, eb, xs, bs, selb, leave} = 'x;
      if (ent_r[r]) begin
        // CarrySelect 0: X', e and the bound still hold the entry values loaded with the job
        // (before its entry row an edge is out or clear, and only a bound row steps them).
        st_n = est_q;
        if (CarrySelect) begin
          x_n = ex_q;  e_n = $signed({1'b0, ee_q});  bx_n = bex_q;
        end
      end else if (st_r[r] == RowBound) begin
        ea = e_r[r] + dea_q;
        eb = e_r[r] + deb_q;
        selb = !eb[EW-1];
        if (CarrySelect) begin
          xs = selb ? x_r[r] + incb_q : x_r[r] + inca_q;
          bs = selb ? bx_r[r] + bincb_q : bx_r[r] + binca_q;
        end else begin
          xs = step_ci(x_r[r], inca_q, selb);
          bs = bound_ci(bx_r[r], binca_q, (dir_q ^ mirror_q) ? selb : !selb);
        end
        leave = ssat_q || !xs[XB-1];   // the stepped offset is >= 0
        x_n  = xs;
        e_n  = selb ? eb : ea;
        bx_n = bs;
        st_n = leave ? (dir_q ? RowClear : RowOut) : RowBound;
      end
    end
    assign st_r[r+1]  = st_n;
    assign x_r[r+1]   = x_n;
    assign bx_r[r+1]  = bx_n;
    assign e_r[r+1]   = e_n;
    assign cnt_r[r+1] = cnt_r[r] - 1'b1;
    assign ent_r[r+1] = enters_q && (cnt_r[r] == WB'(1));
  end
  // Rows 1 .. N again, read by the advance's select (the chain above is indexed statically only,
  // so Verilator splits it).
  logic [1:0] st_c [1:NumEndpoints];
  logic signed [XB-1:0] x_c [1:NumEndpoints];
  logic [BB:0] bx_c [1:NumEndpoints];
  logic signed [EW-1:0] e_c [1:NumEndpoints];
  logic [WB-1:0] cnt_c [1:NumEndpoints];
  logic ent_c [1:NumEndpoints];
  for (genvar r = 1; r <= NumEndpoints; r++) begin : g_copy
    assign st_c[r]  = st_r[r];
    assign x_c[r]   = x_r[r];
    assign bx_c[r]  = bx_r[r];
    assign e_c[r]   = e_r[r];
    assign cnt_c[r] = cnt_r[r];
    assign ent_c[r] = ent_r[r];
  end

  always_comb begin
    st_d = st_q;  x_d = x_q;  e_d = e_q;  bx_d = bx_q;
    cnt_d = cnt_q;  ent_d = ent_q;
    if (load_i) begin
      cnt_d = j_entry_i - 1'b1;
      ent_d = enters_i && (j_entry_i == WB'(1));
      x_d   = entry_x_i;
      e_d   = $signed({1'b0, entry_e_i[RB-1:F]});
      bx_d  = bx_load;
      st_d  = (enters_i && j_entry_i == '0) ? entry_state_i : (dir_down_i ? RowOut : RowClear);
    end else if (adv_i) begin
      // Advance by the group: row j + adv_rows (N = 1: row j + 1).
      for (int r = 1; r <= NumEndpoints; r++) begin
        if (NumEndpoints == 1 || 32'(adv_rows_i) == r) begin
          st_d = st_c[r];  x_d = x_c[r];  e_d = e_c[r];  bx_d = bx_c[r];
          cnt_d = cnt_c[r];  ent_d = ent_c[r];
        end
      end
    end
  end

  // ---- load-time preparation ----
  logic signed [XB-1:0] qse, inca, incb;
  logic signed [EW-1:0] rse, de;
  assign qse  = $signed(XB'(qs_i));
  assign rse  = $signed({1'b0, rs_i[RB-1:F]});
  assign de   = $signed({1'b0, d_i[trirast_pkg::StepBits-1:F]});
  assign inca = dir_down_i ? qse : -qse;                      // X' steps (the bound's)
  assign incb = dir_down_i ? qse + 1'b1 : -qse - 1'b1;
  assign bx_load = entry_b_i;   // the lane's (trirast_improved2_edge_lane's entry_b_o)

  `TRIRAST_FLOP_AR(st_q, st_d, RowOut)
  always_ff @(posedge clk_i) begin
    x_q <= x_d;  e_q <= e_d;  bx_q <= bx_d;  cnt_q <= cnt_d;  ent_q <= ent_d;
    if (load_i) begin
      mirror_q <= mirror_i;
      dir_q    <= dir_down_i;
      ssat_q   <= ssat_i;
      enters_q <= enters_i;
      est_q    <= entry_state_i;
      if (CarrySelect) begin   // the entry row's copies (CarrySelect 0: x_q, e_q, bx_q hold them)
        ex_q     <= entry_x_i;
        ee_q     <= entry_e_i[RB-1:F];
        bex_q    <= bx_load;
      end
      inca_q   <= qse;   // the offset's steps: q_s, q_s + 1 in both directions
      if (CarrySelect) begin
        incb_q   <= qse + 1'b1;
        binca_q  <= (BB+1)'(mirror_i ? -inca : inca);
        bincb_q  <= (BB+1)'(mirror_i ? -incb : incb);
      end else begin
        // inc_m: X' + inca = X' + inc_m + !dir, X' + incb = X' + inc_m + dir for the bound with
        // dir ^ mirror; incb_q, bincb_q are left unused.
        binca_q  <= (BB+1)'((dir_down_i ^ mirror_i) ? qse : ~qse);
      end
      dea_q    <= rse;
      deb_q    <= rse - de;
    end
  end

  assign mirror_o = mirror_q;
  for (genvar r = 0; r < NumEndpoints; r++) begin : g_out
    assign row_state_o[2*r +: 2]       = st_r[r];
    assign row_bound_o[r*(BB+1) +: BB+1] = bx_r[r];
  end
  logic unused_rows;
  assign unused_rows = ^{adv_rows_i,       // N = 1: one row per advance
                         entry_e_i[F-1:0], rs_i[F-1:0], d_i[F-1:0]};   // f's low bits

  // D and r_s have F zero low bits (the lane's), so f's stay the entry f's (see the header).
  `ASSERT_IMPLIES(StepLowBitsZero_A, load_i, rs_i[F-1:0] == '0 && d_i[F-1:0] == '0, clk_i, !rst_ni)

endmodule
