// Registered wrapper of trirast_top for place and route (scripts/synth.sh, Fmax only; not part
// of the unit). Every input and output goes through a flip-flop, so the timing paths are the
// unit's own. The wide triangle port is loaded through a 1-bit shift register and the outputs
// are folded into a few pins, so the design fits the package's I/O.
module trirast_synth_wrapper (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic shift_i,       // shift one bit of the triangle / configuration word in
  input  logic din_i,         // the bit
  input  logic tri_valid_i,
  input  logic span_ready_i,
  output logic tri_ready_o,
  output logic span_valid_o,
  output logic [3:0] fold_o   // XOR fold of the span and observation outputs
);
  localparam int P = trirast_pkg::VertexBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int PB = trirast_pkg::PixBits;
  localparam int TB = trirast_pkg::TagBits;
  localparam int WordBits = TB + 6 * P + 6 * CB + 3 * EB + 3 + 2 * PB + 2;
  localparam int CountBits = $clog2(trirast_pkg::DefaultFifoDepth + 1);

  logic [WordBits-1:0] word_q, word_d;
  logic tri_valid_q, span_ready_q, tri_ready_q, span_valid_q;
  logic [3:0] fold_q, fold_d;

  logic tri_ready, span_valid;
  logic [TB-1:0] span_tag, box_tag, walk_tag;
  logic [PB-1:0] span_y, span_xb;
  logic [PB:0] span_xe;
  logic box_retire, walk_busy, walk_stall, walk_last, walk_retire;
  logic [CountBits-1:0] fifo_count;
  logic [TB+3*PB+1+2*TB+5+CountBits-1:0] obs;

  trirast_top u_top (
    .clk_i            (clk_i),
    .rst_ni           (rst_ni),
    .cfg_vp_xmax_i    (word_q[WordBits-1 -: PB]),
    .cfg_vp_ymax_i    (word_q[WordBits-1-PB -: PB]),
    .cfg_divide_i     (word_q[1]),
    .cfg_adaptive_i   (word_q[0]),
    .cfg_endpoints_i  (3'd1),
    .cfg_fifo_depth_i (CountBits'(trirast_pkg::DefaultFifoDepth)),
    .tri_valid_i      (tri_valid_q),
    .tri_ready_o      (tri_ready),
    .tri_tag_i        (word_q[2 +: TB]),
    .tri_vx_i         (word_q[2 + TB +: 3 * P]),
    .tri_vy_i         (word_q[2 + TB + 3 * P +: 3 * P]),
    .tri_a_i          (word_q[2 + TB + 6 * P +: 3 * CB]),
    .tri_b_i          (word_q[2 + TB + 6 * P + 3 * CB +: 3 * CB]),
    .tri_c_i          (word_q[2 + TB + 6 * P + 6 * CB +: 3 * EB]),
    .tri_bias_i       (word_q[2 + TB + 6 * P + 6 * CB + 3 * EB +: 3]),
    .span_valid_o     (span_valid),
    .span_ready_i     (span_ready_q),
    .span_tag_o       (span_tag),
    .span_y_o         (span_y),
    .span_x_begin_o   (span_xb),
    .span_x_end_o     (span_xe),
    .box_retire_o     (box_retire),
    .box_retire_tag_o (box_tag),
    .walk_busy_o      (walk_busy),
    .walk_stall_o     (walk_stall),
    .walk_last_o      (walk_last),
    .walk_retire_o    (walk_retire),
    .walk_tag_o       (walk_tag),
    .fifo_count_o     (fifo_count)
  );

  always_comb begin
    word_d = shift_i ? {word_q[WordBits-2:0], din_i} : word_q;
    obs    = {span_tag, span_y, span_xb, span_xe, box_tag, walk_tag, box_retire, walk_busy,
              walk_stall, walk_last, walk_retire, fifo_count};
    fold_d = '0;
    for (int i = 0; i < $bits(obs); i++) fold_d[i % 4] = fold_d[i % 4] ^ obs[i];
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      word_q       <= '0;
      tri_valid_q  <= 1'b0;
      span_ready_q <= 1'b0;
      tri_ready_q  <= 1'b0;
      span_valid_q <= 1'b0;
      fold_q       <= '0;
    end else begin
      word_q       <= word_d;
      tri_valid_q  <= tri_valid_i;
      span_ready_q <= span_ready_i;
      tri_ready_q  <= tri_ready;
      span_valid_q <= span_valid;
      fold_q       <= fold_d;
    end
  end

  assign tri_ready_o  = tri_ready_q;
  assign span_valid_o = span_valid_q;
  assign fold_o       = fold_q;

endmodule
