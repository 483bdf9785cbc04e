// The half-space unit's walk stage control: the tile walker (docs/unit.md "The half-space unit",
// stage 2; docs/timing.md). It walks the box in bands of U rows (U = TileSize, or StampSize
// without tiles) and each band in U x U units, one unit test per cycle from the edge values at
// the unit's four corners (kept incrementally: E at the unit, and at the band's two end units),
// and a partial tile's stamps one per cycle through the stamp tester. Its pieces of coverage go
// to the span emitter; at the end of a band it hands the band to the emitter as soon as the
// emitter is free (WWait until then). States: WIdle, WUnit, WStamp, WWait, WDrain (the last band
// is being pushed).
`include "trirast_assert.svh"
`include "trirast_ports.svh"

module trirast_halfspace_tile_walker #(
  parameter int StampSize = 2,   // S: 1, 2, 4
  parameter int TileSize = 8,    // T: 8, 16, or 0 (no tiles)
  // The tile order: 0 row (every unit, left to right); 1 zig-zag (odd bands right to left, with
  // the early band end: the first rejected unit after one that was not); 2 forward (every band
  // left to right, with the early band end).
  parameter int WalkMode = 2,
  parameter int UnitSize = (TileSize > 0) ? TileSize : StampSize,  // derived
  // Signed bits of the edge values at a unit's corners, up to U - 1 pixels past the box (and so
  // past the coordinate range): trirast_pkg::HalfspaceEdgeBits<U> (docs/unit.md). Derived.
  parameter int HalfspaceEdgeBits = (UnitSize == 1) ? trirast_pkg::HalfspaceEdgeBits1 :
                             (UnitSize == 2) ? trirast_pkg::HalfspaceEdgeBits2 :
                             (UnitSize == 4) ? trirast_pkg::HalfspaceEdgeBits4 :
                             (UnitSize == 8) ? trirast_pkg::HalfspaceEdgeBits8 : trirast_pkg::HalfspaceEdgeBits16
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  // ---- hand-off from the setup stage ----
  input  logic                                  hand_valid_i,
  output logic                                  hand_ready_o,
  `TRIRAST_HANDOFF_BOX(input, _i),
  input  logic [3*trirast_pkg::CoefBits-1:0]    hand_a_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]    hand_b_i,
  input  logic [3*trirast_pkg::EdgeBits-1:0]    hand_e0_i,
  input  logic [3*trirast_pkg::EdgeBits-1:0]    hand_eend_i,
  // ---- the triangle, for the emitter ----
  output logic [trirast_pkg::TagBits-1:0]       tag_o,
  output logic [trirast_pkg::PixBits-1:0]       x0_o,
  output logic [trirast_pkg::PixBits-1:0]       y0_o,
  // ---- pieces of the current band and the band hand-over ----
  output logic [UnitSize-1:0]                   merge_o,        // row r of the band has a piece,
  output logic [UnitSize-1:0]                   merge_tile_o,   // ... or has one if accept_o
  output logic                                  accept_o,       // the unit is accepted whole
  output logic [StampSize*(trirast_pkg::BoxBits+1)-1:0] merge_first_o,  // ... piece r mod S
  output logic [StampSize*(trirast_pkg::BoxBits+1)-1:0] merge_last_o,
  output logic                                  band_load_o,
  output logic [trirast_pkg::BoxBits:0]         band_j0_o,
  output logic                                  band_back_o,  // the band runs right to left
  output logic                                  unit_next_o,  // the next unit follows this cycle
  input  logic                                  emit_held_i,  // the band has a run from an earlier cycle
  input  logic                                  emit_any_i,   // ... or from this cycle (assertions only)
  input  logic                                  emit_free_i,  // the emitter can take a band
  // ---- observation ----
  output logic                                  busy_o,
  output logic                                  last_o,       // the triangle's last cycle
  output logic                                  retire_o,     // ... and it had no span
  output logic [2:0]                            state_o
);
  localparam int F = trirast_pkg::FracBits;
  localparam int CoefBits = trirast_pkg::CoefBits;
  // The walker keeps E >> F: every step it takes is a multiple of u = 2^F (a = A*u, b = B*u), so
  // the low F bits of an edge value stay those of E0 (or E_end), and with them in [0, 2^F)
  // E < 0 exactly when E >> F < 0. The walker's values are E >> F, and its steps A and B.
  localparam int EdgeBits = HalfspaceEdgeBits - F;  // the walker's values; the hand-off's are pkg EdgeBits
  localparam int InBits = trirast_pkg::EdgeBits;
  localparam int BoxBits = trirast_pkg::BoxBits;
  localparam int PB = BoxBits + 1;
  localparam int S = StampSize;
  localparam int U = UnitSize;
  localparam bit Tiles = TileSize > 0;

  typedef enum logic [2:0] {
    WIdle  = 3'd0,
    WUnit  = 3'd1,
    WStamp = 3'd2,
    WWait  = 3'd3,
    WDrain = 3'd4
  } hs_walk_state_e;

  hs_walk_state_e state_q, state_d;
  logic [trirast_pkg::TagBits-1:0] tag_q, tag_d;
  logic [trirast_pkg::PixBits-1:0] x0_q, x0_d, y0_q, y0_d;
  logic [BoxBits-1:0] xmax_q, xmax_d, ymax_q, ymax_d;
  logic [3*EdgeBits-1:0] a_q, a_d, b_q, b_d;        // A, B: the steps a = A*u, b = B*u, >> F
  logic [3*EdgeBits-1:0] eu_q, eu_d;                // E at the current unit (i0, j0)
  // E at the band row's end units: ebn on the side the next band starts from, ebo on the other
  // (the same side without zig-zag). A next band starts at ebn + U*b; zig-zag's sides then swap.
  logic [3*EdgeBits-1:0] ebn_q, ebn_d, ebo_q, ebo_d;
  logic [PB-1:0] i0_q, i0_d, j0_q, j0_d, si_q, si_d, sj_q, sj_d, iend_q, iend_d;
  logic back_q, back_d, seen_q, seen_d, spans_q, spans_d;
  // The unit test's corner offsets, set at the load: E is linear, so of a unit's four corners
  // the largest edge value is at c00 + omax, omax = (U - 1)*(max(A, 0) + max(B, 0)), and the
  // smallest at c00 + omin, omin = (U - 1)*(min(A, 0) + min(B, 0)). Every corner < 0 exactly
  // when the largest is, every corner >= 0 exactly when the smallest is (the corner values fit
  // EdgeBits: no wrap). One carry chain from eu_q per test instead of the chained corner sums.
  localparam int OffBits = CoefBits + $clog2(U) + 1;  // |omax|, |omin| <= 2*(U - 1)*2^(CoefBits-1)
  logic [3*OffBits-1:0] omax_q, omax_d, omin_q, omin_d;
  // A partial tile's stamp values are tile-relative and narrow. Of an edge that crosses the tile
  // (neither all its corners outside nor all inside), every value in the tile lies between its
  // smallest and largest corner, c00 + omin < 0 <= c00 + omax, whose spread omax - omin =
  // (U - 1)*(|A| + |B|) < 2^(OffBits-1): so every one of them fits OffBits signed bits, and the
  // stamps keep and sum the low OffBits bits of E (exact modulo 2^OffBits, so exact). An edge that
  // holds the whole tile inside has large values but a known sign: its flag in st_inside_q masks
  // it in the stamp tester. Without tiles the stamp is the unit and its values are eu_q's.
  localparam int StampBits = Tiles ? OffBits : EdgeBits;
  logic [3*StampBits-1:0] es_q, es_d, esr_q, esr_d;  // E at the stamp / its stamp row's start
  logic [3*StampBits-1:0] a_st, b_st, eu_st;          // a, b and E at the unit, narrowed
  logic [2:0] st_inside_q, st_inside_d;               // the edge holds the tile inside

  // ---- unit test (WUnit): the four corners of the U x U unit ----
  // Rejected: all four corners outside one edge (its largest corner value < 0); accepted (tiles
  // only): all four inside every edge (each edge's smallest >= 0, so none rejects either). The
  // decision (u_decide, below) forms both from the six signs.
  // A sign of c00 + o (o an offset of OffBits signed bits) from a carry chain of OffBits bits:
  // with H = c00's bits from OffBits up and c the chain's carry out, the sum's high part is
  // H + c (o >= 0) or H - 1 + c (o < 0), whose sign is H's flipped exactly when H + 1 carries
  // into (H - 1 borrows from) H's sign bit: H's other bits all ones (all zeros). Those flags come
  // from eu_q alone, beside the chain; the chain's end selects between two early values.
  localparam logic [EdgeBits-1:0] HighMask =  // H's bits but its sign bit
      (EdgeBits'(1) << (EdgeBits - OffBits - 1)) - EdgeBits'(1);
  logic [2:0] out, all_in;
  always_comb begin
    for (int k = 0; k < 3; k++) begin
      logic [EdgeBits-1:0] c00, high;
      logic [OffBits-1:0] omax, omin;
      logic high_ones, high_zeros;
      /* verilator lint_off UNUSEDSIGNAL */
      logic [OffBits:0] smax, smin;  // their carries out only
      /* verilator lint_on UNUSEDSIGNAL */
      c00 = eu_q[k*EdgeBits +: EdgeBits];
      omax = omax_q[k*OffBits +: OffBits];
      omin = omin_q[k*OffBits +: OffBits];
      high = c00 >> OffBits;
      high_ones = (high & HighMask) == HighMask;
      high_zeros = (high & HighMask) == '0;
      smax = {1'b0, c00[OffBits-1:0]} + {1'b0, omax};
      smin = {1'b0, c00[OffBits-1:0]} + {1'b0, omin};
      out[k] = c00[EdgeBits-1] ^ (omax[OffBits-1] ? !smax[OffBits] && high_zeros
                                                  : smax[OffBits] && high_ones);
      all_in[k] = !(c00[EdgeBits-1] ^ (omin[OffBits-1] ? !smin[OffBits] && high_zeros
                                                      : smin[OffBits] && high_ones));
    end
  end
  logic reject, accept;

  // ---- stamp tester: the unit itself without tiles, else the next stamp ----
  // With tiles its result is read in WStamp only, without tiles in WUnit only: its inputs are
  // the unit's (eu, i0, j0) or, with tiles, the next stamp's (es_d, si_d, the next sj), and with
  // tiles its S x S coverage bits are registered with the stamp (es_en): the tester's adders
  // start from the stamp registers' inputs, which the registers and the registered last-column
  // and last-row flags select (no walk decision before them), and a stamp's pieces come from
  // flip-flops.
  logic [S*S-1:0] st_cover, st_cover_c, st_cover_q;
  logic [S-1:0] st_any;
  logic [S*PB-1:0] st_first, st_last;
  logic [PB-1:0] sj_next;  // the next stamp's row: sj_d at a stamp row's start, else sj_q
  logic stamp_mode;
  assign stamp_mode = state_q == WStamp;
  always_comb begin
    for (int k = 0; k < 3; k++) begin
      a_st[k*StampBits +: StampBits] = a_q[k*EdgeBits +: StampBits];
      b_st[k*StampBits +: StampBits] = b_q[k*EdgeBits +: StampBits];
      eu_st[k*StampBits +: StampBits] = eu_q[k*EdgeBits +: StampBits];
    end
  end
  trirast_halfspace_stamp_tester #(.StampSize (S), .EdgeBits (StampBits)) u_stamp (
    .e_i         (Tiles ? es_d : eu_st),
    .inside_i    (Tiles ? st_inside_d : 3'b000),
    .a_i         (a_st),
    .b_i         (b_st),
    .i0_i        (Tiles ? si_d : i0_q),
    .j0_i        (Tiles ? sj_next : j0_q),
    .xmax_i      (xmax_q),
    .ymax_i      (ymax_q),
    .cover_o     (st_cover_c)
  );
  assign st_cover = Tiles ? st_cover_q : st_cover_c;
`ifndef SYNTHESIS  // simulation only (the port proofs cut the stamp tester's outputs free)
`ifndef FORMAL
  // The coverage registered a cycle ahead is the stamp's own: the stamp tester on its registers.
  logic [S*S-1:0] st_cover_now;
  trirast_halfspace_stamp_tester #(.StampSize (S), .EdgeBits (StampBits)) u_stamp_now (
    .e_i (es_q), .inside_i (st_inside_q), .a_i (a_st), .b_i (b_st), .i0_i (si_q), .j0_i (sj_q),
    .xmax_i (xmax_q), .ymax_i (ymax_q), .cover_o (st_cover_now));
  `ASSERT_IMPLIES(HalfspaceStampAhead_A, Tiles && stamp_mode, st_cover_q == st_cover_now, clk_i,
                 !rst_ni)
`endif  // FORMAL
`endif  // SYNTHESIS
  // Per stamp row: any pixel, the first and last covered column: the stamp's column (S-aligned)
  // with its low bits set to the pixel's (no adder).
  always_comb begin
    logic [S-1:0] any;
    logic [S*PB-1:0] first, last;
    logic [PB-1:0] i0;
    i0 = Tiles ? si_q : i0_q;
    any = '0;
    first = '0;
    last = '0;
    for (int dj = 0; dj < S; dj++) begin
      for (int di = S - 1; di >= 0; di--) begin  // right to left: the last hit is the first column
        if (st_cover[dj*S + di]) begin
          if (!any[dj]) last[dj*PB +: PB] = i0 | PB'(di);
          first[dj*PB +: PB] = i0 | PB'(di);
          any[dj] = 1'b1;
        end
      end
    end
    st_any = any;
    st_first = first;
    st_last = last;
  end

  // ---- pieces for the emitter (row r of the band) ----
  // Row r's piece is piece r mod S: a stamp row starts at an S-aligned row of the unit, so a
  // stamp's row dj is band row srow + dj with dj = r mod S; an accepted tile gives every row the
  // same piece [i0, tile_i1]. The pieces are S muxes, and merge_o says which rows take theirs.
  // The last column of the tile inside the box, min(i0 + U - 1, Xmax), with no adder or compare
  // of magnitudes: i0 is U-aligned and <= Xmax, so i0 + U - 1 is i0 with its low L bits set, and
  // it passes Xmax exactly when i0 is in Xmax's unit (HalfspaceTileEnds_A).
  localparam int L = $clog2(U);
  localparam int LB = (L > 0) ? L : 1;  // a row of the unit (U = 1: one bit, always 0)
  logic [PB-1:0] tile_i1;
  assign tile_i1 = (i0_q >> L) == ({1'b0, xmax_q} >> L) ? {1'b0, xmax_q} : i0_q | PB'(U - 1);
  always_comb begin
    logic [PB-1:0] srow;
    logic [U-1:0] m, mt;
    srow = stamp_mode ? sj_q & PB'(U - 1) : '0;  // sj_q - j0_q: sj_q is in j0_q's (U-aligned) unit
    m = '0;
    mt = '0;
    for (int r = 0; r < U; r++) begin
      // j0 + r <= Ymax, j0 U-aligned: every row but in the box's last band, whose rows go to
      // Ymax's low bits (HalfspaceTileEnds_A).
      mt[r] = Tiles && state_q == WUnit && (!band_last || LB'(r) <= LB'(ymax_q & BoxBits'(U - 1)));
      for (int dj = 0; dj < S; dj++) begin
        if ((stamp_mode || (state_q == WUnit && !Tiles)) && srow + PB'(dj) == PB'(r) &&
            st_any[dj]) begin
          m[r] = 1'b1;
        end
      end
    end
    merge_tile_o = mt;
    merge_o = m;  // one write (Icarus 11: see trirast_halfspace_stamp_tester.sv)
  end
  for (genvar dj = 0; dj < S; dj++) begin : g_piece
    // With tiles, WUnit's piece is the accepted tile's; else (WStamp, or the unit without tiles)
    // the stamp row's.
    assign merge_first_o[dj*PB +: PB] = (Tiles && !stamp_mode) ? i0_q : st_first[dj*PB +: PB];
    assign merge_last_o[dj*PB +: PB] = (Tiles && !stamp_mode) ? tile_i1 : st_last[dj*PB +: PB];
  end

  // ---- the walk ----
  logic last_unit, band_last, stamp_last_col, stamp_last_row;
  logic [PB-1:0] tile_j1;  // the tile's last row in the box (as tile_i1; j0 is in Ymax's unit
  assign tile_j1 = band_last ? {1'b0, ymax_q} : j0_q | PB'(U - 1);  // in the last band)
  // The stamp's column (row) is the tile's last, si_q + S > tile_i1 (sj_q + S > tile_j1), with no
  // adder before a compare: units are U-aligned and stamps S-aligned in them, so it is the unit's
  // last stamp column, or si_q + S > xmax_q, which for an S-aligned si_q is si_q/S >= xmax_q/S.
  // Both are flip-flops, set with si_q and sj_q from their next values (Xmax and Ymax are set at
  // the load, and a unit's stamps start with es_en and esr_en after it): the stamp's control and
  // the next stamp's values start from them.
  function automatic logic stamp_end(input logic [PB-1:0] s, input logic [BoxBits-1:0] smax);
    stamp_end = (s & PB'(U - 1)) == PB'(U - S) || (s >> $clog2(S)) >= ({1'b0, smax} >> $clog2(S));
  endfunction
  logic stamp_last_col_q, stamp_last_row_q;
  assign stamp_last_col = stamp_last_col_q;
  assign stamp_last_row = stamp_last_row_q;
  // The band's last unit (back_q ? i0_q == 0 : i0_q == iend_q) and the box's last band
  // (j0_q + U > ymax_q) are flip-flops, set with i0_q and j0_q: the control starts from them.
  logic last_unit_q, last_unit_d, band_last_q, band_last_d;
  assign last_unit = last_unit_q;
  assign band_last = band_last_q;

  // The next values, from registers only (none waits for this cycle's test): the test selects
  // among them through the registers' enables and one 2:1 mux per bit (a next band's start or the
  // rest), so that the unit test's carry chain is followed by the control alone.
  localparam bit Zigzag = WalkMode == 1;    // odd bands right to left
  localparam bit EarlyEnd = WalkMode != 0;  // a rejected unit after a covered one ends the band
  logic [3*EdgeBits-1:0] ebn_next, ebo_next, eu_next, eu_band;
  logic [3*StampBits-1:0] esr_next, es_next;
  logic next_back;  // the next band runs right to left
  assign next_back = Zigzag && !back_q;
  always_comb begin
    for (int k = 0; k < 3; k++) begin
      logic [EdgeBits-1:0] ak, bk, bn, bo;
      /* verilator lint_off UNUSEDSIGNAL */
      logic [EdgeBits:0] nxt;  // its low bit only carries back_q in
      /* verilator lint_on UNUSEDSIGNAL */
      ak = a_q[k*EdgeBits +: EdgeBits];
      bk = b_q[k*EdgeBits +: EdgeBits];
      esr_next[k*StampBits +: StampBits] = esr_q[k*StampBits +: StampBits] +
                                          (b_st[k*StampBits +: StampBits] << $clog2(S));
      es_next[k*StampBits +: StampBits] = es_q[k*StampBits +: StampBits] +
                                         (a_st[k*StampBits +: StampBits] << $clog2(S));
      // The next band row's ends; zig-zag swaps the sides (the band after next starts on this
      // band's side), so the next band's start is always bn: no select between the sides.
      bn = ebn_q[k*EdgeBits +: EdgeBits] + (bk << L);
      bo = ebo_q[k*EdgeBits +: EdgeBits] + (bk << L);
      ebn_next[k*EdgeBits +: EdgeBits] = Zigzag ? bo : bn;
      ebo_next[k*EdgeBits +: EdgeBits] = Zigzag ? bn : bo;
      eu_band[k*EdgeBits +: EdgeBits] = bn;
      // The band's next unit, E + U*A or (right to left) E - U*A = E + ~(U*A) + 1: one adder, its
      // carry in back_q as the low bit of both operands.
      nxt = {eu_q[k*EdgeBits +: EdgeBits], 1'b1} + {(ak << L) ^ {EdgeBits{back_q}}, back_q};
      eu_next[k*EdgeBits +: EdgeBits] = nxt[EdgeBits:1];
    end
  end
  assign band_j0_o = j0_q;
  assign hand_ready_o = state_q == WIdle;

  // Which registers take a new value this cycle: the load (WIdle), the band's next unit, a next
  // band (at the hand-over), the stamps of a partial tile; and the next state. Formed here from the
  // registers alone once for each outcome of the unit test (rejected, accepted, neither); the
  // outcome then picks one (u_decide), so that only a select follows the test's carry chains.
  localparam int CtlBits = 7;
  logic load, band_go, band_next, eu_en, band_en, es_en, esr_en, stamp_col, stamp_row, stamp_done;
  logic band_any;  // the band has a run, this cycle's pieces included
  logic [CtlBits-1:0] ctl, ctl_if [3];  // the controls if rejected, accepted, neither
  hs_walk_state_e state_if [3];    // the next state ...
  hs_walk_state_e rest_state;
  assign load = state_q == WIdle && hand_valid_i;
  assign stamp_col = stamp_mode && !stamp_last_col;                    // the next stamp
  assign stamp_row = stamp_mode && stamp_last_col && !stamp_last_row;  // the next stamp row
  assign stamp_done = stamp_mode && stamp_last_col && stamp_last_row;  // the tile's last stamp
  // This cycle's pieces apart from an accepted tile's: a stamp row's come from the stamp tester,
  // not from the unit test (HalfspaceBandAny_A checks the sum with the emitter's rows).
  logic stamp_any;
  assign stamp_any = (stamp_mode || (state_q == WUnit && !Tiles)) && |st_any;
  assign rest_state = state_q == WIdle ? (hand_valid_i ? WUnit : WIdle)
                    : state_q == WDrain && !emit_free_i ? WDrain : WIdle;
  always_comb begin
    for (int c = 0; c < 3; c++) begin
      logic rej, acc, unit_done, band_end_or_wait, go, next_band, step, part, any;
      hs_walk_state_e next, over_state;
      rej = c == 0;
      acc = Tiles && c == 1;
      // The band has a run: an earlier cycle's, a stamp row's, or the accepted tile's (its row 0
      // is in the box).
      any = emit_held_i || stamp_any || (acc && state_q == WUnit);
      // The next state at a band's hand-over.
      if (!emit_free_i) over_state = WWait;
      else if (!band_last) over_state = WUnit;
      else if (any) over_state = WDrain;
      else over_state = WIdle;
      // The unit's test (without tiles every test is the unit's) or its last stamp is done; the
      // band ends (its last unit, or the early band end: a rejected unit after a covered one) or
      // waits.
      unit_done = (state_q == WUnit && (rej || acc || !Tiles)) || stamp_done;
      band_end_or_wait = (unit_done && (last_unit || (EarlyEnd && seen_q && state_q == WUnit &&
                                                      rej))) || state_q == WWait;
      go = band_end_or_wait && emit_free_i;            // the band is handed over
      next_band = go && !band_last;                    // ... and a next band starts
      step = unit_done && !band_end_or_wait;           // the band's next unit
      part = Tiles && state_q == WUnit && !rej && !acc;  // the unit's stamps next
      if (!(state_q == WUnit || state_q == WStamp || state_q == WWait)) next = rest_state;
      else if (band_end_or_wait) next = over_state;
      else if (unit_done) next = WUnit;
      else next = WStamp;
      ctl_if[c] = {any, go, next_band, load || step || next_band, load || next_band,
                   part || stamp_col || stamp_row, part || stamp_row};
      state_if[c] = next;
    end
  end
  trirast_halfspace_walk_decide #(.Tiles (Tiles), .CtlBits (CtlBits)) u_decide (
    .out_i        (out),
    .all_in_i     (all_in),
    .if_reject_i  (ctl_if[0]),
    .if_accept_i  (ctl_if[1]),
    .if_neither_i (ctl_if[2]),
    .state_if_reject_i  (state_if[0]),
    .state_if_accept_i  (state_if[1]),
    .state_if_neither_i (state_if[2]),
    .reject_o     (reject),
    .accept_o     (accept),
    .ctl_o        (ctl),
    .state_o      (state_d)
  );
  assign {band_any, band_go, band_next, eu_en, band_en, es_en, esr_en} = ctl;

  always_comb begin
    logic [PB-1:0] i0_step;
    // Load values (the WIdle hand-off).
    `TRIRAST_LOAD_HANDOFF_BOX
    for (int k = 0; k < 3; k++) begin
      logic [OffBits-1:0] ak, bk, smax, smin;
      a_d[k*EdgeBits +: EdgeBits] = EdgeBits'($signed(hand_a_i[k*CoefBits +: CoefBits]));
      b_d[k*EdgeBits +: EdgeBits] = EdgeBits'($signed(hand_b_i[k*CoefBits +: CoefBits]));
      ak = OffBits'($signed(hand_a_i[k*CoefBits +: CoefBits]));
      bk = OffBits'($signed(hand_b_i[k*CoefBits +: CoefBits]));
      smax = (ak[OffBits-1] ? '0 : ak) + (bk[OffBits-1] ? '0 : bk);
      smin = (ak[OffBits-1] ? ak : '0) + (bk[OffBits-1] ? bk : '0);
      omax_d[k*OffBits +: OffBits] = (smax << L) - smax;  // (U - 1)*smax
      omin_d[k*OffBits +: OffBits] = (smin << L) - smin;
    end
    // ~(W'(x)), not ~W'(x): Yosys 0.23 reads the latter as W'(x) (docs/formal.md)
    iend_d = {1'b0, hand_xmax_i & ~(BoxBits'(U - 1))};
    // The band's next unit, or a next band's first (the load's: the box corner).
    for (int k = 0; k < 3; k++) begin  // E >> F, sign-extended to the walker's width
      logic [EdgeBits-1:0] e0;
      e0 = EdgeBits'($signed(hand_e0_i[k*InBits + F +: InBits - F]));
      eu_d[k*EdgeBits +: EdgeBits] = band_next ? eu_band[k*EdgeBits +: EdgeBits]
                                   : state_q == WIdle ? e0 : eu_next[k*EdgeBits +: EdgeBits];
      // The load: band 0 starts at E0 (left); zig-zag's band 1 at E_end (right), the other walks'
      // at E0.
      ebn_d[k*EdgeBits +: EdgeBits] = state_q == WIdle
          ? (Zigzag ? EdgeBits'($signed(hand_eend_i[k*InBits + F +: InBits - F])) : e0)
          : ebn_next[k*EdgeBits +: EdgeBits];
      ebo_d[k*EdgeBits +: EdgeBits] = state_q == WIdle ? e0 : ebo_next[k*EdgeBits +: EdgeBits];
    end
    i0_step = back_q ? i0_q - PB'(U) : i0_q + PB'(U);
    i0_d = band_next ? (next_back ? iend_q : '0) : state_q == WIdle ? '0 : i0_step;
    // A next band's first unit is its last when iend_q == 0 (either way), the load's if iend_d is.
    last_unit_d = band_next ? iend_q == '0
                : state_q == WIdle ? iend_d == '0 : back_q ? i0_step == '0 : i0_step == iend_q;
    j0_d = state_q == WIdle ? '0 : j0_q + PB'(U);
    band_last_d = j0_d + PB'(U) > {1'b0, state_q == WIdle ? hand_ymax_i : ymax_q};
    back_d = state_q != WIdle && next_back;
    // Seen a unit not rejected in this band (with the early band end, the next rejected one ends
    // it).
    seen_d = !load && !band_next && (seen_q || (state_q == WUnit && !reject));
    spans_d = !load && (spans_q || (band_go && band_any));
    // A partial tile's stamps: from the unit's corner, along the stamp row, then the next row.
    si_d = stamp_col ? si_q + PB'(S) : i0_q;
    sj_d = stamp_mode ? sj_q + PB'(S) : j0_q;
    sj_next = stamp_mode && !stamp_last_col ? sj_q : sj_d;
    es_d = stamp_mode ? (stamp_last_col ? esr_next : es_next) : eu_st;
    esr_d = stamp_mode ? esr_next : eu_st;
    st_inside_d = stamp_mode ? st_inside_q : all_in;
  end

  // The triangle's last cycle: its last band handed over with no span, or its last span pushed.
  assign band_load_o = band_go;
  assign accept_o = accept;
  assign band_back_o = back_q;
  assign unit_next_o = eu_en;
  assign last_o = (band_go && band_last && !band_any) || (state_q == WDrain && emit_free_i);
  assign retire_o = band_go && band_last && !band_any && !spans_q;

  assign tag_o = tag_q;
  assign x0_o = x0_q;
  assign y0_o = y0_q;
  assign busy_o = state_q != WIdle;
  assign state_o = state_q;

  `TRIRAST_FLOP_AR(state_q, state_d, WIdle)
  always_ff @(posedge clk_i) begin
    if (load) begin
      {tag_q, x0_q, y0_q, xmax_q, ymax_q, a_q, b_q, omax_q, omin_q, iend_q} <=
          {tag_d, x0_d, y0_d, xmax_d, ymax_d, a_d, b_d, omax_d, omin_d, iend_d};
    end
    if (eu_en) {eu_q, i0_q, last_unit_q} <= {eu_d, i0_d, last_unit_d};
    if (band_en) begin
      {ebn_q, ebo_q, j0_q, back_q, band_last_q} <= {ebn_d, ebo_d, j0_d, back_d, band_last_d};
    end
    if (es_en) begin
      {si_q, es_q, st_inside_q, stamp_last_col_q} <= {si_d, es_d, st_inside_d, stamp_end(si_d, xmax_q)};
      st_cover_q <= st_cover_c;
    end
    if (esr_en) {sj_q, esr_q, stamp_last_row_q} <= {sj_d, esr_d, stamp_end(sj_d, ymax_q)};
    {seen_q, spans_q} <= {seen_d, spans_d};
  end

  `ASSERT_INIT(HalfspaceEdgeBitsLegal_A, EdgeBits >= InBits - F && EdgeBits > CoefBits &&
               EdgeBits > OffBits && StampBits <= EdgeBits)
  // Box-relative positions are PB = BoxBits + 1 bits: a unit past the box must not wrap.
  `ASSERT_INIT(HalfspaceBoxHoldsUnit_A, (1 << BoxBits) >= U)
  `ASSERT_INIT(HalfspaceParamsLegal_A, (StampSize == 1 || StampSize == 2 || StampSize == 4) &&
               (TileSize == 0 || TileSize == 8 || TileSize == 16) &&
               (TileSize == 0 || TileSize % StampSize == 0))
  `ASSERT(HalfspaceWalkStateLegal_A, state_q == WIdle || state_q == WUnit || state_q == WStamp ||
          state_q == WWait || state_q == WDrain, clk_i, !rst_ni)
  // The walker's position stays inside the box while it tests.
  `ASSERT_IMPLIES(HalfspaceUnitInBox_A, state_q == WUnit,
                 i0_q <= {1'b0, xmax_q} && j0_q <= {1'b0, ymax_q}, clk_i, !rst_ni)
  // The tile's ends from aligned positions are min(i0 + U - 1, Xmax) and min(j0 + U - 1, Ymax).
  `ASSERT_IMPLIES(HalfspaceTileEnds_A, state_q == WUnit || state_q == WStamp,
                 (i0_q & PB'(U - 1)) == '0 && (j0_q & PB'(U - 1)) == '0 &&
                 tile_i1 == ((i0_q + PB'(U - 1) > {1'b0, xmax_q}) ? {1'b0, xmax_q} : i0_q + PB'(U - 1)) &&
                 tile_j1 == ((j0_q + PB'(U - 1) > {1'b0, ymax_q}) ? {1'b0, ymax_q} : j0_q + PB'(U - 1)),
                 clk_i, !rst_ni)
  // The stamp tester's origin is S-aligned (it reads it so: trirast_halfspace_stamp_tester.sv).
  `ASSERT_IMPLIES(HalfspaceStampAligned_A, Tiles ? state_q == WStamp : state_q == WUnit,
                 ((Tiles ? si_q : i0_q) & PB'(S - 1)) == '0 && ((Tiles ? sj_q : j0_q) & PB'(S - 1)) == '0,
                 clk_i, !rst_ni)
  `ASSERT_IMPLIES(HalfspaceStampInTile_A, state_q == WStamp, si_q <= tile_i1 && sj_q <= tile_j1,
          clk_i, !rst_ni)
  // The flip-flops and the short forms above say what their definitions say: the test's signs
  // are those of the full sums c00 + omax and c00 + omin, ...
  function automatic logic sum_neg(input logic [EdgeBits-1:0] c00, input logic [OffBits-1:0] o);
    logic [EdgeBits-1:0] sum;
    sum = c00 + EdgeBits'($signed(o));
    sum_neg = sum[EdgeBits-1];
  endfunction
  `ASSERT(HalfspaceTestSigns_A, state_q != WUnit || (out == {
          sum_neg(eu_q[2*EdgeBits +: EdgeBits], omax_q[2*OffBits +: OffBits]),
          sum_neg(eu_q[EdgeBits +: EdgeBits], omax_q[OffBits +: OffBits]),
          sum_neg(eu_q[0 +: EdgeBits], omax_q[0 +: OffBits])} && all_in == ~{
          sum_neg(eu_q[2*EdgeBits +: EdgeBits], omin_q[2*OffBits +: OffBits]),
          sum_neg(eu_q[EdgeBits +: EdgeBits], omin_q[OffBits +: OffBits]),
          sum_neg(eu_q[0 +: EdgeBits], omin_q[0 +: OffBits])}), clk_i, !rst_ni)
  // ... the flip-flops hold their conditions, and the stamp's last column and row are the tile's.
  `ASSERT_IMPLIES(HalfspaceLastUnitHeld_A, state_q != WIdle,
                 last_unit_q == (back_q ? i0_q == '0 : i0_q == iend_q) &&
                 band_last_q == (j0_q + PB'(U) > {1'b0, ymax_q}), clk_i, !rst_ni)
  `ASSERT_IMPLIES(HalfspaceStampLast_A, state_q == WStamp,
                 stamp_last_col == (si_q + PB'(S) > tile_i1) &&
                 stamp_last_row == (sj_q + PB'(S) > tile_j1), clk_i, !rst_ni)
  // The band's run as the walker decides it is the emitter's (its rows with this cycle's pieces),
  // for a test with one outcome: the emitter takes an accepted tile's rows by accept alone, the
  // walker's controls give reject the priority.
  `ASSERT_IMPLIES(HalfspaceBandAny_A, (state_q == WUnit || state_q == WStamp || state_q == WWait) &&
                 !(accept && reject), band_any == emit_any_i, clk_i, !rst_ni)
`ifndef FORMAL  // simulation: the edge values are the set-up's (the port proofs cut the box stage,
                // so theirs may wrap, and a unit may be both)
  // A unit is never both accepted and rejected: each edge's smallest corner value is at most its
  // largest, and they do not wrap (HalfspaceEdgeBits).
  `ASSERT_IMPLIES(HalfspaceTestOneOutcome_A, state_q == WUnit, !(accept && reject), clk_i, !rst_ni)
`endif  // FORMAL
  `ASSERT_IMPLIES(HalfspaceHandOffOnlyIdle_A, hand_valid_i && hand_ready_o, state_q == WIdle, clk_i,
          !rst_ni)
  `ASSERT_KNOWN(HalfspaceWalkKnown_A, {busy_o, last_o, retire_o, band_load_o}, clk_i, !rst_ni)
  // Cover points (docs/coverage.md): every state and the walk's cases: a unit (tile or stamp)
  // rejected (outside an edge), accepted whole (inside all three: tiles only), partial (stamps
  // walked: tiles only); a band ended early (zigzag, forward: a rejected unit after a covered one), a band
  // walked right to left (zigzag), a band's hand-off waiting for the emitter, and a triangle
  // retired without a span.
  `COVER(WalkWIdle_C, state_q == WIdle, clk_i, !rst_ni)
  `COVER(WalkWUnit_C, state_q == WUnit, clk_i, !rst_ni)
  `COVER(WalkWStamp_C, state_q == WStamp, clk_i, !rst_ni)
  `COVER(WalkWWait_C, state_q == WWait, clk_i, !rst_ni)
  `COVER(WalkWDrain_C, state_q == WDrain, clk_i, !rst_ni)
  `COVER(WalkUnitRejected_C, state_q == WUnit && reject, clk_i, !rst_ni)
  `COVER(WalkUnitAccepted_C, state_q == WUnit && accept, clk_i, !rst_ni)
  `COVER(WalkUnitPartial_C, state_q == WUnit && !reject && !accept && Tiles, clk_i, !rst_ni)
  `COVER(WalkBandEndEarly_C, state_q == WUnit && EarlyEnd && seen_q && reject && !last_unit,
         clk_i, !rst_ni)
  `COVER(WalkBandBackward_C, state_q == WUnit && back_q, clk_i, !rst_ni)
  `COVER(WalkRetireNoSpan_C, retire_o, clk_i, !rst_ni)

endmodule
