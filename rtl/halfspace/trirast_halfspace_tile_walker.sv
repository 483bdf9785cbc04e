// The half-space unit's walk stage control: the tile walker (docs/unit.md "The half-space unit",
// stage 2; docs/timing.md). It walks the box in bands of U rows (U = TileSize, or StampSize
// without tiles) and each band in U x U units, one unit test per cycle from the edge values at
// the unit's four corners (kept incrementally: E at the unit, at the band's first and last unit),
// and a partial tile's stamps one per cycle through the stamp tester. Its pieces of coverage go
// to the span emitter; at the end of a band it hands the band to the emitter as soon as the
// emitter is free (WWait until then). States: WIdle, WUnit, WStamp, WWait, WDrain (the last band
// is being pushed).
`include "trirast_assert.svh"
`include "trirast_ports.svh"

module trirast_halfspace_tile_walker #(
  parameter int StampSize = 2,   // S: 1, 2, 4
  parameter int TileSize = 8,    // T: 8, 16, or 0 (no tiles)
  parameter bit WalkZigzag = 1'b1,        // zig-zag bands with early band end; 0: row order
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
  output logic [UnitSize-1:0]                   merge_o,
  output logic [UnitSize*(trirast_pkg::BoxBits+1)-1:0] merge_first_o,
  output logic [UnitSize*(trirast_pkg::BoxBits+1)-1:0] merge_last_o,
  output logic                                  band_load_o,
  output logic [trirast_pkg::BoxBits:0]         band_j0_o,
  input  logic                                  emit_any_i,   // the band (with this cycle) has a run
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
  logic [3*EdgeBits-1:0] ebl_q, ebl_d, ebr_q, ebr_d;  // E at the band's first / last unit
  logic [3*EdgeBits-1:0] es_q, es_d, esr_q, esr_d;  // E at the stamp / its stamp row's start
  logic [PB-1:0] i0_q, i0_d, j0_q, j0_d, si_q, si_d, sj_q, sj_d, iend_q, iend_d;
  logic back_q, back_d, seen_q, seen_d, spans_q, spans_d;

  // ---- unit test (WUnit): the four corners of the U x U unit ----
  logic reject, accept;
  always_comb begin
    logic [2:0] out, all_in;
    for (int k = 0; k < 3; k++) begin
      logic [EdgeBits-1:0] ak, bk, c00, c10, c01, c11;
      ak = a_q[k*EdgeBits +: EdgeBits];
      bk = b_q[k*EdgeBits +: EdgeBits];
      c00 = eu_q[k*EdgeBits +: EdgeBits];
      c10 = c00 + (ak << $clog2(U)) - ak;  // + (U - 1)*a
      c01 = c00 + (bk << $clog2(U)) - bk;
      c11 = c10 + (bk << $clog2(U)) - bk;
      out[k] = c00[EdgeBits-1] && c10[EdgeBits-1] && c01[EdgeBits-1] && c11[EdgeBits-1];
      all_in[k] = !c00[EdgeBits-1] && !c10[EdgeBits-1] && !c01[EdgeBits-1] && !c11[EdgeBits-1];
    end
    reject = |out;
    accept = Tiles && !reject && &all_in;
  end

  // ---- stamp tester: the unit itself without tiles, else the current stamp ----
  // With tiles its result is read in WStamp only, without tiles in WUnit only: its inputs are
  // the stamp's (es, si, sj) or the unit's (eu, i0, j0) by the build, not by the state.
  logic [S-1:0] st_any;
  logic [S*PB-1:0] st_first, st_last;
  logic stamp_mode;
  assign stamp_mode = state_q == WStamp;
  trirast_halfspace_stamp_tester #(.StampSize (S), .EdgeBits (EdgeBits)) u_stamp (
    .e_i         (Tiles ? es_q : eu_q),
    .a_i         (a_q),
    .b_i         (b_q),
    .i0_i        (Tiles ? si_q : i0_q),
    .j0_i        (Tiles ? sj_q : j0_q),
    .xmax_i      (xmax_q),
    .ymax_i      (ymax_q),
    .row_any_o   (st_any),
    .row_first_o (st_first),
    .row_last_o  (st_last)
  );

  // ---- pieces for the emitter (row r of the band) ----
  logic [PB-1:0] tile_i1;  // last column of the tile inside the box
  assign tile_i1 = (i0_q + PB'(U - 1) > {1'b0, xmax_q}) ? {1'b0, xmax_q} : i0_q + PB'(U - 1);
  always_comb begin
    logic [PB-1:0] srow;
    logic [U-1:0] m;
    logic [U*PB-1:0] mf, ml;
    srow = stamp_mode ? sj_q - j0_q : '0;
    m = '0;
    mf = '0;
    ml = '0;
    for (int r = 0; r < U; r++) begin
      if (state_q == WUnit && accept) begin
        m[r] = j0_q + PB'(r) <= {1'b0, ymax_q};
        mf[r*PB +: PB] = i0_q;
        ml[r*PB +: PB] = tile_i1;
      end
      for (int dj = 0; dj < S; dj++) begin
        if ((stamp_mode || (state_q == WUnit && !Tiles)) && srow + PB'(dj) == PB'(r) &&
            st_any[dj]) begin
          m[r] = 1'b1;
          mf[r*PB +: PB] = st_first[dj*PB +: PB];
          ml[r*PB +: PB] = st_last[dj*PB +: PB];
        end
      end
    end
    // One write each (Icarus 11: see trirast_halfspace_stamp_tester.sv).
    merge_o = m;
    merge_first_o = mf;
    merge_last_o = ml;
  end

  // ---- the walk ----
  logic unit_done, is_rej, last_unit, band_end, band_last, stamp_last_col, stamp_last_row;
  logic [PB-1:0] tile_j1;
  assign tile_j1 = (j0_q + PB'(U - 1) > {1'b0, ymax_q}) ? {1'b0, ymax_q} : j0_q + PB'(U - 1);
  assign stamp_last_col = si_q + PB'(S) > tile_i1;
  assign stamp_last_row = sj_q + PB'(S) > tile_j1;
  assign is_rej = state_q == WUnit && reject;
  assign unit_done = (state_q == WUnit && (reject || accept || !Tiles)) ||
                     (stamp_mode && stamp_last_col && stamp_last_row);
  assign last_unit = back_q ? i0_q == '0 : i0_q == iend_q;
  assign band_end = unit_done && (last_unit || (WalkZigzag && seen_q && is_rej));
  assign band_last = j0_q + PB'(U) > {1'b0, ymax_q};

  // The next stamp row's start and the next band's first and last unit.
  logic [3*EdgeBits-1:0] esr_next, ebl_next, ebr_next;
  always_comb begin
    for (int k = 0; k < 3; k++) begin
      esr_next[k*EdgeBits +: EdgeBits] = esr_q[k*EdgeBits +: EdgeBits] +
                                         (b_q[k*EdgeBits +: EdgeBits] << $clog2(S));
      ebl_next[k*EdgeBits +: EdgeBits] = ebl_q[k*EdgeBits +: EdgeBits] +
                                         (b_q[k*EdgeBits +: EdgeBits] << $clog2(U));
      ebr_next[k*EdgeBits +: EdgeBits] = ebr_q[k*EdgeBits +: EdgeBits] +
                                         (b_q[k*EdgeBits +: EdgeBits] << $clog2(U));
    end
  end
  logic next_back;  // the next band runs right to left
  assign next_back = WalkZigzag && !back_q;
  assign band_j0_o = j0_q;
  assign hand_ready_o = state_q == WIdle;

  always_comb begin
    logic band_load, last, retire;  // one write each of the outputs (Icarus 11)
    state_d = state_q;
    {tag_d, x0_d, y0_d, xmax_d, ymax_d, a_d, b_d, eu_d, ebl_d, ebr_d, es_d, esr_d, i0_d, j0_d, si_d,
     sj_d, iend_d, back_d, seen_d, spans_d} =
        {tag_q, x0_q, y0_q, xmax_q, ymax_q, a_q, b_q, eu_q, ebl_q, ebr_q, es_q, esr_q, i0_q, j0_q,
         si_q, sj_q, iend_q, back_q, seen_q, spans_q};
    band_load = 1'b0;
    last = 1'b0;
    retire = 1'b0;

    unique case (state_q)
      WIdle: begin
        if (hand_valid_i) begin
          state_d = WUnit;
          `TRIRAST_LOAD_HANDOFF_BOX
          for (int k = 0; k < 3; k++) begin
            a_d[k*EdgeBits +: EdgeBits] = EdgeBits'($signed(hand_a_i[k*CoefBits +: CoefBits]));
            b_d[k*EdgeBits +: EdgeBits] = EdgeBits'($signed(hand_b_i[k*CoefBits +: CoefBits]));
          end
          for (int k = 0; k < 3; k++) begin  // E >> F, sign-extended to the walker's width
            eu_d[k*EdgeBits +: EdgeBits] = EdgeBits'($signed(hand_e0_i[k*InBits + F +: InBits - F]));
            ebl_d[k*EdgeBits +: EdgeBits] = EdgeBits'($signed(hand_e0_i[k*InBits + F +: InBits - F]));
            ebr_d[k*EdgeBits +: EdgeBits] = EdgeBits'($signed(hand_eend_i[k*InBits + F +: InBits - F]));
          end
          i0_d = '0;
          j0_d = '0;
          // ~(W'(x)), not ~W'(x): Yosys 0.23 reads the latter as W'(x) (docs/formal.md)
          iend_d = {1'b0, hand_xmax_i & ~(BoxBits'(U - 1))};
          back_d = 1'b0;
          seen_d = 1'b0;
          spans_d = 1'b0;
        end
      end
      WUnit: begin
        if (!reject) seen_d = 1'b1;
        if (Tiles && !reject && !accept) begin
          state_d = WStamp;
          si_d = i0_q;
          sj_d = j0_q;
          es_d = eu_q;
          esr_d = eu_q;
        end
      end
      WStamp: begin
        if (!stamp_last_col) begin
          si_d = si_q + PB'(S);
          for (int k = 0; k < 3; k++)
            es_d[k*EdgeBits +: EdgeBits] = es_q[k*EdgeBits +: EdgeBits] +
                                           (a_q[k*EdgeBits +: EdgeBits] << $clog2(S));
        end else if (!stamp_last_row) begin
          si_d = i0_q;
          sj_d = sj_q + PB'(S);
          esr_d = esr_next;
          es_d = esr_next;
        end
      end
      WWait, WDrain: ;
      default: state_d = WIdle;
    endcase

    // After a unit (a test, or a partial tile's last stamp): the next unit, or the band's end.
    if (unit_done && !band_end) begin
      state_d = WUnit;
      i0_d = back_q ? i0_q - PB'(U) : i0_q + PB'(U);
      for (int k = 0; k < 3; k++)
        eu_d[k*EdgeBits +: EdgeBits] = back_q
            ? eu_q[k*EdgeBits +: EdgeBits] - (a_q[k*EdgeBits +: EdgeBits] << $clog2(U))
            : eu_q[k*EdgeBits +: EdgeBits] + (a_q[k*EdgeBits +: EdgeBits] << $clog2(U));
    end
    if (band_end || state_q == WWait) begin
      if (!emit_free_i) begin
        state_d = WWait;
      end else begin
        band_load = 1'b1;
        spans_d = spans_q || emit_any_i;
        if (band_last) begin
          // The last band: done now if it has no span, else when its last span is pushed.
          if (emit_any_i) state_d = WDrain;
          else state_d = WIdle;
          last = !emit_any_i;
          retire = !emit_any_i && !spans_q;
        end else begin
          state_d = WUnit;
          j0_d = j0_q + PB'(U);
          back_d = next_back;
          seen_d = 1'b0;
          ebl_d = ebl_next;
          ebr_d = ebr_next;
          eu_d = next_back ? ebr_next : ebl_next;
          i0_d = next_back ? iend_q : '0;
        end
      end
    end
    if (state_q == WDrain && emit_free_i) begin
      state_d = WIdle;
      last = 1'b1;
    end
    band_load_o = band_load;
    last_o = last;
    retire_o = retire;
  end

  assign tag_o = tag_q;
  assign x0_o = x0_q;
  assign y0_o = y0_q;
  assign busy_o = state_q != WIdle;
  assign state_o = state_q;

  `TRIRAST_FLOP_AR(state_q, state_d, WIdle)
  always_ff @(posedge clk_i) begin
    {tag_q, x0_q, y0_q, xmax_q, ymax_q, a_q, b_q, eu_q, ebl_q, ebr_q, es_q, esr_q, i0_q, j0_q, si_q,
     sj_q, iend_q, back_q, seen_q, spans_q} <=
        {tag_d, x0_d, y0_d, xmax_d, ymax_d, a_d, b_d, eu_d, ebl_d, ebr_d, es_d, esr_d, i0_d, j0_d,
         si_d, sj_d, iend_d, back_d, seen_d, spans_d};
  end

  `ASSERT_INIT(HalfspaceEdgeBitsLegal_A, EdgeBits >= InBits - F && EdgeBits > CoefBits)
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
  `ASSERT_IMPLIES(HalfspaceStampInTile_A, state_q == WStamp, si_q <= tile_i1 && sj_q <= tile_j1,
          clk_i, !rst_ni)
  `ASSERT_IMPLIES(HalfspaceHandOffOnlyIdle_A, hand_valid_i && hand_ready_o, state_q == WIdle, clk_i,
          !rst_ni)
  `ASSERT_KNOWN(HalfspaceWalkKnown_A, {busy_o, last_o, retire_o, band_load_o}, clk_i, !rst_ni)
  // Cover points (docs/coverage.md): every state and the walk's cases: a unit (tile or stamp)
  // rejected (outside an edge), accepted whole (inside all three: tiles only), partial (stamps
  // walked: tiles only); a band ended early (zigzag: a rejected unit after a covered one), a band
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
  `COVER(WalkBandEndEarly_C, band_end && !last_unit, clk_i, !rst_ni)
  `COVER(WalkBandBackward_C, state_q == WUnit && back_q, clk_i, !rst_ni)
  `COVER(WalkRetireNoSpan_C, retire_o, clk_i, !rst_ni)

endmodule
