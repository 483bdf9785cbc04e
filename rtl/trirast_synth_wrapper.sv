// Registered wrapper of trirast_top for place and route (scripts/synth.sh, Fmax only; not part
// of the unit). Every input is a bit of a shift register loaded serially through din_i (the
// triangle, the configuration, tri_valid_i, span_ready_i); every output is captured by a flip-flop
// with no logic in between and read back through a second, serial shift register. So the timing
// paths are the unit's own (register -> unit logic -> register), and the design needs five pins.
// NumEndpoints and FifoDepth are the defaults; the runtime n and DEPTH are tied to them.
module trirast_synth_wrapper (
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
  localparam int CountBits = $clog2(trirast_pkg::DefaultFifoDepth + 1);
  // {vp_xmax, vp_ymax, divide, adaptive, tri_valid, span_ready, tag, vx, vy, a, b, c, bias}
  localparam int InBits = 2 * PB + 4 + TB + 6 * P + 6 * CB + 3 * EB + 3;
  // {tri_ready, span_valid, span, box_retire, box tag, walk busy/stall/last/retire, walk tag, count}
  localparam int OutBits = 2 + TB + 3 * PB + 1 + 1 + TB + 4 + TB + CountBits;

  logic [InBits-1:0] in_q;
  logic [OutBits-1:0] out_d, out_q, sh_q;

  logic tri_ready, span_valid;
  logic [TB-1:0] span_tag, box_tag, walk_tag;
  logic [PB-1:0] span_y, span_xb;
  logic [PB:0] span_xe;
  logic box_retire, walk_busy, walk_stall, walk_last, walk_retire;
  logic [CountBits-1:0] fifo_count;

  trirast_top u_top (
    .clk_i            (clk_i),
    .rst_ni           (rst_ni),
    .cfg_vp_xmax_i    (in_q[InBits-1 -: PB]),
    .cfg_vp_ymax_i    (in_q[InBits-1-PB -: PB]),
    .cfg_divide_i     (in_q[InBits-1-2*PB]),
    .cfg_adaptive_i   (in_q[InBits-2-2*PB]),
    .cfg_endpoints_i  (3'(trirast_pkg::DefaultEndpoints)),
    .cfg_fifo_depth_i (CountBits'(trirast_pkg::DefaultFifoDepth)),
    .tri_valid_i      (in_q[InBits-3-2*PB]),
    .tri_ready_o      (tri_ready),
    .tri_tag_i        (in_q[3 + 3 * EB + 6 * CB + 6 * P +: TB]),
    .tri_vx_i         (in_q[3 + 3 * EB + 6 * CB + 3 * P +: 3 * P]),
    .tri_vy_i         (in_q[3 + 3 * EB + 6 * CB +: 3 * P]),
    .tri_a_i          (in_q[3 + 3 * EB + 3 * CB +: 3 * CB]),
    .tri_b_i          (in_q[3 + 3 * EB +: 3 * CB]),
    .tri_c_i          (in_q[3 +: 3 * EB]),
    .tri_bias_i       (in_q[2:0]),
    .span_valid_o     (span_valid),
    .span_ready_i     (in_q[InBits-4-2*PB]),
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

  assign out_d = {tri_ready, span_valid, span_tag, span_y, span_xb, span_xe, box_retire, box_tag,
                  walk_busy, walk_stall, walk_last, walk_retire, walk_tag, fifo_count};

  // Wrapper registers: no reset (the unit's own control registers are reset through rst_ni).
  always_ff @(posedge clk_i) begin
    if (shift_i) in_q <= {in_q[InBits-2:0], din_i};
    out_q <= out_d;
    if (load_i) sh_q <= out_q;
    else sh_q <= {1'b0, sh_q[OutBits-1:1]};
  end

  assign dout_o = sh_q[0];

endmodule
