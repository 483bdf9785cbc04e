// The walk stage (docs/timing.md, "Walk stage"): three edge walkers and NumEndpoints span
// generators, FSM StWalkIdle -> StWalk. Loaded at the hand-off in cycle h, it walks from h + 1:
// each StWalk cycle processes the next group of n rows (n = cfg_endpoints_i <= NumEndpoints)
// when the FIFO held at most DEPTH - n spans at the start of the cycle, else it stalls.
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
  localparam int StepBits = trirast_pkg::StepBits;
  localparam int QuotBits = trirast_pkg::QuotBits;
  localparam int RemBits = trirast_pkg::RemBits;
  localparam int RowBits = trirast_pkg::RowBits;
  localparam int XBits = trirast_pkg::WalkerXBits;
  localparam int BoxBits = trirast_pkg::BoxBits;
  localparam int PixBits = trirast_pkg::PixBits;
  localparam int TagBits = trirast_pkg::TagBits;
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
  logic [NumEndpoints*XBits-1:0] wx [3];

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
      .entry_x_i     (hand_entry_x_i[k*XBits +: XBits]),
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
      .x_i      ({wx[2][r*XBits +: XBits], wx[1][r*XBits +: XBits], wx[0][r*XBits +: XBits]}),
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
    tag_d   = tag_q;
    x0_d    = x0_q;
    y0_d    = y0_q;
    xmax_d  = xmax_q;
    ymax_d  = ymax_q;
    row_d   = row_q;
    any_d   = any_q;
    unique case (state_q)
      StWalkIdle: begin
        if (load) begin
          state_d = StWalk;
          tag_d   = hand_tag_i;
          x0_d    = hand_x0_i;
          y0_d    = hand_y0_i;
          xmax_d  = hand_xmax_i;
          ymax_d  = hand_ymax_i;
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

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= StWalkIdle;
    end else begin
      state_q <= state_d;
    end
  end

  // Datapath registers: no reset (loaded at the hand-off).
  always_ff @(posedge clk_i) begin
    tag_q  <= tag_d;
    x0_q   <= x0_d;
    y0_q   <= y0_d;
    xmax_q <= xmax_d;
    ymax_q <= ymax_d;
    row_q  <= row_d;
    any_q  <= any_d;
  end

  assign hand_ready_o = state_q == StWalkIdle;
  assign busy_o       = state_q == StWalk;
  assign stall_o      = (state_q == StWalk) && !room;
  assign tag_o        = tag_q;
  assign row_o        = row_q;

endmodule
