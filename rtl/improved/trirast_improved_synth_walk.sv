// Registered wrapper of the walk stage for place and route (scripts/synth.sh: per-stage Fmax; not
// part of the unit). WithFifo = 0: trirast_improved_walk_stage alone, its FIFO occupancy input from a
// register and its pushes captured by registers. WithFifo = 1: the walk stage and the span FIFO
// connected as in trirast_improved_top, because the pushes are combinational from the walkers into the
// FIFO's pointers, count and storage (a path that crosses the boundary and is only timed when both
// are placed together). The registers around them are trirast_synth_shell's, so the timing paths
// are the stages' own. NumEndpoints and FifoDepth are the synthesized defaults and the runtime n
// and DEPTH are tied to them, as in the whole unit's wrapper (scripts/synth.sh).
`include "trirast_ports.svh"

module trirast_improved_synth_walk #(
  parameter int WithFifo = 0
) (
  input  logic clk_i, rst_ni,
  input  logic shift_i, din_i, load_i,  // trirast_synth_shell's serial port
  output logic dout_o
);
  localparam int N = trirast_pkg::DefaultEndpoints;
  localparam int Depth = trirast_pkg::DefaultFifoDepth;
  localparam int CountBits = $clog2(Depth + 1);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  localparam int EntryBits = TB + 3 * PB + 1;
  // The hand-off bundle: {tag, x0, y0, xmax, ymax, mirror, dir_down, d, qs, rs, ssat, enters,
  // j_entry, entry_state, entry_x, entry_e}.
  localparam int HandBits = TB + 2 * PB + 2 * BB + 3 * SB + 3 * QB + 6 * RB + 3 * WB + 3 * XB + 18;
  // {hand_valid, bundle, fifo_count (alone) or span_ready (with the FIFO)}
  localparam int InBits = 1 + HandBits + (WithFifo != 0 ? 1 : CountBits);
  // {hand_ready, busy, stall, last, retire, tag, row} + {push, push_data} or
  // {fifo_count, span_valid, head}
  localparam int OutBits = 5 + TB + WB + (WithFifo != 0 ? CountBits + 1 + EntryBits :
                                                          N + N * EntryBits);

  logic [InBits-1:0] dut_in;     // the stages' inputs, from the shell's input register
  logic [OutBits-1:0] dut_out;   // their outputs, into the shell's output register
  trirast_synth_shell #(.InBits (InBits), .OutBits (OutBits)) u_shell (
    .clk_i (clk_i), .shift_i (shift_i), .din_i (din_i), .load_i (load_i),
    .dout_o (dout_o), .in_q_o (dut_in), .out_d_i (dut_out));

  logic [HandBits-1:0] hand;
  assign hand = dut_in[InBits-2 -: HandBits];

  logic hand_ready, busy, stall, last, retire;
  logic [TB-1:0] tag;
  logic [WB-1:0] row;
  logic [N-1:0] push;
  logic [N*EntryBits-1:0] push_data;
  logic [CountBits-1:0] fifo_count;

  trirast_improved_walk_stage #(
    .NumEndpoints (N),
    .CountBits    (CountBits),
    .EntryBits    (EntryBits)
  ) u_walk (
    .clk_i              (clk_i),
    .rst_ni             (rst_ni),
    .endpoints_i        (3'(N)),
    .fifo_depth_i       (CountBits'(Depth)),
    .hand_valid_i       (dut_in[InBits-1]),
    .hand_ready_o       (hand_ready),
    .hand_tag_i         (hand[HandBits-1 -: TB]),
    .hand_x0_i          (hand[HandBits-1-TB -: PB]),
    .hand_y0_i          (hand[HandBits-1-TB-PB -: PB]),
    .hand_xmax_i        (hand[HandBits-1-TB-2*PB -: BB]),
    .hand_ymax_i        (hand[HandBits-1-TB-2*PB-BB -: BB]),
    .hand_mirror_i      (hand[HandBits-1-TB-2*PB-2*BB -: 3]),
    .hand_dir_down_i    (hand[HandBits-4-TB-2*PB-2*BB -: 3]),
    .hand_d_i           (hand[6*RB+3*XB+6+3*WB+6+3*QB +: 3*SB]),
    .hand_qs_i          (hand[6*RB+3*XB+6+3*WB+6 +: 3*QB]),
    .hand_rs_i          (hand[3*RB+3*XB+6+3*WB+6 +: 3*RB]),
    .hand_ssat_i        (hand[3*RB+3*XB+6+3*WB+3 +: 3]),
    .hand_enters_i      (hand[3*RB+3*XB+6+3*WB +: 3]),
    .hand_j_entry_i     (hand[3*RB+3*XB+6 +: 3*WB]),
    .hand_entry_state_i (hand[3*RB+3*XB +: 6]),
    .hand_entry_x_i     (hand[3*RB +: 3*XB]),
    .hand_entry_e_i     (hand[0 +: 3*RB]),
    .fifo_count_i       (fifo_count),
    .push_o             (push),
    .push_data_o        (push_data),
    .busy_o             (busy),
    .stall_o            (stall),
    .last_o             (last),
    .retire_o           (retire),
    .tag_o              (tag),
    .row_o              (row)
  );

  if (WithFifo != 0) begin : g_fifo
    logic span_valid;
    logic [EntryBits-1:0] head;
    trirast_span_port #(.NumEndpoints (N), .FifoDepth (Depth)) u_span_port (
      .clk_i (clk_i), .rst_ni (rst_ni),
      .push_i (push), .push_data_i (push_data), .count_o (fifo_count),
      .span_valid_o (span_valid), .span_ready_i (dut_in[0]),
      .span_tag_o (head[EntryBits-1 -: TB]),
      .span_y_o (head[3*PB -: PB]), .span_x_begin_o (head[2*PB -: PB]), .span_x_end_o (head[PB:0]));
    assign dut_out = {hand_ready, busy, stall, last, retire, tag, row, fifo_count, span_valid,
                      head};
  end else begin : g_alone
    assign fifo_count = dut_in[CountBits-1:0];
    assign dut_out = {hand_ready, busy, stall, last, retire, tag, row, push, push_data};
  end

endmodule
