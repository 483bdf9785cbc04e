// The second-generation improved unit's walk stage (rtl/improved2/trirast_improved2.f, docs/rtl.md): a
// retimed walk stage (the walkers, the span generator, a registered push with its credit, the
// span FIFO; tb/improved2/improved2_walk_stage_tb.sv holds it against the improved unit's walk
// stage) with a tiny job: a triangle
// whose box has at most 2 x 2 pixel centres comes with its rows' spans already
// decided by the direct 2x2 test (hand_tiny_i, per row j a valid bit and begin / end relative to
// x0: 0 or 1, 1 or 2). A tiny job takes the walk stage like any other (so spans leave in
// acceptance order) and emits its rows through the same registered push: one row per cycle, and
// it ends after row 0 when row 1 is empty or outside the box (a job without spans takes one cycle).
// The walkers load stale hand-off values for a tiny job; their outputs are not read.
// Build choices for the iCE40 fit (docs/improved2.md, "Build choices"; the same cycles):
// FifoRam 1 keeps the span FIFO in block RAM (trirast_span_fifo_ram.sv) instead of flip-flops,
// written from the push register's inputs a cycle ahead of the push (no push data register);
// WalkerCs 0 gives the walkers trirast_improved2_edge_walker's carry-in step (one X' and one bound adder
// each).
// NumEndpoints N (docs/timing.md, "The second-generation improved unit", W): each walk cycle
// processes a group of n = cfg_endpoints_i rows (1..N; N = 1: one row, cfg_endpoints_i unused), as
// rtl/improved/trirast_improved_walk_stage.sv does: the walkers present rows j .. j + N - 1 (a chain of steps), one
// span generator per row, and the registered push holds up to n spans, pushed together through the
// span FIFO's n push ports (trirast_span_fifo, rows packed in order). A group goes in a cycle when
// count + (the spans in the push register) + n <= DEPTH (N = 1: count + push < DEPTH). The last
// group is the one reaching past Ymax; its rows past Ymax push nothing. A tiny job's rows 0 and 1
// are one group when n >= 2 (n = 1: as above, row 1 only when it has a span). FifoRam applies
// to N = 1 only (the block RAM FIFO has one write port): with N > 1 the FIFO is in flip-flops.
// HandHeld 1: the job's tag, x0, y0, Xmax and Ymax (hand_tag_i .. hand_ymax_i) are held outside
// the stage from the cycle after the load until the next load (trirast_improved2_top's job ring),
// and read from then on instead of being copied at the load.
`include "trirast_ports.svh"

`include "trirast_assert.svh"
module trirast_improved2_walk_stage #(
  parameter int FifoDepth = trirast_pkg::DefaultFifoDepth,
  parameter bit FifoRam   = 1'b0,
  parameter bit WalkerCs  = 1'b1,
  parameter bit HandHeld  = 1'b0,
  parameter int NumEndpoints = 1,
  parameter int CountBits = $clog2(FifoDepth + 1)  // derived: do not override
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic                                  hand_valid_i,
  output logic                                  hand_ready_o,
  `TRIRAST_HANDOFF_BOX(input, _i),
  `TRIRAST_IMPROVED_HANDOFF_EDGES(input, _i),
  input  logic [3*(trirast_pkg::BoxBits+1)-1:0] hand_entry_b_i,     // the bounds - 1
  input  logic [3*trirast_pkg::RemBits-1:0]     hand_entry_e_i,
  input  logic                                  hand_tiny_i,        // a tiny job (2x2 test)
  input  logic [1:0]                            hand_tiny_valid_i,  // row j has a span
  input  logic [1:0]                            hand_tiny_begin_i,  // row j: x_begin - x0 (0, 1)
  input  logic [1:0]                            hand_tiny_end1_i,   // row j: x_end - x0 - 1 (0, 1)
  input  logic [CountBits-1:0]                  cfg_fifo_depth_i,   // room: entries + push < this
  input  logic [2:0]                            cfg_endpoints_i,    // n: rows per group (1..N)
  input  logic                                  span_ready_i,
  output logic                                  span_valid_o,
  output logic [trirast_pkg::TagBits+3*trirast_pkg::PixBits:0] span_o,
  output logic                                  busy_o,
  // ---- observation ----
  output logic                                  walk_o,     // a job walks
  output logic                                  stall_o,    // ... and its group waits for room
  output logic                                  last_o,     // its last group goes
  output logic                                  retire_o,   // ... and the job had no span
  output logic [trirast_pkg::TagBits-1:0]       tag_o,
  output logic [CountBits-1:0]                  fifo_count_o
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  localparam int EntryBits = TB + 3 * PB + 1;

  localparam int NB = NumEndpoints;
  localparam int PushBits = $clog2(NB + 1);

  logic walk_q, walk_d, load, go, last;
  logic [TB-1:0] tag_q;
  logic [PB-1:0] x0_q, y0_q;
  logic [BB-1:0] xmax_q, ymax_q;
  if (HandHeld) begin : g_held
    assign {tag_q, x0_q, y0_q, xmax_q, ymax_q} =
        {hand_tag_i, hand_x0_i, hand_y0_i, hand_xmax_i, hand_ymax_i};
  end else begin : g_copy
    always_ff @(posedge clk_i) begin
      if (load) begin
        tag_q  <= hand_tag_i;
        x0_q   <= hand_x0_i;
        y0_q   <= hand_y0_i;
        xmax_q <= hand_xmax_i;
        ymax_q <= hand_ymax_i;
      end
    end
  end
  logic [WB-1:0] row_q, row_d;
  logic [2:0] mirror;
  logic [3*2*NB-1:0] st;             // walker k, row r: [2*(k*NB + r) +: 2]
  logic [3*NB*(BB+1)-1:0] bnd;        // walker k, row r: [(k*NB + r)*(BB+1) +: BB+1]
  logic tiny_q;
  logic [1:0] tvalid_q, tbegin_q, tend1_q;
  logic [2:0] n;          // rows per group
  logic [1:0] n1;         // n - 1

  if (NB == 1) begin : g_n1
    assign n  = 3'd1;
    assign n1 = 2'd0;
    logic unused_n;
    assign unused_n = ^cfg_endpoints_i;
  end else begin : g_nn
    assign n  = cfg_endpoints_i;
    assign n1 = 2'(cfg_endpoints_i - 3'd1);
  end

  assign load = !walk_q && hand_valid_i;

  for (genvar k = 0; k < 3; k++) begin : g_walker
    trirast_improved2_edge_walker #(.CarrySelect (WalkerCs), .NumEndpoints (NB)) u_walker (
      .clk_i         (clk_i),
      .rst_ni        (rst_ni),
      .load_i        (load),
      .mirror_i      (hand_mirror_i[k]),
      .dir_down_i    (hand_dir_down_i[k]),
      .d_i           (hand_d_i[k*SB +: SB]),
      .qs_i          (hand_qs_i[k*QB +: QB]),
      .rs_i          (hand_rs_i[k*RB +: RB]),
      .ssat_i        (hand_ssat_i[k]),
      .enters_i      (hand_enters_i[k]),
      .j_entry_i     (hand_j_entry_i[k*WB +: WB]),
      .entry_state_i (hand_entry_state_i[2*k +: 2]),
      .entry_x_i     (hand_entry_x_i[k*XB +: XB]),
      .entry_b_i     (hand_entry_b_i[k*(BB+1) +: BB+1]),
      .entry_e_i     (hand_entry_e_i[k*RB +: RB]),
      .adv_i         (go),
      .adv_rows_i    (n),
      .mirror_o      (mirror[k]),
      .row_state_o   (st[k*2*NB +: 2*NB]),
      .row_bound_o   (bnd[k*NB*(BB+1) +: NB*(BB+1)])
    );
  end

  // The registered push (up to n spans) and its credit.
  logic [NB-1:0] push_q, push_d;
  logic [NB*EntryBits-1:0] data_d;
  logic [CountBits-1:0] count;
  logic room;
  if (NB == 1) begin : g_room1
    // count + push < DEPTH (written as the N = 1 unit always was: Yosys maps the general form
    // below, with its + 0, to some 500 more iCE40 LUTs in the whole unit).
    assign room = (CountBits + 1)'(count) + (CountBits + 1)'(push_q) <
                  (CountBits + 1)'(cfg_fifo_depth_i);
    logic unused_n1;
    assign unused_n1 = ^n1;
  end else begin : g_roomn
    // count + pushes_q + n <= DEPTH, as count + pushes_q + (n - 1) < DEPTH (pushes_q: the spans
    // in the push register).
    logic [PushBits-1:0] pushes_q;
    always_comb begin
      pushes_q = '0;
      for (int r = 0; r < NB; r++) pushes_q = pushes_q + PushBits'(push_q[r]);
    end
    assign room = (CountBits + 1)'(count) + (CountBits + 1)'(pushes_q) + (CountBits + 1)'(n1) <
                  (CountBits + 1)'(cfg_fifo_depth_i);
  end
  assign go = walk_q && room;
  // The last group reaches past Ymax (row j + n - 1 >= Ymax; N = 1: row j = Ymax); a tiny job's
  // ends after row 0 when row 1 has no span.
  logic past;
  if (NB == 1) begin : g_last1
    assign past = row_q == WB'(ymax_q);
  end else begin : g_lastn
    assign past = row_q + WB'(n1) >= WB'(ymax_q);
  end
  assign last = go && (past || (tiny_q && !tvalid_q[1]));

  // One span generator per row of the group; row r is j + r.
  for (genvar r = 0; r < NB; r++) begin : g_row
    logic gvalid, tv, tb, te1, inbox;
    logic [BB:0] gbegin, gend;
    logic [WB-1:0] row_r;
    trirast_improved2_span_generator u_gen (
      .state_i  ({st[2*(2*NB + r) +: 2], st[2*(NB + r) +: 2], st[2*r +: 2]}),
      .bound_i  ({bnd[(2*NB + r)*(BB+1) +: BB+1], bnd[(NB + r)*(BB+1) +: BB+1],
                  bnd[r*(BB+1) +: BB+1]}),
      .mirror_i (mirror),
      .xmax_i   (xmax_q),
      .valid_o  (gvalid),
      .begin_o  (gbegin),
      .end_o    (gend)
    );
    assign row_r = row_q + WB'(r);
    assign tv  = row_r[0] ? tvalid_q[1] : tvalid_q[0];
    assign tb  = row_r[0] ? tbegin_q[1] : tbegin_q[0];
    assign te1 = row_r[0] ? tend1_q[1] : tend1_q[0];
    // Rows of the group inside the box (N = 1: the row always is).
    assign inbox = (NB == 1) || ((r < 32'(n)) && (row_r <= WB'(ymax_q)));
    assign push_d[r] = go && inbox && (tiny_q ? tv : gvalid);
    // The span generator gives begin - 1 (two's complement) and end - 1, a tiny job begin and
    // end - 1 (te1 + 0): x0 + that + 1 with the carry-in from the low bit of {.., 1} + {.., cin}.
    logic [PB:0] xb_sum;
    logic [PB+1:0] xe_sum;
    assign xb_sum = {x0_q, 1'b1} + {tiny_q ? PB'(tb) : PB'($signed(gbegin)), !tiny_q};
    assign xe_sum = {1'b0, x0_q, 1'b1} + {tiny_q ? (PB + 1)'(te1) : (PB + 1)'(gend), 1'b1};
    assign data_d[r*EntryBits +: EntryBits] =
        {tag_q, y0_q + PB'(row_r), xb_sum[PB:1], xe_sum[PB+1:1]};
    logic unused_cin;
    assign unused_cin = ^{xb_sum[0], xe_sum[0]};
  end

  always_comb begin
    walk_d = walk_q;
    row_d  = row_q;
    if (load) begin
      walk_d = 1'b1;
      row_d  = '0;
    end else if (go) begin
      row_d = row_q + WB'(n);
      if (last) walk_d = 1'b0;
    end
  end

  `TRIRAST_FLOP_AR({walk_q, push_q}, {walk_d, push_d}, '0)
  always_ff @(posedge clk_i) begin
    row_q  <= row_d;
    if (load) begin
      tiny_q <= hand_tiny_i;
      tvalid_q <= hand_tiny_valid_i;
      tbegin_q <= hand_tiny_begin_i;
      tend1_q <= hand_tiny_end1_i;
    end
  end

  if (FifoRam && NB == 1) begin : g_fifo_ram
    trirast_span_fifo_ram #(
      .FifoDepth (FifoDepth),
      .EntryBits (EntryBits)
    ) u_fifo (
      .clk_i   (clk_i),
      .rst_ni  (rst_ni),
      .wr_i    (push_d[0]),
      .wdata_i (data_d),
      .push_i  (push_q[0]),
      .count_o (count),
      .valid_o (span_valid_o),
      .ready_i (span_ready_i),
      .data_o  (span_o)
    );
  end else begin : g_fifo_ff
    logic [NB*EntryBits-1:0] data_q;   // the registered push's spans
    always_ff @(posedge clk_i) begin
      data_q <= data_d;
    end
    trirast_span_fifo #(
      .NumEndpoints (NB),
      .FifoDepth    (FifoDepth),
      .EntryBits    (EntryBits)
    ) u_fifo (
      .clk_i   (clk_i),
      .rst_ni  (rst_ni),
      .push_i  (push_q),
      .data_i  (data_q),
      .count_o (count),
      .valid_o (span_valid_o),
      .ready_i (span_ready_i),
      .data_o  (span_o)
    );
  end

  // A job's first span (any_q: one went in an earlier row).
  logic any_q;
  always_ff @(posedge clk_i) begin
    if (load) any_q <= 1'b0;
    else if (push_d != '0) any_q <= 1'b1;
  end
  assign walk_o       = walk_q;
  assign stall_o      = walk_q && !go;
  assign last_o       = last;
  assign retire_o     = last && !any_q && (push_d == '0);
  assign tag_o        = tag_q;
  assign fifo_count_o = count;

  assign hand_ready_o = !walk_q;
  // A job walks, or its last spans are in the push register.
  assign busy_o = walk_q || (push_q != '0);

  // Cover points (docs/coverage.md): both states (idle, walking), a stall (no room in the FIFO),
  // a tiny job walked (its rows from the 2x2 test), with a span in its second row, and a job
  // retired without a span.
  `COVER(WalkIdle_C, !walk_q, clk_i, !rst_ni)
  `COVER(WalkWalk_C, walk_q, clk_i, !rst_ni)
  `COVER(WalkStall_C, stall_o, clk_i, !rst_ni)
  `COVER(WalkTinyJob_C, load && hand_tiny_i, clk_i, !rst_ni)
  `COVER(WalkTinyJobRow1Span_C, load && hand_tiny_i && hand_tiny_valid_i[1], clk_i, !rst_ni)
  `COVER(WalkRetireNoSpan_C, retire_o, clk_i, !rst_ni)

endmodule
