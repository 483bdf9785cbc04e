// gen2 study prototype (not a unit; scripts/gen2_study.sh): the walk stage retimed, N = 1, with
// the span FIFO: three trirast_improved2_edge_walker, trirast_improved2_span_generator, the span (with x0, y0 added) registered
// before the FIFO push, and the admission test counting the registered push as a credit:
// a row is processed when count + push_q + 1 <= DEPTH (count and push_q both registers), so no
// path runs from the walkers into the FIFO's pointers in one cycle. Cycle contract change against
// gen1 (docs/timing.md, "Walk stage"): a span enters the FIFO one cycle later (first-span and
// done cycles + 1 per triangle; throughput unchanged with an always-ready sink).
module g2_walk_slice #(
  parameter int FifoDepth = trirast_pkg::DefaultFifoDepth
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
  input  logic [3*(trirast_pkg::BoxBits+1)-1:0] hand_entry_b_i,   // the walkers' bounds - 1
  input  logic [3*trirast_pkg::RemBits-1:0]     hand_entry_e_i,
  input  logic                                  span_ready_i,
  output logic                                  span_valid_o,
  output logic [trirast_pkg::TagBits+3*trirast_pkg::PixBits:0] span_o,
  output logic                                  busy_o
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
  localparam int CountBits = $clog2(FifoDepth + 1);

  logic walk_q, walk_d, load, go, last;
  logic [TB-1:0] tag_q;
  logic [PB-1:0] x0_q, y0_q;
  logic [BB-1:0] xmax_q, ymax_q;
  logic [WB-1:0] row_q, row_d;
  logic [2:0] mirror;
  logic [5:0] st;
  logic [3*(BB+1)-1:0] bnd;

  assign load = !walk_q && hand_valid_i;

  for (genvar k = 0; k < 3; k++) begin : g_walker
    trirast_improved2_edge_walker u_walker (
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
      .mirror_o      (mirror[k]),
      .row_state_o   (st[2*k +: 2]),
      .row_bound_o   (bnd[k*(BB+1) +: BB+1])
    );
  end

  logic gvalid;
  logic [BB:0] gbegin, gend;
  trirast_improved2_span_generator u_gen (
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
  assign go   = walk_q && (32'(count) + 32'(push_q) + 1 <= FifoDepth);
  assign last = go && (row_q == WB'(ymax_q));
  assign push_d = go && gvalid;
  // the span generator gives begin - 1 (two's complement) and end - 1
  assign data_d = {tag_q, y0_q + PB'(row_q), x0_q + PB'($signed(gbegin)) + 1'b1,
                   {1'b0, x0_q} + (PB + 1)'(gend) + 1'b1};

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
    end
  end

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

  assign hand_ready_o = !walk_q;
  assign busy_o = walk_q;

endmodule
