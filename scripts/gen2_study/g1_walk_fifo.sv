// gen2 study reference (not a unit; scripts/gen2_study.sh): the first generation's walk stage
// (rtl/improved/trirast_improved_walk_stage.sv, N = 1) and span FIFO connected as in rtl/improved/trirast_improved_top.sv (the push
// combinational from the walkers into the FIFO), with g2_walk_slice's ports, so that both are
// measured the same way.
module g1_walk_fifo #(
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
  input  logic [3*trirast_pkg::RemBits-1:0]     hand_entry_e_i,
  input  logic                                  span_ready_i,
  output logic                                  span_valid_o,
  output logic [trirast_pkg::TagBits+3*trirast_pkg::PixBits:0] span_o,
  output logic                                  busy_o
);
  localparam int TB = trirast_pkg::TagBits;
  localparam int PB = trirast_pkg::PixBits;
  localparam int EntryBits = TB + 3 * PB + 1;
  localparam int CountBits = $clog2(FifoDepth + 1);
  logic push;
  logic [EntryBits-1:0] push_data;
  logic [CountBits-1:0] count;
  logic stall, last, retire;
  logic [TB-1:0] tag;
  logic [trirast_pkg::RowBits-1:0] row;
  /* verilator lint_off PINCONNECTEMPTY */
  trirast_improved_walk_stage #(
    .NumEndpoints (1),
    .CountBits    (CountBits),
    .EntryBits    (EntryBits)
  ) u_walk (
    .clk_i (clk_i), .rst_ni (rst_ni),
    .endpoints_i (3'd1), .fifo_depth_i (CountBits'(FifoDepth)),
    .hand_valid_i (hand_valid_i), .hand_ready_o (hand_ready_o),
    .hand_tag_i (hand_tag_i), .hand_x0_i (hand_x0_i), .hand_y0_i (hand_y0_i),
    .hand_xmax_i (hand_xmax_i), .hand_ymax_i (hand_ymax_i),
    .hand_mirror_i (hand_mirror_i), .hand_dir_down_i (hand_dir_down_i),
    .hand_d_i (hand_d_i), .hand_qs_i (hand_qs_i), .hand_rs_i (hand_rs_i),
    .hand_ssat_i (hand_ssat_i), .hand_enters_i (hand_enters_i),
    .hand_j_entry_i (hand_j_entry_i), .hand_entry_state_i (hand_entry_state_i),
    .hand_entry_x_i (hand_entry_x_i), .hand_entry_e_i (hand_entry_e_i),
    .fifo_count_i (count), .push_o (push), .push_data_o (push_data),
    .busy_o (busy_o), .stall_o (stall), .last_o (last), .retire_o (retire),
    .tag_o (tag), .row_o (row));
  /* verilator lint_on PINCONNECTEMPTY */
  trirast_span_fifo #(
    .NumEndpoints (1), .FifoDepth (FifoDepth), .EntryBits (EntryBits)
  ) u_fifo (
    .clk_i (clk_i), .rst_ni (rst_ni), .push_i (push), .data_i (push_data),
    .count_o (count), .valid_o (span_valid_o), .ready_i (span_ready_i), .data_o (span_o));
endmodule
