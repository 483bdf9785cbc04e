// One edge lane of the setup stage (docs/timing.md, "Lane cycles"): a small FSM in front of its
// own adder divider. After a load it runs, in this order and only when the edge needs them, the
// slope division s / D, the boundary traversal (boundary mode `step`: one column step per cycle;
// `divide`: one entry-row division) and the entry-x division (docs/unit.md, sections 3 and 4).
// The next operation is chosen combinationally, so there is no cycle between operations:
// the lane works for L_k = boundary_steps_k + Q * divisions_k cycles.
// Its result registers are what the walk stage loads at the hand-off.
`include "trirast_ports.svh"

`include "trirast_assert.svh"
module trirast_improved_edge_lane (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 divide_i,      // boundary mode: 1 divide, 0 step
  input  logic [$clog2(trirast_pkg::QuotBits+1)-1:0] qx_i,   // iterations of an x division
  input  logic [$clog2(trirast_pkg::QuotBits+1)-1:0] qy_i,   // iterations of a y division
  // ---- load (setup StEdge): one normalized edge (docs/unit.md, section 2) ----
  input  logic                                 load_i,        // take the edge below
  input  logic                                 horiz_i,       // a == 0: no x bound
  input  logic                                 mirror_i,      // a > 0: a left edge
  input  logic                                 dir_down_i,    // b >= 0: X' grows down the box
  input  logic signed [trirast_pkg::EdgeBits-1:0] t_i,        // f at column 0, row 0
  input  logic signed [trirast_pkg::EdgeBits-1:0] t1_i,       // f at column Xmax, row 0
  input  logic [trirast_pkg::StepBits-1:0]     d_i,           // |a|
  input  logic [trirast_pkg::StepBits-1:0]     s_i,           // |b|
  // ---- the triangle's box (held by the interface while the lane works) ----
  input  logic [trirast_pkg::BoxBits-1:0]      xmax_i,
  input  logic [trirast_pkg::BoxBits-1:0]      ymax_i,
  // ---- progress ----
  output logic                                 busy_o,        // does a unit of work this cycle
  output logic                                 done_next_o,   // has no work from next cycle on
  output logic                                 div_o,         // ... and it is a divider iteration
  // ---- results: the walker's start registers (docs/unit.md, section 4) ----
  output logic                                 horiz_o,
  `TRIRAST_IMPROVED_EDGE_RESULT(output, _o),
  output logic [trirast_pkg::RemBits-1:0]      entry_e_o      // e at j_entry (when bound)
);
  `TRIRAST_PKG_NAMES
  localparam logic [RowBits-1:0] NeverRow = '1;  // "never enters" (> any Ymax)

  // The lane's operations, in the order it runs them.
  // (Constants rather than an enum: Icarus 11 wants casts for enums in conditional operators.)
  localparam logic [1:0] PhSlope = 2'd0;  // slope division s / D
  localparam logic [1:0] PhTrav  = 2'd1;  // boundary traversal (column steps or entry-row division)
  localparam logic [1:0] PhEntry = 2'd2;  // entry-x division at the entry row
  localparam logic [1:0] PhDone  = 2'd3;

  logic [1:0] phase_q, phase_d;
  // The edge's constants, taken at the load.
  logic horiz_q, horiz_d, mirror_q, mirror_d, dir_q, dir_d;
  logic [StepBits-1:0] d_q, d_d, s_q, s_d;
  // Boundary traversal: the edge value on the box's side column at row j.
  logic signed [EdgeBits-1:0] v_q, v_d;
  logic [RowBits-1:0] j_q, j_d;
  // Results.
  logic [QuotBits-1:0] qs_q, qs_d;
  logic [RemBits-1:0] rs_q, rs_d;
  logic ssat_q, ssat_d;
  logic [1:0] est_q, est_d;
  logic signed [WalkerXBits-1:0] ex_q, ex_d;
  logic [RemBits-1:0] ee_q, ee_d;

  // The divider.
  logic div_en /* verilator public_flat_rd */;  // counted by the harness: divider busy cycles
  logic div_busy, div_last, div_sat;
  logic [NumerBits-1:0] div_n;
  logic [StepBits-1:0] div_d;
  logic [QuotBits-1:0] div_quot;  // the divider's quotient
  logic [$clog2(QuotBits+1)-1:0] div_bits;
  logic [RemBits-1:0] div_r;

  trirast_improved_adder_divider u_divider (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .en_i      (div_en),
    .numer_i   (div_n),
    .divisor_i (div_d),
    .bits_i    (div_bits),
    .busy_o    (div_busy),
    .last_o    (div_last),
    .quot_o    (div_quot),
    .rem_o     (div_r),
    .sat_o     (div_sat)
  );

  // The edge has entered at row j when its side-column value changed sign:
  // dir +: f >= 0 on column 0; dir -: f < 0 on column Xmax. The operation the lane works on
  // skips the ones the edge does not need. (Plain signals, no functions: Icarus 11 loops on
  // functions with locals called from several always_comb blocks.)
  // Combinational: _now from this cycle's registers (_q), _next from the next state (_d).
  logic entered_now, entered_next;
  logic [1:0] skip1_now, skip2_now, skip3_now, skip1_next, skip2_next, skip3_next;

  logic in_box_now, in_box_next;          // j <= Ymax
  logic need_trav_now, need_trav_next;    // the traversal has work at (v, j)
  logic need_entry_now, need_entry_next;  // the entry-x division is needed at (v, j)
  logic [1:0] cur;                       // this cycle's operation
  logic div_busy_next;
  // Divide-mode traversal results.
  logic [RowBits-1:0] jdiv;
  logic signed [EdgeBits-1:0] vdiv;
  // Entry-x results.
  logic carry;
  logic signed [WalkerXBits-1:0] xneg;

  // This cycle's operation and the divider's operands: from the registers only.
  always_comb begin
    // Needs at the registered (v, j).
    in_box_now     = j_q <= RowBits'(ymax_i);
    entered_now    = dir_q ? !v_q[EdgeBits-1] : v_q[EdgeBits-1];
    need_trav_now  = !entered_now && (divide_i ? (s_q != '0) : in_box_now);
    need_entry_now = !horiz_q && entered_now && in_box_now;
    skip1_now      = (phase_q == PhSlope && horiz_q) ? PhTrav : phase_q;
    skip2_now      = (skip1_now == PhTrav && !need_trav_now) ? PhEntry : skip1_now;
    skip3_now      = (skip2_now == PhEntry && !need_entry_now) ? PhDone : skip2_now;
    cur            = div_busy ? phase_q : skip3_now;
    // The divider's operands (single assignments; see below for why):
    // slope s / D -> q_s, r_s (X' moves q_s per row plus a carry from r_s), along x;
    // entry row (divide mode): dir + divides -T by s (first j with T + j*s >= 0), dir - divides
    // T1 by s (first j with T1 - j*s < 0), along y;
    // entry x: dir + divides N = v by D; dir - divides -G = -v (and restores the sign), along x.
    div_en   = (cur == PhSlope) || (cur == PhEntry) || (cur == PhTrav && divide_i);
    div_n    = (cur == PhSlope) ? NumerBits'(s_q)
             : ((cur == PhTrav) == dir_q) ? NumerBits'(-v_q) : NumerBits'(v_q);
    div_d    = (cur == PhTrav) ? s_q : d_q;
    div_bits = (cur == PhTrav) ? qy_i : qx_i;
  end

  // Next state: the results of this cycle's work.
  always_comb begin
    {phase_d, horiz_d, mirror_d, dir_d, d_d, s_d, v_d, j_d, qs_d, rs_d, ssat_d, est_d, ex_d, ee_d} =
        {phase_q, horiz_q, mirror_q, dir_q, d_q, s_q, v_q, j_q, qs_q, rs_q, ssat_q, est_q, ex_q,
         ee_q};

    unique case (cur)
      PhSlope: begin
        phase_d = PhSlope;
        if (div_last) begin
          qs_d    = div_quot;
          rs_d    = div_r;
          ssat_d  = div_sat;
          phase_d = PhTrav;
        end
      end
      PhTrav: begin
        phase_d = PhTrav;
        if (!divide_i) begin
          // step: one row down the side column: dir + adds s, dir - subtracts it.
          v_d = dir_q ? v_q + EdgeBits'(s_q) : v_q - EdgeBits'(s_q);
          j_d = j_q + 1'b1;
        end else begin
          // divide: the entry row j and the value at it (jdiv, vdiv below).
          if (div_last) begin
            v_d     = vdiv;
            j_d     = div_sat ? NeverRow : jdiv;  // saturated: never enters
            phase_d = PhEntry;
          end
        end
      end
      PhEntry: begin
        phase_d = PhEntry;
        if (div_last) begin
          phase_d = PhDone;
          if (dir_q) begin
            ex_d  = WalkerXBits'(div_quot);
            ee_d  = div_r;
            est_d = (div_sat || div_quot >= QuotBits'(xmax_i)) ? RowClear : RowBound;
          end else begin
            ex_d  = xneg;
            ee_d  = carry ? d_q - div_r : '0;
            est_d = (div_sat || xneg[WalkerXBits-1]) ? RowOut : RowBound;
          end
        end
      end
      default: phase_d = PhDone;
    endcase

    // A new edge (setup StEdge): the traversal starts on column 0 (dir +) or Xmax (dir -).
    if (load_i) begin
      phase_d  = PhSlope;
      horiz_d  = horiz_i;
      mirror_d = mirror_i;
      dir_d    = dir_down_i;
      d_d      = d_i;
      s_d      = s_i;
      v_d      = dir_down_i ? t_i : t1_i;
      j_d      = '0;
    end

  end

  // Divider results turned into traversal and entry values (each assigned once).
  always_comb begin
    // Entry row: dir + j = q + (r != 0), value s - r (0 when r = 0); dir - j = q + 1, value r - s.
    jdiv  = dir_q ? RowBits'(div_quot) + RowBits'(div_r != '0) : RowBits'(div_quot) + 1'b1;
    vdiv  = dir_q ? ((div_r == '0) ? '0 : EdgeBits'(s_q) - EdgeBits'(div_r))
                  : EdgeBits'(div_r) - EdgeBits'(s_q);
    // Entry x, dir -: X'' = -q - (r != 0), X' = Xmax + X''.
    carry = div_r != '0;
    xneg  = WalkerXBits'(xmax_i) - WalkerXBits'(div_quot) - WalkerXBits'(carry);
  end

  // Look ahead: will the lane still have work next cycle?
  always_comb begin
    div_busy_next    = div_en ? !div_last : div_busy;
    in_box_next      = j_d <= RowBits'(ymax_i);
    entered_next     = dir_d ? !v_d[EdgeBits-1] : v_d[EdgeBits-1];
    need_trav_next   = !entered_next && (divide_i ? (s_d != '0) : in_box_next);
    need_entry_next  = !horiz_d && entered_next && in_box_next;
    skip1_next       = (phase_d == PhSlope && horiz_d) ? PhTrav : phase_d;
    skip2_next       = (skip1_next == PhTrav && !need_trav_next) ? PhEntry : skip1_next;
    skip3_next       = (skip2_next == PhEntry && !need_entry_next) ? PhDone : skip2_next;
  end
  // Outputs as continuous assignments, not always_comb writes (Icarus 11 re-runs blocks whose
  // output ports share a vector with other instances' ports).
  assign done_next_o = (div_busy_next ? phase_d : skip3_next) == PhDone;
  assign busy_o      = cur != PhDone;
  assign div_o       = div_en;

  `TRIRAST_FLOP_AR(phase_q, phase_d, PhDone)

  // Datapath registers: no reset (loaded before use).
  always_ff @(posedge clk_i) begin
    {horiz_q, mirror_q, dir_q, d_q, s_q, v_q, j_q, qs_q, rs_q, ssat_q, est_q, ex_q, ee_q} <=
        {horiz_d, mirror_d, dir_d, d_d, s_d, v_d, j_d, qs_d, rs_d, ssat_d, est_d, ex_d, ee_d};
  end

  assign {horiz_o, mirror_o, dir_down_o, d_o, qs_o, rs_o, ssat_o} =
      {horiz_q, mirror_q, dir_q, d_q, qs_q, rs_q, ssat_q};
  assign enters_o   = entered_now && in_box_now;
  assign j_entry_o  = j_q;
  // A horizontal edge has no bound: past its entry it is clear (dir +) or out (dir -).
  assign entry_state_o = horiz_q ? (dir_q ? RowClear : RowOut) : est_q;
  assign entry_x_o  = ex_q;
  assign entry_e_o  = ee_q;

  // Cover points (docs/coverage.md): the phase worked in this cycle (cur), each boundary step
  // kind (a column step down or up the box; an entry-row division, saturated: never enters), the
  // saturated slope and entry-x divisions, and a horizontal edge (no slope division).
  `COVER(LanePhSlope_C, cur == PhSlope, clk_i, !rst_ni)
  `COVER(LanePhTrav_C, cur == PhTrav, clk_i, !rst_ni)
  `COVER(LanePhEntry_C, cur == PhEntry, clk_i, !rst_ni)
  `COVER(LanePhDone_C, cur == PhDone, clk_i, !rst_ni)
  `COVER(LaneStepDown_C, cur == PhTrav && !divide_i && dir_q, clk_i, !rst_ni)
  `COVER(LaneStepUp_C, cur == PhTrav && !divide_i && !dir_q, clk_i, !rst_ni)
  `COVER(LaneEntryRowDivided_C, cur == PhTrav && divide_i && div_last && !div_sat, clk_i, !rst_ni)
  `COVER(LaneEntryRowSaturated_C, cur == PhTrav && divide_i && div_last && div_sat, clk_i, !rst_ni)
  `COVER(LaneSlopeSaturated_C, cur == PhSlope && div_last && div_sat, clk_i, !rst_ni)
  `COVER(LaneEntryXSaturated_C, cur == PhEntry && div_last && div_sat, clk_i, !rst_ni)
  `COVER(LaneHorizontalEdge_C, load_i && horiz_i, clk_i, !rst_ni)

endmodule
