// The improved2 unit's two corner forms side by side, for the exhaustive comparison at reduced
// widths (tb/improved2/improved2_corner_forms_exhaustive.sh; the C++ driver
// improved2_corner_forms_exhaustive.cpp enumerates the inputs and compares): the digit-serial form
// (rtl/common/trirast_corner_serial.sv) with DigitBits 4, as trirast_improved2_top
// builds it, and with DigitBits 2 (more digits per operand at the same widths, so the digit count
// and the digit pointer are exercised at widths where radix 16 needs one digit), against the
// products form (trirast_improved2_corner_products.sv).
// The serial units take the inputs of the corner stage (their triangle only at a first start); the
// products unit takes the triangle of the last first start and x1 = x0 + Xmax for the edges of
// the last second run (ref_*), as the driver holds them. A, B and A + B are formed here from the
// vertices (A_k = y_k - y_k+1, B_k = x_k+1 - x_k), as the top forms them for both forms. The
// widths go out on *_bits_o, so the driver follows the package it was built with.
`include "trirast_ports.svh"

module improved2_corner_forms_exhaustive_tb (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  // the corner stage's side: both serial units
  input  logic                                 start_i,
  input  logic                                 second_i,
  input  logic [2:0]                           run_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] vx_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] vy_i,
  input  logic [2:0]                           bias_i,
  input  logic [trirast_pkg::PixBits-1:0]      x0_i,
  input  logic [trirast_pkg::PixBits-1:0]      y0_i,
  input  logic [trirast_pkg::BoxBits-1:0]      xmax_i,
  output logic                                 busy16_o,   // DigitBits 4 (radix 16)
  output logic [3*trirast_pkg::EdgeBits-1:0]   el16_o,
  output logic [2:0]                           far16_o,
  output logic [2:0]                           fneg16_o,
  output logic                                 busy4_o,    // DigitBits 2 (radix 4)
  output logic [3*trirast_pkg::EdgeBits-1:0]   el4_o,
  output logic [2:0]                           far4_o,
  output logic [2:0]                           fneg4_o,
  // the products form, on the held triangle
  input  logic [3*trirast_pkg::VertexBits-1:0] ref_vx_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] ref_vy_i,
  input  logic [trirast_pkg::PixBits-1:0]      ref_x0_i,
  input  logic [trirast_pkg::PixBits-1:0]      ref_x1_i,
  input  logic [2:0]                           ref_x1sel_i,
  input  logic [trirast_pkg::PixBits-1:0]      ref_y0_i,
  output logic [3*trirast_pkg::EdgeBits-1:0]   ref_el_o,
  // the package's widths
  output logic [7:0]                           vertex_bits_o,
  output logic [7:0]                           frac_bits_o,
  output logic [7:0]                           coef_bits_o,
  output logic [7:0]                           edge_bits_o,
  output logic [7:0]                           pix_bits_o,
  output logic [7:0]                           box_bits_o
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES

  assign vertex_bits_o = 8'(P);
  assign frac_bits_o   = 8'(F);
  assign coef_bits_o   = 8'(CB);
  assign edge_bits_o   = 8'(EB);
  assign pix_bits_o    = 8'(PB);
  assign box_bits_o    = 8'(BB);

  // Edge k runs from vertex k to vertex k + 1: A = y_k - y_k+1, B = x_k+1 - x_k, and A + B.
  function automatic logic [3*CB-1:0] coef_a(input logic [3*P-1:0] vy);
    for (int k = 0; k < 3; k++)
      coef_a[k*CB +: CB] = CB'($signed(vy[k*P +: P])) - CB'($signed(vy[((k+1)%3)*P +: P]));
  endfunction
  function automatic logic [3*CB-1:0] coef_b(input logic [3*P-1:0] vx);
    for (int k = 0; k < 3; k++)
      coef_b[k*CB +: CB] = CB'($signed(vx[((k+1)%3)*P +: P])) - CB'($signed(vx[k*P +: P]));
  endfunction
  function automatic logic [3*(CB+1)-1:0] coef_p(input logic [3*CB-1:0] a,
                                                  input logic [3*CB-1:0] b);
    for (int k = 0; k < 3; k++)
      coef_p[k*(CB+1) +: CB+1] = (CB+1)'($signed(a[k*CB +: CB])) + (CB+1)'($signed(b[k*CB +: CB]));
  endfunction

  logic [3*CB-1:0] a, b, ref_a, ref_b;
  logic [3*(CB+1)-1:0] p;
  assign a = coef_a(vy_i);
  assign b = coef_b(vx_i);
  assign p = coef_p(a, b);
  assign ref_a = coef_a(ref_vy_i);
  assign ref_b = coef_b(ref_vx_i);

  trirast_corner_serial #(.DigitBits (4)) u_serial16 (
    .clk_i (clk_i), .rst_ni (rst_ni), .start_i (start_i), .second_i (second_i), .run_i (run_i),
    .vx_i (vx_i), .vy_i (vy_i), .a_i (a), .b_i (b), .p_i (p), .bias_i (bias_i), .x0_i (x0_i),
    .y0_i (y0_i), .xmax_i (xmax_i), .busy_o (busy16_o), .el_o (el16_o), .far_o (far16_o),
    .fneg_o (fneg16_o));
  trirast_corner_serial #(.DigitBits (2)) u_serial4 (
    .clk_i (clk_i), .rst_ni (rst_ni), .start_i (start_i), .second_i (second_i), .run_i (run_i),
    .vx_i (vx_i), .vy_i (vy_i), .a_i (a), .b_i (b), .p_i (p), .bias_i (bias_i), .x0_i (x0_i),
    .y0_i (y0_i), .xmax_i (xmax_i), .busy_o (busy4_o), .el_o (el4_o), .far_o (far4_o),
    .fneg_o (fneg4_o));

  trirast_improved2_corner_products u_products (
    .vx_i (ref_vx_i), .vy_i (ref_vy_i), .a_i (ref_a), .b_i (ref_b), .bias_i (bias_i),
    .x0_i (ref_x0_i), .x1_i (ref_x1_i), .x1sel_i (ref_x1sel_i), .y0_i (ref_y0_i),
    .el_o (ref_el_o));
endmodule
