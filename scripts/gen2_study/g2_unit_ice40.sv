// gen2 study prototype (scripts/gen2_study.sh, rows g2.unit_ice40*; docs/gen2-design.md section 1,
// "Fitting the HX8K"): trirast_improved2_top in its iCE40 HX form, the MSB-first radix-16 corner unit
// (CornerForm 1, as g2_unit_msb16) with the fit's build choices, each a parameter here so a row can
// leave one out (chparam): the span FIFO in block RAM, the walkers' carry-in step, the 2x2 test on
// E_L's bits above F (a fifth, ElReg, E_L for the lanes from a register, went when the second
// corner run began to form each lane's value in place; a sixth, SignFold, the corner unit's signs
// on the multiplicands, when its signed-digit pairs replaced the magnitudes and signs). The same spans and cycles as g2_unit_msb16. The triangle port has no C: the unit's
// corner values are vertex-relative and trirast_improved2_top ignores tri_c_i (tied to zero
// here), so the wrapper does not register 150 unused bits.
module g2_unit_ice40 #(
  parameter bit FifoRam  = 1'b1,
  parameter bit WalkerCs = 1'b0,
  parameter bit TestHi   = 1'b1,
  parameter int LanePreIter = 0   // 1: trirast_improved2_edge_lane's pre-iteration (fewer LUT4, more cycles)
) (
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
    .CornerForm (1), .FifoRam (FifoRam), .WalkerCs (WalkerCs), .TestHi (TestHi),
    .LanePreIter (LanePreIter)
  ) u_unit (
    .clk_i, .rst_ni, .cfg_vp_xmax_i, .cfg_vp_ymax_i, .cfg_fifo_depth_i (4'd8), .tri_valid_i, .tri_ready_o, .tri_tag_i,
    .tri_vx_i, .tri_vy_i, .tri_a_i, .tri_b_i, .tri_c_i ('0), .tri_bias_i, .span_valid_o,
    .span_ready_i, .span_tag_o, .span_y_o, .span_x_begin_o, .span_x_end_o, .box_retire_o,
    .box_retire_tag_o, .busy_o);
endmodule
