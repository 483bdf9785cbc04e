// The half-space unit's span emitter (docs/unit.md "The half-space unit", stage 4; docs/timing.md):
// two buffers of UnitSize rows. The collect buffer widens each row's run [first, last] with the
// walker's pieces (stamp rows, accepted tiles) of the current band; at band_load_i (end of the
// band) the merged rows move to the emit buffer, which pushes one span per cycle, lowest row
// first, when the FIFO has room at the start of the cycle: count + pending < DEPTH, with pending
// the span in the push register in front of the span FIFO (trirast_halfspace_top: a span pushed
// in t is counted from the end of t + 1).
// The run is the hull of the row's pieces, widened without a compare: the walk's order says which
// piece is further out. A band's units come left to right (band_back_i low) or right to left, and
// a unit's pieces of one row left to right (its stamps). Left to right, every piece is right of
// the row's earlier ones: first is the first piece's, last the newest. Right to left, a piece of a
// new unit is left of every earlier one (first is its first), a later piece of the same unit right
// of that unit's earlier ones; last is the newest piece of the row's first unit. Two flags per row
// say which: a piece came from the current unit (in_unit_q), all its pieces did (first_unit_q);
// unit_next_i (the walker leaves its unit at the end of the cycle) clears them.
`include "trirast_assert.svh"

module trirast_halfspace_span_emitter #(
  parameter int UnitSize = 8,
  parameter int StampSize = 2,  // S: the walker's pieces per cycle; row r takes piece r mod S
  parameter int CountBits = 4,
  parameter int EntryBits = trirast_pkg::TagBits + 3 * trirast_pkg::PixBits + 1,
  // 1: each buffer's column registers take their value from LUTs of their own (the iCE40 form:
  // a logic cell pairs one LUT with one flip-flop, and a LUT that drives two flip-flops shares a
  // cell with neither); 0: one select per column feeds both buffers (fewer LUTs: the xc7 form).
  parameter bit OwnLuts = 1'b0
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic [CountBits-1:0]                  fifo_depth_i,
  input  logic [CountBits-1:0]                  fifo_count_i,
  input  logic                                  fifo_pending_i,  // a span in the FIFO's push register
  input  logic                                  fifo_pop_i,      // the FIFO's head is taken
  // ---- the triangle (stable while the walk stage is busy) ----
  input  logic [trirast_pkg::TagBits-1:0]       tag_i,
  input  logic [trirast_pkg::PixBits-1:0]       x0_i,
  input  logic [trirast_pkg::PixBits-1:0]       y0_i,
  // ---- the walker's pieces of the current band: row r has one (merge_i[r]), piece r mod S ----
  input  logic [UnitSize-1:0]                   merge_i,
  input  logic [UnitSize-1:0]                   merge_tile_i,  // ... or has one if accept_i
  input  logic                                  accept_i,
  input  logic [StampSize*(trirast_pkg::BoxBits+1)-1:0] merge_first_i,
  input  logic [StampSize*(trirast_pkg::BoxBits+1)-1:0] merge_last_i,
  // ---- band hand-over (a valid/ready pair: band_load_i only when free_o) ----
  input  logic                                  band_load_i,
  input  logic [trirast_pkg::BoxBits:0]         band_j0_i,
  input  logic                                  band_back_i,  // the band runs right to left
  input  logic                                  unit_next_i,  // the walker's next unit follows
  output logic                                  held_o,   // the band has a row with a run before this cycle
  output logic                                  any_o,    // ... or with this cycle's pieces
  output logic                                  free_o,   // nothing left to push after this cycle
  // ---- FIFO pushes ----
  output logic                                  push_o,
  output logic [EntryBits-1:0]                  push_data_o,
  output logic                                  stall_o   // a span waits for FIFO room
);
  localparam int PB = trirast_pkg::BoxBits + 1;
  localparam int PixBits = trirast_pkg::PixBits;
  localparam int RowBits = (UnitSize > 1) ? $clog2(UnitSize) : 1;

  localparam int BoxBits = trirast_pkg::BoxBits;  // a column in the box: <= Xmax < 2^BoxBits

  logic [UnitSize-1:0] acc_q, acc_d, pend_q, pend_d, merged;
  logic [UnitSize-1:0] in_unit_q, in_unit_d, first_unit_q, first_unit_d;
  logic [UnitSize*BoxBits-1:0] accf_q, accf_d, accl_q, accl_d, outf_q, outf_d, outl_q, outl_d;
  logic [UnitSize*BoxBits-1:0] mf, ml;
  logic [PB-1:0] outj0_q, outj0_d;
`ifndef SYNTHESIS
`ifndef FORMAL
  localparam logic [UnitSize*PB-1:0] ColumnTopBits = {UnitSize{1'b1, {BoxBits{1'b0}}}};
  logic [UnitSize*BoxBits-1:0] hull_f, hull_l;
`endif  // FORMAL
`endif  // SYNTHESIS
  logic room;
  logic [RowBits-1:0] row;
  logic [UnitSize-1:0] pend_next;

  // The collect buffer merged with this cycle's pieces (the header says which piece sets what).
  logic [UnitSize-1:0] upd_f, upd_l;  // the piece sets the row's first (last) column
  logic [UnitSize-1:0] merge, set_f, set_l;
  assign merge = merge_i | ({UnitSize{accept_i}} & merge_tile_i);
  assign set_f = ~acc_q | ({UnitSize{band_back_i}} & ~in_unit_q);
  assign set_l = ~acc_q | {UnitSize{!band_back_i}} | first_unit_q;
  trirast_halfspace_late_select #(.Bits (2 * UnitSize)) u_upd (
    .sel_i      (accept_i),
    .if_set_i   ({(merge_i | merge_tile_i) & set_f, (merge_i | merge_tile_i) & set_l}),
    .if_clear_i ({merge_i & set_f, merge_i & set_l}),
    .o          ({upd_f, upd_l})
  );
  assign merged = acc_q | merge;
  // Row r's piece, piece r mod S (its column's top bit, PB = BoxBits + 1, is clear: in the box).
  logic [UnitSize*PB-1:0] piece_f, piece_l;
  for (genvar r = 0; r < UnitSize; r++) begin : g_row
    assign piece_f[r*PB +: PB] = merge_first_i[(r % StampSize)*PB +: PB];
    assign piece_l[r*PB +: PB] = merge_last_i[(r % StampSize)*PB +: PB];
    assign mf[r*BoxBits +: BoxBits] = upd_f[r] ? piece_f[r*PB +: BoxBits]
                                               : accf_q[r*BoxBits +: BoxBits];
    assign ml[r*BoxBits +: BoxBits] = upd_l[r] ? piece_l[r*PB +: BoxBits]
                                               : accl_q[r*BoxBits +: BoxBits];
  end
  assign held_o = |acc_q;
  assign any_o = |merged;
  assign in_unit_d = (unit_next_i || band_load_i) ? '0 : in_unit_q | merge;
  assign first_unit_d = (unit_next_i || band_load_i) ? '0 : first_unit_q | (merge & ~acc_q);

  // The emit buffer: the lowest pending row goes when the FIFO has room.
  // room, registered: the next cycle's count + pending (count + pending - pop now, plus this
  // cycle's push) against the depth.
  logic room_q, room_d;
  assign room = room_q;
  assign room_d = (CountBits + 1)'(fifo_count_i) + (CountBits + 1)'(fifo_pending_i) -
                  (CountBits + 1)'(fifo_pop_i) + (CountBits + 1)'(push_o) <
                  (CountBits + 1)'(fifo_depth_i);
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) room_q <= 1'b1;  // empty, and the depth is at least 1
    else room_q <= room_d;
  end
  `ASSERT(HalfspaceRoomHeld_A, room_q == ((CountBits + 1)'(fifo_count_i) +
          (CountBits + 1)'(fifo_pending_i) < (CountBits + 1)'(fifo_depth_i)), clk_i, !rst_ni)
  always_comb begin
    logic [RowBits-1:0] lowest;
    lowest = '0;
    for (int r = UnitSize - 1; r >= 0; r--) if (pend_q[r]) lowest = RowBits'(r);
    row = lowest;
  end
  assign push_o = |pend_q && room;
  assign stall_o = |pend_q && !room;
  always_comb begin
    logic [UnitSize-1:0] left;
    left = pend_q;
    if (push_o) left[row] = 1'b0;
    pend_next = left;
  end
  // free_o, registered: nothing left to push after the next cycle's push either, formed from the
  // next cycle's pending rows and room (at the hand-over the merged rows, by accept last), so that
  // the walker's control starts from a flip-flop (HalfspaceFreeHeld_A: the same as ~|pend_next).
  function automatic logic drained(input logic [UnitSize-1:0] rows, input logic room_next);
    logic any, more;  // a row, more than one
    any = 1'b0;
    more = 1'b0;
    for (int r = 0; r < UnitSize; r++) begin
      more = more || (any && rows[r]);
      any = any || rows[r];
    end
    drained = !any || (!more && room_next);
  endfunction
  logic free_q, free_d, free_if_accept, free_if_not;
  assign free_if_accept = drained(acc_q | merge_i | merge_tile_i, room_d);
  assign free_if_not = drained(acc_q | merge_i, room_d);
  logic free_load;  // free_d at the hand-over
  trirast_halfspace_late_select #(.Bits (1)) u_free (
    .sel_i      (accept_i),
    .if_set_i   (free_if_accept),
    .if_clear_i (free_if_not),
    .o          (free_load)
  );
  assign free_d = band_load_i ? free_load : drained(pend_next, room_d);
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) free_q <= 1'b1;  // no row pending
    else free_q <= free_d;
  end
  assign free_o = free_q;
  `ASSERT(HalfspaceFreeHeld_A, free_q == ~|pend_next, clk_i, !rst_ni)

  always_comb begin
    logic [PixBits-1:0] y, xb;
    logic [PixBits:0] xe;
    /* verilator lint_off UNUSEDSIGNAL */
    logic [BoxBits-1:0] first, last;  // a column; its bits above PixBits (small builds) are zero
    /* verilator lint_on UNUSEDSIGNAL */
    // The row's run by a mux of its UnitSize rows: Yosys 0.23 maps the indexed part-select
    // outf_q[row*BoxBits +: BoxBits] to a shifter, 590 more iCE40 LUTs at UnitSize 8.
    y = y0_i + PixBits'(outj0_q) + PixBits'(row);
    first = '0;
    last = '0;
    for (int r = 0; r < UnitSize; r++) begin
      if (row == RowBits'(r)) begin
        first = outf_q[r*BoxBits +: BoxBits];
        last = outl_q[r*BoxBits +: BoxBits];
      end
    end
    xb = x0_i + PixBits'(first);
    xe = {1'b0, x0_i} + (PixBits+1)'(last) + 1'b1;
    push_data_o = {tag_i, y, xb, xe};
  end

  assign acc_d = band_load_i ? '0 : merged;
  logic [UnitSize*BoxBits-1:0] out_mf, out_ml;  // the emit buffer's at the hand-over
  if (OwnLuts) begin : g_own_luts
    // The collect buffer's columns: mf and ml, but zero on a row without a run (not read: its
    // next piece sets them). Not a select between the piece and the register itself, which
    // synthesis makes a flip-flop enable with the piece as its data (a piece drives the columns
    // of UnitSize / StampSize rows: no LUT of their own).
    // The emit buffer's: mf and ml with their own select, upd_f | ~acc_q (upd_l | ~acc_q), the
    // same on every row it will push (a row without a run before this cycle takes its piece:
    // upd_f and upd_l set) and different only on rows it does not push.
    for (genvar r = 0; r < UnitSize; r++) begin : g_row
      logic [BoxBits-1:0] pf, pl, af, al;
      assign {pf, pl} = {piece_f[r*PB +: BoxBits], piece_l[r*PB +: BoxBits]};
      assign {af, al} = {accf_q[r*BoxBits +: BoxBits], accl_q[r*BoxBits +: BoxBits]};
      assign accf_d[r*BoxBits +: BoxBits] = upd_f[r] ? pf : af & {BoxBits{acc_q[r]}};
      assign accl_d[r*BoxBits +: BoxBits] = upd_l[r] ? pl : al & {BoxBits{acc_q[r]}};
      assign out_mf[r*BoxBits +: BoxBits] = (upd_f[r] || !acc_q[r]) ? pf : af;
      assign out_ml[r*BoxBits +: BoxBits] = (upd_l[r] || !acc_q[r]) ? pl : al;
      `ASSERT_IMPLIES(HalfspaceEmitLoadRun_A, merged[r],
                      out_mf[r*BoxBits +: BoxBits] == mf[r*BoxBits +: BoxBits] &&
                      out_ml[r*BoxBits +: BoxBits] == ml[r*BoxBits +: BoxBits], clk_i, !rst_ni)
    end
  end else begin : g_shared_luts
    assign {accf_d, accl_d, out_mf, out_ml} = {mf, ml, mf, ml};
  end
  assign pend_d = band_load_i ? merged : pend_next;
  assign outf_d = band_load_i ? out_mf : outf_q;
  assign outl_d = band_load_i ? out_ml : outl_q;
  assign outj0_d = band_load_i ? band_j0_i : outj0_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      {acc_q, pend_q, in_unit_q, first_unit_q} <= '0;
    end else begin
      {acc_q, pend_q, in_unit_q, first_unit_q} <= {acc_d, pend_d, in_unit_d, first_unit_d};
    end
  end
  always_ff @(posedge clk_i) begin
    {accf_q, accl_q, outf_q, outl_q, outj0_q} <= {accf_d, accl_d, outf_d, outl_d, outj0_d};
  end

  // A band is handed over only when the previous one is out.
  `ASSERT_IMPLIES(HalfspaceBandLoadWhenFree_A, band_load_i, free_o, clk_i, !rst_ni)
`ifndef SYNTHESIS  // simulation only: neither synthesis nor the formal flow (Yosys), whose
`ifndef FORMAL     // proof of the ports cuts the stamp tester's outputs free
  // Merged pieces lie in the box: a column's top bit (PB = BoxBits + 1) is clear.
  logic [UnitSize*PB-1:0] merge_cols;
  for (genvar r = 0; r < UnitSize; r++) begin : g_merge_cols
    assign merge_cols[r*PB +: PB] = {PB{merge[r]}};
  end
  `ASSERT(HalfspacePieceInBox_A, ((piece_f | piece_l) & merge_cols & ColumnTopBits) == '0, clk_i,
          !rst_ni)
  // The walk's order makes the widened run the hull of the row's pieces: the compares it saves.
  always_comb begin
    logic [UnitSize*BoxBits-1:0] hf, hl;
    hf = accf_q;
    hl = accl_q;
    for (int r = 0; r < UnitSize; r++) begin
      if (merge[r] && (!acc_q[r] || piece_f[r*PB +: BoxBits] < accf_q[r*BoxBits +: BoxBits]))
        hf[r*BoxBits +: BoxBits] = piece_f[r*PB +: BoxBits];
      if (merge[r] && (!acc_q[r] || piece_l[r*PB +: BoxBits] > accl_q[r*BoxBits +: BoxBits]))
        hl[r*BoxBits +: BoxBits] = piece_l[r*PB +: BoxBits];
    end
    hull_f = hf;
    hull_l = hl;
  end
  `ASSERT(HalfspaceRunIsHull_A, mf == hull_f && ml == hull_l, clk_i, !rst_ni)
`endif  // FORMAL
`endif  // SYNTHESIS
  `ASSERT_KNOWN(HalfspaceEmitterKnown_A, {push_o, free_o, any_o, stall_o}, clk_i, !rst_ni)
  `ASSERT_KNOWN_IF(HalfspacePushDataKnown_A, push_o, push_data_o, clk_i, !rst_ni)
endmodule
