// gen2 study prototype (not a unit; scripts/gen2_study.sh): g2_walk_slice.sv (the retimed walk
// stage, N = 1, with the span FIFO) extended for the whole-unit prototype trirast_improved2_top.sv with a tiny
// job: a triangle whose box has at most 2 x 2 pixel centres comes with its rows' spans already
// decided by the direct 2x2 test (hand_tiny_i, per row j a valid bit and begin / end relative to
// x0: 0 or 1, 1 or 2). A tiny job takes the walk stage like any other (so spans leave in
// acceptance order) and emits its rows through the same registered push: one row per cycle, and
// it ends after row 0 when row 1 is empty or outside the box (a job without spans takes one cycle).
// The walkers load stale hand-off values for a tiny job; their outputs are not read.
// Build choices for the iCE40 fit (docs/gen2-design.md, "Fitting the HX8K"; the same cycles):
// FifoRam 1 keeps the span FIFO in block RAM (trirast_span_fifo_ram.sv) instead of flip-flops;
// WalkerCs 0 gives the walkers trirast_edge_walker2's carry-in step (one X' and one bound adder each).
module trirast_walk_stage2 #(
  parameter int FifoDepth = trirast_pkg::DefaultFifoDepth,
  parameter bit FifoRam   = 1'b0,
  parameter bit WalkerCs  = 1'b1,
  parameter int CountBits = $clog2(FifoDepth + 1)  // derived: do not override
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic                                  hand_valid_i,
  output logic                                  hand_ready_o,
  input  logic [trirast_pkg::TagBits-1:0]       hand_tag_i,
  input  logic [trirast_pkg::PixBits-1:0]       hand_x0_i,
  input  logic [trirast_pkg::PixBits-1:0]       hand_y0_i,
  input  logic [trirast_pkg::BoxBits-1:0]       hand_xmax_i,
  input  logic [trirast_pkg::BoxBits-1:0]       hand_ymax_i,
  input  logic [2:0]                            hand_mirror_i,
  input  logic [2:0]                            hand_dir_down_i,
  input  logic [3*trirast_pkg::StepBits-1:0]    hand_d_i,
  input  logic [3*trirast_pkg::QuotBits-1:0]    hand_qs_i,
  input  logic [3*trirast_pkg::RemBits-1:0]     hand_rs_i,
  input  logic [2:0]                            hand_ssat_i,
  input  logic [2:0]                            hand_enters_i,
  input  logic [3*trirast_pkg::RowBits-1:0]     hand_j_entry_i,
  input  logic [5:0]                            hand_entry_state_i,
  input  logic [3*trirast_pkg::WalkerXBits-1:0] hand_entry_x_i,
  input  logic [3*trirast_pkg::RemBits-1:0]     hand_entry_e_i,
  input  logic                                  hand_tiny_i,        // a tiny job (2x2 test)
  input  logic [1:0]                            hand_tiny_valid_i,  // row j has a span
  input  logic [1:0]                            hand_tiny_begin_i,  // row j: x_begin - x0 (0, 1)
  input  logic [1:0]                            hand_tiny_end1_i,   // row j: x_end - x0 - 1 (0, 1)
  input  logic [CountBits-1:0]                  cfg_fifo_depth_i,   // room: entries + push < this
  input  logic                                  span_ready_i,
  output logic                                  span_valid_o,
  output logic [trirast_pkg::TagBits+3*trirast_pkg::PixBits:0] span_o,
  output logic                                  busy_o,
  // ---- observation ----
  output logic                                  walk_o,     // a job walks
  output logic                                  stall_o,    // ... and its row waits for room
  output logic                                  last_o,     // its last row goes
  output logic                                  retire_o,   // ... and the job had no span
  output logic [trirast_pkg::TagBits-1:0]       tag_o,
  output logic [CountBits-1:0]                  fifo_count_o
);
  localparam int SB = trirast_pkg::StepBits;
  localparam int QB = trirast_pkg::QuotBits;
  localparam int RB = trirast_pkg::RemBits;
  localparam int WB = trirast_pkg::RowBits;
  localparam int XB = trirast_pkg::WalkerXBits;
  localparam int BB = trirast_pkg::BoxBits;
  localparam int PB = trirast_pkg::PixBits;
  localparam int TB = trirast_pkg::TagBits;
  localparam int EntryBits = TB + 3 * PB + 1;

  logic walk_q, walk_d, load, go, last;
  logic [TB-1:0] tag_q;
  logic [PB-1:0] x0_q, y0_q;
  logic [BB-1:0] xmax_q, ymax_q;
  logic [WB-1:0] row_q, row_d;
  logic [2:0] mirror;
  logic [5:0] st;
  logic [3*(BB+1)-1:0] bnd;
  logic tiny_q;
  logic [1:0] tvalid_q, tbegin_q, tend1_q;
  logic tv, tb, te1;

  assign load = !walk_q && hand_valid_i;

  for (genvar k = 0; k < 3; k++) begin : g_walker
    trirast_edge_walker2 #(.CarrySelect (WalkerCs)) u_walker (
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
      .entry_e_i     (hand_entry_e_i[k*RB +: RB]),
      .xmax_i        (hand_xmax_i),
      .adv_i         (go),
      .mirror_o      (mirror[k]),
      .row_state_o   (st[2*k +: 2]),
      .row_bound_o   (bnd[k*(BB+1) +: BB+1])
    );
  end

  logic gvalid;
  logic [BB:0] gbegin, gend;
  trirast_span_generator2 u_gen (
    .state_i  (st),
    .bound_i  (bnd),
    .mirror_i (mirror),
    .xmax_i   (xmax_q),
    .valid_o  (gvalid),
    .begin_o  (gbegin),
    .end_o    (gend)
  );

  // The registered push and its credit.
  logic push_q, push_d;
  logic [EntryBits-1:0] data_q, data_d;
  logic [CountBits-1:0] count;
  assign tv  = row_q[0] ? tvalid_q[1] : tvalid_q[0];
  assign tb  = row_q[0] ? tbegin_q[1] : tbegin_q[0];
  assign te1 = row_q[0] ? tend1_q[1] : tend1_q[0];
  assign go   = walk_q && ((CountBits + 1)'(count) + (CountBits + 1)'(push_q) <
                           (CountBits + 1)'(cfg_fifo_depth_i));
  assign last = go && ((row_q == WB'(ymax_q)) || (tiny_q && !tvalid_q[1]));
  assign push_d = go && (tiny_q ? tv : gvalid);
  assign data_d = tiny_q ?
      {tag_q, y0_q + PB'(row_q), x0_q + PB'(tb), {1'b0, x0_q} + (PB + 1)'({te1, ~te1})} :
      {tag_q, y0_q + PB'(row_q), x0_q + PB'(gbegin), {1'b0, x0_q} + (PB + 1)'(gend)};

  always_comb begin
    walk_d = walk_q;
    row_d  = row_q;
    if (load) begin
      walk_d = 1'b1;
      row_d  = '0;
    end else if (go) begin
      row_d = row_q + 1'b1;
      if (last) walk_d = 1'b0;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      walk_q <= 1'b0;
      push_q <= 1'b0;
    end else begin
      walk_q <= walk_d;
      push_q <= push_d;
    end
  end
  always_ff @(posedge clk_i) begin
    row_q  <= row_d;
    data_q <= data_d;
    if (load) begin
      tag_q  <= hand_tag_i;
      x0_q   <= hand_x0_i;
      y0_q   <= hand_y0_i;
      xmax_q <= hand_xmax_i;
      ymax_q <= hand_ymax_i;
      tiny_q <= hand_tiny_i;
      tvalid_q <= hand_tiny_valid_i;
      tbegin_q <= hand_tiny_begin_i;
      tend1_q <= hand_tiny_end1_i;
    end
  end

  if (FifoRam) begin : g_fifo_ram
    trirast_span_fifo_ram #(
      .FifoDepth (FifoDepth),
      .EntryBits (EntryBits)
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
  end else begin : g_fifo_ff
    trirast_span_fifo #(
      .NumEndpoints (1),
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
    else if (push_d) any_q <= 1'b1;
  end
  assign walk_o       = walk_q;
  assign stall_o      = walk_q && !go;
  assign last_o       = last;
  assign retire_o     = last && !any_q && !push_d;
  assign tag_o        = tag_q;
  assign fifo_count_o = count;

  assign hand_ready_o = !walk_q;
  assign busy_o = walk_q || push_q;   // a job walks, or its last span is in the push register

endmodule
