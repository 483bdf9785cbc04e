// Registered wrapper of the setup stage alone for place and route (scripts/synth.sh: per-stage
// Fmax; not part of the unit). Every input of trirast_setup_stage is a bit of a shift register
// (loaded serially through din_i), every output is captured by a flip-flop with no logic in
// between and read back through a second, serial shift register, so the timing paths are the
// stage's own: register -> stage logic -> register. The hand-off's hand_ready_i is a register, as
// in the unit (the walk stage's state).
module trirast_synth_setup (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic shift_i,   // shift the input word by one bit
  input  logic din_i,     // the bit shifted in
  input  logic load_i,    // copy the captured outputs into the output shift register
  output logic dout_o     // the output shift register's last bit
);
  localparam int P = trirast_pkg::VertexBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int PB = trirast_pkg::PixBits;
  localparam int TB = trirast_pkg::TagBits;
  localparam int BB = trirast_pkg::BoxBits;
  localparam int SB = trirast_pkg::StepBits;
  localparam int QB = trirast_pkg::QuotBits;
  localparam int RB = trirast_pkg::RemBits;
  localparam int WB = trirast_pkg::RowBits;
  localparam int XB = trirast_pkg::WalkerXBits;
  // {vp_xmax, vp_ymax, divide, adaptive, tri_valid, hand_ready, tag, vx, vy, a, b, c, bias}
  localparam int InBits = 2 * PB + 4 + TB + 6 * P + 6 * CB + 3 * EB + 3;
  localparam int OutBits = 2 * TB + 2 * PB + 2 * BB + 3 * SB + 3 * QB + 6 * RB + 3 * WB +
                           3 * XB + 27;

  logic [InBits-1:0] in_q;
  logic [OutBits-1:0] out_d, out_q, sh_q;

  logic tri_ready, box_retire, hand_valid;
  logic [TB-1:0] box_retire_tag, hand_tag;
  logic [PB-1:0] hand_x0, hand_y0;
  logic [BB-1:0] hand_xmax, hand_ymax;
  logic [2:0] hand_mirror, hand_dir_down, hand_ssat, hand_enters, state, lane_busy;
  logic [3*SB-1:0] hand_d;
  logic [3*QB-1:0] hand_qs;
  logic [3*RB-1:0] hand_rs, hand_entry_e;
  logic [3*WB-1:0] hand_j_entry;
  logic [5:0] hand_entry_state;
  logic [3*XB-1:0] hand_entry_x;

  trirast_setup_stage u_setup (
    .clk_i              (clk_i),
    .rst_ni             (rst_ni),
    .vp_xmax_i          (in_q[InBits-1 -: PB]),
    .vp_ymax_i          (in_q[InBits-1-PB -: PB]),
    .divide_i           (in_q[InBits-1-2*PB]),
    .adaptive_i         (in_q[InBits-2-2*PB]),
    .tri_valid_i        (in_q[InBits-3-2*PB]),
    .tri_ready_o        (tri_ready),
    .tri_tag_i          (in_q[3 + 3 * EB + 6 * CB + 6 * P +: TB]),
    .tri_vx_i           (in_q[3 + 3 * EB + 6 * CB + 3 * P +: 3 * P]),
    .tri_vy_i           (in_q[3 + 3 * EB + 6 * CB +: 3 * P]),
    .tri_a_i            (in_q[3 + 3 * EB + 3 * CB +: 3 * CB]),
    .tri_b_i            (in_q[3 + 3 * EB +: 3 * CB]),
    .tri_c_i            (in_q[3 +: 3 * EB]),
    .tri_bias_i         (in_q[2:0]),
    .box_retire_o       (box_retire),
    .box_retire_tag_o   (box_retire_tag),
    .hand_valid_o       (hand_valid),
    .hand_ready_i       (in_q[InBits-4-2*PB]),
    .hand_tag_o         (hand_tag),
    .hand_x0_o          (hand_x0),
    .hand_y0_o          (hand_y0),
    .hand_xmax_o        (hand_xmax),
    .hand_ymax_o        (hand_ymax),
    .hand_mirror_o      (hand_mirror),
    .hand_dir_down_o    (hand_dir_down),
    .hand_d_o           (hand_d),
    .hand_qs_o          (hand_qs),
    .hand_rs_o          (hand_rs),
    .hand_ssat_o        (hand_ssat),
    .hand_enters_o      (hand_enters),
    .hand_j_entry_o     (hand_j_entry),
    .hand_entry_state_o (hand_entry_state),
    .hand_entry_x_o     (hand_entry_x),
    .hand_entry_e_o     (hand_entry_e),
    .state_o            (state),
    .lane_busy_o        (lane_busy)
  );

  assign out_d = {tri_ready, box_retire, box_retire_tag, hand_valid, hand_tag, hand_x0, hand_y0,
                  hand_xmax, hand_ymax, hand_mirror, hand_dir_down, hand_d, hand_qs, hand_rs,
                  hand_ssat, hand_enters, hand_j_entry, hand_entry_state, hand_entry_x,
                  hand_entry_e, state, lane_busy};

  // Wrapper registers: no reset (the stage's own control registers are reset through rst_ni).
  always_ff @(posedge clk_i) begin
    if (shift_i) in_q <= {in_q[InBits-2:0], din_i};
    out_q <= out_d;
    if (load_i) sh_q <= out_q;
    else sh_q <= {1'b0, sh_q[OutBits-1:1]};
  end

  assign dout_o = sh_q[0];

endmodule
