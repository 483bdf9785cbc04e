// gen2 study prototype (not a unit; scripts/gen2_study.sh): one edge walker, N = 1, retimed.
// The same row sequence as rtl/trirast_edge_walker.sv (docs/unit.md, section 4), but every test of
// a step is computed beside its add instead of after it:
//  - carry-select Bresenham step: both X' + inc and X' + inc + 1 (dir +; dir -: - q_s, - q_s - 1)
//    and both e + de_a and e + de_b (dir +: r_s and r_s - D; dir -: -r_s and D - r_s), the sign of
//    one sum selecting the pair;
//  - the leave test (dir +: X' >= Xmax, dir -: X' < 0) as X' >= threshold against two thresholds
//    prepared at the load (Xmax - inc, ...), in parallel with the adds;
//  - the entry row from a down counter with a registered "next row enters" flag, not a compare of
//    the walk stage's row counter;
//  - the restored span bound (mirrored: Xmax - X', else X' + 1) kept in its own register, stepped
//    with the same select, so the span generator starts from registers.
// The load-time preparation (a few subtractions) sits on the hand-off path, which a gen2 unit
// registers (hand-off buffer).
// CarrySelect 0 (the iCE40 fit, docs/gen2-design.md "Fitting the HX8K"; the same rows): X' and the
// bound are not formed twice; each is one adder whose carry-in is the select (X' + inc or
// X' + inc +- 1 as X' + inc_m + t, inc_m = q_s or ~q_s prepared at the load, t = selb or !selb),
// so it follows the e sum's sign instead of running beside it; and the entry row takes X', e and
// the bound from the running registers, which hold the values loaded with the job until then (no
// copies ex, ee, bex).
module trirast_edge_walker2 #(
  parameter bit CarrySelect = 1'b1
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 load_i,
  input  logic                                 mirror_i,
  input  logic                                 dir_down_i,
  input  logic [trirast_pkg::StepBits-1:0]     d_i,
  input  logic [trirast_pkg::QuotBits-1:0]     qs_i,
  input  logic [trirast_pkg::RemBits-1:0]      rs_i,
  input  logic                                 ssat_i,
  input  logic                                 enters_i,
  input  logic [trirast_pkg::RowBits-1:0]      j_entry_i,
  input  logic [1:0]                           entry_state_i,
  input  logic signed [trirast_pkg::WalkerXBits-1:0] entry_x_i,
  input  logic [trirast_pkg::RemBits-1:0]      entry_e_i,
  input  logic [trirast_pkg::BoxBits-1:0]      xmax_i,
  input  logic                                 adv_i,
  output logic                                 mirror_o,
  output logic [1:0]                           row_state_o,
  output logic [trirast_pkg::BoxBits:0]        row_bound_o   // the restored bound (when bound)
);
  localparam int RB = trirast_pkg::RemBits;
  localparam int WB = trirast_pkg::RowBits;
  localparam int XB = trirast_pkg::WalkerXBits;
  localparam int BB = trirast_pkg::BoxBits;
  localparam logic [1:0] RowOut = trirast_pkg::RowOut;
  localparam logic [1:0] RowBound = trirast_pkg::RowBound;
  localparam logic [1:0] RowClear = trirast_pkg::RowClear;

  logic mirror_q, dir_q, ssat_q, enters_q, ent_q, ent_d;
  logic [WB-1:0] cnt_q, cnt_d;
  logic [1:0] est_q, st_q, st_d;
  logic signed [XB-1:0] ex_q, inca_q, incb_q, tha_q, thb_q, x_q, x_d;
  logic signed [XB-1:0] bx_q, bx_d, binca_q, bincb_q, bex_q;   // bound register and its steps
  logic signed [RB+1:0] dea_q, deb_q, e_q, e_d;                // e in RB + 2 signed bits
  logic [RB-1:0] ee_q;

  // ---- the step: all in parallel ----
  logic signed [RB+1:0] ea, eb;
  logic signed [XB-1:0] xs, bs;
  logic ga, gb, selb, leave;
  assign ea = e_q + dea_q;
  assign eb = e_q + deb_q;
  assign ga = x_q >= tha_q;          // the leave test of xa (dir -: negated)
  assign gb = x_q >= thb_q;
  assign selb = dir_q ? !eb[RB+1] : ea[RB+1];
  assign leave = ssat_q || (dir_q ? (selb ? gb : ga) : !(selb ? gb : ga));
  if (CarrySelect) begin : g_cs
    logic signed [XB-1:0] xa, xb, ba, bb;
    assign xa = x_q + inca_q;
    assign xb = x_q + incb_q;
    assign ba = bx_q + binca_q;
    assign bb = bx_q + bincb_q;
    assign xs = selb ? xb : xa;
    assign bs = selb ? bb : ba;
  end else begin : g_ci
    // inca_q / binca_q hold inc_m; incb_q / bincb_q are unused (the carry-in below).
    logic [XB:0] xsum, bsum;
    logic tx, tbx;
    assign tx   = dir_q ? selb : !selb;
    assign tbx  = (dir_q ^ mirror_q) ? selb : !selb;
    assign xsum = {x_q, 1'b1} + {inca_q, tx};
    assign bsum = {bx_q, 1'b1} + {binca_q, tbx};
    assign xs = $signed(xsum[XB:1]);
    assign bs = $signed(bsum[XB:1]);
    logic unused_ci;
    assign unused_ci = ^{incb_q, bincb_q, xsum[0], bsum[0]};
  end

  always_comb begin
    st_d = st_q;  x_d = x_q;  e_d = e_q;  bx_d = bx_q;
    cnt_d = cnt_q;  ent_d = ent_q;
    if (load_i) begin
      cnt_d = j_entry_i - 1'b1;
      ent_d = enters_i && (j_entry_i == WB'(1));
      x_d   = entry_x_i;
      e_d   = $signed({2'b00, entry_e_i});
      bx_d  = mirror_i ? $signed(XB'(xmax_i)) - entry_x_i : entry_x_i + 1'b1;
      st_d  = (enters_i && j_entry_i == '0) ? entry_state_i : (dir_down_i ? RowOut : RowClear);
    end else if (adv_i) begin
      cnt_d = cnt_q - 1'b1;
      ent_d = enters_q && (cnt_q == WB'(1));
      if (ent_q) begin
        // CarrySelect 0: X', e and the bound still hold the entry values loaded with the job
        // (before its entry row an edge is out or clear, and only a bound row steps them).
        st_d = est_q;
        if (CarrySelect) begin
          x_d = ex_q;  e_d = $signed({2'b00, ee_q});  bx_d = bex_q;
        end
      end else if (st_q == RowBound) begin
        x_d  = xs;
        e_d  = selb ? eb : ea;
        bx_d = bs;
        st_d = leave ? (dir_q ? RowClear : RowOut) : RowBound;
      end
    end
  end

  // ---- load-time preparation ----
  logic signed [XB-1:0] qse, inca, incb, xm;
  logic signed [RB+1:0] rse, de;
  assign qse  = $signed(XB'(qs_i));
  assign xm   = $signed(XB'(xmax_i));
  assign rse  = $signed({2'b00, rs_i});
  assign de   = $signed({2'b00, d_i});
  assign inca = dir_down_i ? qse : -qse;
  assign incb = dir_down_i ? qse + 1'b1 : -qse - 1'b1;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      st_q <= RowOut;
    end else begin
      st_q <= st_d;
    end
  end
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
        ee_q     <= entry_e_i;
        bex_q    <= mirror_i ? xm - entry_x_i : entry_x_i + 1'b1;
      end
      if (CarrySelect) begin
        inca_q   <= inca;
        incb_q   <= incb;
        binca_q  <= mirror_i ? -inca : inca;
        bincb_q  <= mirror_i ? -incb : incb;
      end else begin
        // inc_m: X' + inca = X' + inc_m + !dir, X' + incb = X' + inc_m + dir (the same for the
        // bound with dir ^ mirror); incb_q, bincb_q are left unused.
        inca_q   <= dir_down_i ? qse : ~qse;
        binca_q  <= (dir_down_i ^ mirror_i) ? qse : ~qse;
      end
      dea_q    <= dir_down_i ? rse : -rse;
      deb_q    <= dir_down_i ? rse - de : de - rse;
      // dir +: leave when x + inc >= Xmax, i.e. x >= Xmax - inc; dir -: stay when x + inc >= 0.
      if (CarrySelect) begin
        tha_q    <= dir_down_i ? xm - inca : -inca;
        thb_q    <= dir_down_i ? xm - incb : -incb;
      end else begin
        tha_q    <= dir_down_i ? xm - qse : qse;
        thb_q    <= dir_down_i ? xm + ~qse : qse + 1'b1;
      end
    end
  end

  assign mirror_o    = mirror_q;
  assign row_state_o = st_q;
  assign row_bound_o = bx_q[BB:0];

endmodule
