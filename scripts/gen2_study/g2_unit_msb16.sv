// gen2 study prototype (scripts/gen2_study.sh, row g2.unit_msb16): trirast_improved2_top with the MSB-first
// radix-16 corner unit (CornerForm 1, the iCE40 HX form), as a top of its own (scripts/synth_wrap.py
// finds a top by its plain name; a chparam'd top gets a derived one).
module g2_unit_msb16 (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic [trirast_pkg::PixBits-1:0]       cfg_vp_xmax_i,
  input  logic [trirast_pkg::PixBits-1:0]       cfg_vp_ymax_i,
  input  logic                                  tri_valid_i,
  output logic                                  tri_ready_o,
  input  logic [trirast_pkg::TagBits-1:0]       tri_tag_i,
  input  logic [3*trirast_pkg::VertexBits-1:0]  tri_vx_i,
  input  logic [3*trirast_pkg::VertexBits-1:0]  tri_vy_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]    tri_a_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]    tri_b_i,
  input  logic [3*trirast_pkg::EdgeBits-1:0]    tri_c_i,
  input  logic [2:0]                            tri_bias_i,
  output logic                                  span_valid_o,
  input  logic                                  span_ready_i,
  output logic [trirast_pkg::TagBits-1:0]       span_tag_o,
  output logic [trirast_pkg::PixBits-1:0]       span_y_o,
  output logic [trirast_pkg::PixBits-1:0]       span_x_begin_o,
  output logic [trirast_pkg::PixBits:0]         span_x_end_o,
  output logic                                  box_retire_o,
  output logic [trirast_pkg::TagBits-1:0]       box_retire_tag_o,
  output logic                                  busy_o
);
  trirast_improved2_top #(
    .CornerForm (1), .FifoRam (1'b0), .WalkerCs (1'b1), .TestHi (1'b0)
  ) u_unit (
    .clk_i, .rst_ni, .cfg_vp_xmax_i, .cfg_vp_ymax_i, .cfg_fifo_depth_i (4'd8), .tri_valid_i, .tri_ready_o, .tri_tag_i,
    .tri_vx_i, .tri_vy_i, .tri_a_i, .tri_b_i, .tri_c_i, .tri_bias_i, .span_valid_o,
    .span_ready_i, .span_tag_o, .span_y_o, .span_x_begin_o, .span_x_end_o, .box_retire_o,
    .box_retire_tag_o, .busy_o);
endmodule
