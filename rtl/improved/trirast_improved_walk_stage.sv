// The walk stage (docs/timing.md, "Walk stage"): three edge walkers and NumEndpoints span
// generators, FSM StWalkIdle -> StWalk. Loaded at the hand-off in cycle h, it walks from h + 1:
// each StWalk cycle processes the next group of n rows (n = cfg_endpoints_i <= NumEndpoints)
// when the FIFO held at most DEPTH - n spans at the start of the cycle, else it stalls.
`include "trirast_ports.svh"

`include "trirast_assert.svh"
module trirast_improved_walk_stage #(
  parameter int NumEndpoints = 1,
  parameter int CountBits = 4,      // bits of the FIFO occupancy and of the runtime depth
  parameter int EntryBits = 8       // bits of one FIFO entry {tag, y, x_begin, x_end}
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  // ---- configuration ----
  input  logic [2:0]                            endpoints_i,   // n: rows per group (1..N)
  input  logic [CountBits-1:0]                  fifo_depth_i,  // DEPTH (n..FifoDepth)
  // ---- hand-off from the setup stage ----
  input  logic                                  hand_valid_i,
  output logic                                  hand_ready_o,  // StWalkIdle
  `TRIRAST_HANDOFF_BOX(input, _i),
  `TRIRAST_IMPROVED_HANDOFF_EDGES(input, _i),
  input  logic [3*trirast_pkg::RemBits-1:0]     hand_entry_e_i,
  // ---- pushes into the span FIFO ----
  input  logic [CountBits-1:0]                  fifo_count_i,  // occupancy at the cycle's start
  output logic [NumEndpoints-1:0]               push_o,        // row r of the group has a span
  output logic [NumEndpoints*EntryBits-1:0]     push_data_o,   // {tag, y, x_begin, x_end}
  // ---- observation ----
  output logic                                  busy_o,        // StWalk
  output logic                                  stall_o,       // StWalk, no room: a stall cycle
  output logic                                  last_o,        // processes the last group
  output logic                                  retire_o,      // last group, no span at all
  output logic [trirast_pkg::TagBits-1:0]       tag_o,         // the walked triangle
  output logic [trirast_pkg::RowBits-1:0]       row_o          // first row of the group
);
  `TRIRAST_PKG_NAMES
  localparam int CountExtBits = CountBits + 1;
  localparam int Pix1Bits = PixBits + 1;

  typedef enum logic {
    StWalkIdle = 1'b0,
    StWalk     = 1'b1
  } walk_state_e;

  walk_state_e state_q, state_d;
  logic [TagBits-1:0] tag_q, tag_d;
  logic [PixBits-1:0] x0_q, x0_d, y0_q, y0_d;
  logic [BoxBits-1:0] xmax_q, xmax_d, ymax_q, ymax_d;
  logic [RowBits-1:0] row_q, row_d;   // first row of the next group
  logic any_q, any_d;                 // the triangle pushed a span already
  logic load, room, go;
  logic [RowBits-1:0] row_end;        // one past the group's last row

  logic [2:0] mirror;
  logic [2*NumEndpoints-1:0] wst [3];
  logic [NumEndpoints*WalkerXBits-1:0] wx [3];

  for (genvar k = 0; k < 3; k++) begin : g_walker
    trirast_improved_edge_walker #(
      .NumEndpoints (NumEndpoints)
    ) u_walker (
      .clk_i         (clk_i),
      .rst_ni        (rst_ni),
      .load_i        (load),
      .mirror_i      (hand_mirror_i[k]),
      .dir_down_i    (hand_dir_down_i[k]),
      .d_i           (hand_d_i[k*StepBits +: StepBits]),
      .qs_i          (hand_qs_i[k*QuotBits +: QuotBits]),
      .rs_i          (hand_rs_i[k*RemBits +: RemBits]),
      .ssat_i        (hand_ssat_i[k]),
      .enters_i      (hand_enters_i[k]),
      .j_entry_i     (hand_j_entry_i[k*RowBits +: RowBits]),
      .entry_state_i (hand_entry_state_i[2*k +: 2]),
      .entry_x_i     (hand_entry_x_i[k*WalkerXBits +: WalkerXBits]),
      .entry_e_i     (hand_entry_e_i[k*RemBits +: RemBits]),
      .xmax_i        (xmax_q),
      .row_i         (row_q),
      .adv_i         (go),
      .adv_rows_i    (endpoints_i),
      .mirror_o      (mirror[k]),
      .row_state_o   (wst[k]),
      .row_x_o       (wx[k])
    );
  end

  // One span generator per row of the group.
  logic [NumEndpoints-1:0] gen_valid;
  logic [BoxBits:0] gen_begin [NumEndpoints];
  logic [BoxBits:0] gen_end [NumEndpoints];

  for (genvar r = 0; r < NumEndpoints; r++) begin : g_row
    trirast_improved_span_generator u_span_generator (
      .state_i  ({wst[2][2*r +: 2], wst[1][2*r +: 2], wst[0][2*r +: 2]}),
      .x_i      ({wx[2][r*WalkerXBits +: WalkerXBits], wx[1][r*WalkerXBits +: WalkerXBits], wx[0][r*WalkerXBits +: WalkerXBits]}),
      .mirror_i (mirror),
      .xmax_i   (xmax_q),
      .valid_o  (gen_valid[r]),
      .begin_o  (gen_begin[r]),
      .end_o    (gen_end[r])
    );
  end

  // The group's rows: span r is row j + r, pushed when it lies in the box and has a span.
  for (genvar r = 0; r < NumEndpoints; r++) begin : g_push
    logic [RowBits-1:0] row_r;
    logic [PixBits-1:0] span_y, span_xb;
    logic [PixBits:0] span_xe;
    assign row_r   = row_q + RowBits'(r);
    assign span_y  = y0_q + PixBits'(row_r);
    assign span_xb = x0_q + PixBits'(gen_begin[r]);
    assign span_xe = {1'b0, x0_q} + Pix1Bits'(gen_end[r]);
    // Rows of the group inside the box (the last group may be shorter).
    assign push_o[r] = go && gen_valid[r] && (r < 32'(endpoints_i)) &&
                       (row_r <= RowBits'(ymax_q));
    assign push_data_o[r*EntryBits +: EntryBits] = {tag_q, span_y, span_xb, span_xe};
  end

  always_comb begin
    load = (state_q == StWalkIdle) && hand_valid_i;
    // Room for a whole group: count <= DEPTH - n (count at the start of the cycle).
    room = CountExtBits'(fifo_count_i) + CountExtBits'(endpoints_i) <=
           CountExtBits'(fifo_depth_i);
    go      = (state_q == StWalk) && room;
    row_end = row_q + RowBits'(endpoints_i);
    // The last group: it reaches past Ymax.
    last_o  = go && (row_end > RowBits'(ymax_q));
  end

  always_comb begin
    retire_o = last_o && !any_q && (push_o == '0);
    state_d = state_q;
    {tag_d, x0_d, y0_d, xmax_d, ymax_d, row_d, any_d} =
        {tag_q, x0_q, y0_q, xmax_q, ymax_q, row_q, any_q};
    unique case (state_q)
      StWalkIdle: begin
        if (load) begin
          state_d = StWalk;
          `TRIRAST_LOAD_HANDOFF_BOX
          row_d   = '0;
          any_d   = 1'b0;
        end
      end
      StWalk: begin
        if (go) begin
          row_d = row_end;
          any_d = any_q || (push_o != '0);
          if (last_o) state_d = StWalkIdle;
        end
      end
      default: state_d = StWalkIdle;
    endcase
  end

  `TRIRAST_FLOP_AR(state_q, state_d, StWalkIdle)

  // Datapath registers: no reset (loaded at the hand-off).
  always_ff @(posedge clk_i) begin
    {tag_q, x0_q, y0_q, xmax_q, ymax_q, row_q, any_q} <=
        {tag_d, x0_d, y0_d, xmax_d, ymax_d, row_d, any_d};
  end

  assign hand_ready_o = state_q == StWalkIdle;
  assign busy_o       = state_q == StWalk;
  assign stall_o      = (state_q == StWalk) && !room;
  assign tag_o        = tag_q;
  assign row_o        = row_q;

  // Cover points (docs/coverage.md): both states, a stall (no room for a group in the FIFO), a
  // triangle retired without a span, and what each edge says about the group's first row
  // (out, bound, clear) while it goes.
  `COVER(WalkStWalkIdle_C, state_q == StWalkIdle, clk_i, !rst_ni)
  `COVER(WalkStWalk_C, state_q == StWalk, clk_i, !rst_ni)
  `COVER(WalkStall_C, stall_o, clk_i, !rst_ni)
  `COVER(WalkRetireNoSpan_C, retire_o, clk_i, !rst_ni)
  for (genvar k = 0; k < 3; k++) begin : g_cover_edge
    `COVER(WalkRowOut_C, go && wst[k][1:0] == RowOut, clk_i, !rst_ni)
    `COVER(WalkRowBound_C, go && wst[k][1:0] == RowBound, clk_i, !rst_ni)
    `COVER(WalkRowClear_C, go && wst[k][1:0] == RowClear, clk_i, !rst_ni)
  end

endmodule
