// The testbench of rtl/common/trirast_triangle_port_check.sv alone (ctest rtl_port_check_*): one
// triangle, formed with trirast_port_pkg as the CLI's setup forms it, then broken as +case=NAME
// says, offered for one handshake. Every case but "good" must stop the run naming its assertion
// (tests/rtl/expect_failure.sh); the units' own tests (rtl_port_precondition_*) drive the
// orientation and the zero area through every top.
//   good     the triangle as formed: no assertion fires ("port_check_tb good: no assertion fired")
//   edge_a, edge_b, edge_c
//            edge 1's A, B or C one more than its vertices': TriEdgesFromVertices_A, _B, _C
//   bias     edge 2's bias bit flipped: TriEdgesFromVertices_Bias
//   box_fits a triangle whose box is 2^BoxBits pixels wide, the most the port takes: no assertion
//   box      one pixel wider, in a viewport that holds it: TriBoxInRange_A
//   grid     (S = 0 only) a vertex at half a pixel, off the 1/2^S grid: TriVertexOnGrid_A
`include "trirast_assert.svh"

module port_check_tb;
  import trirast_port_pkg::form_port_triangle;
  localparam int P = trirast_pkg::VertexBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int PB = trirast_pkg::PixBits;
  localparam int S = trirast_pkg::SubpixelBits;

  logic clk = 1'b0, rst_n = 1'b0, valid = 1'b0;
  logic [PB-1:0] vp_xmax, vp_ymax;
  logic [3*P-1:0] sx, sy, vx, vy;
  logic [3*CB-1:0] a, b;
  logic [3*EB-1:0] c;
  logic [2:0] bias;
  logic degenerate, swapped;

  trirast_triangle_port_check u_port_check (
    .clk_i (clk), .rst_ni (rst_n), .cfg_vp_xmax_i (vp_xmax), .cfg_vp_ymax_i (vp_ymax),
    .tri_valid_i (valid), .tri_ready_i (1'b1), .tri_vx_i (vx), .tri_vy_i (vy),
    .tri_a_i (a), .tri_b_i (b), .tri_c_i (c), .tri_bias_i (bias));

  always #5 clk <= !clk;

  // A vertex in 1/2^S pixel from whole pixels and 1/4 pixels.
  function automatic logic [P-1:0] at(input int pixels, input int quarters);
    at = P'((pixels << S) + ((quarters << S) >>> 2));
  endfunction

  initial begin
    string name;
    if (!$value$plusargs("case=%s", name)) $fatal(1, "port_check_tb: no +case=NAME");
    vp_xmax = '1;  // the largest viewport the port holds
    vp_ymax = '1;
    // Clockwise on screen (y down): (2, 3), (40, 11), (9, 50), at quarter pixels (2 1/4: the box
    // starts at pixel 2, centre 2 1/2). The box cases move v1 to x = 2 + 2^BoxBits (the last
    // centre inside, 1 + 2^BoxBits 1/2, makes a box of 2^BoxBits pixels) or one pixel further;
    // the viewport (2^PixBits pixels) holds both.
    sx = {at(9, 3), at(40, 2), at(2, 1)};
    sy = {at(50, 1), at(11, 0), at(3, 2)};
    if (name == "box_fits") sx[P +: P] = at(2 + (1 << trirast_pkg::BoxBits), 0);
    if (name == "box") sx[P +: P] = at(3 + (1 << trirast_pkg::BoxBits), 0);
    form_port_triangle(sx, sy, degenerate, swapped, vx, vy, a, b, c, bias);
    if (degenerate || swapped) $fatal(1, "port_check_tb: the triangle is not formed as meant");
    case (name)
      "good", "box_fits", "box": ;
      "edge_a": a[CB +: CB] = a[CB +: CB] + 1'b1;
      "edge_b": b[CB +: CB] = b[CB +: CB] + 1'b1;
      "edge_c": c[EB +: EB] = c[EB +: EB] + 1'b1;
      "bias": bias[2] = !bias[2];
      "grid": begin
        if (S != 0) $fatal(1, "port_check_tb: case grid needs S = 0 (this package has S = %0d)", S);
        vx[0] = 1'b1;  // the edges of the vertices as they now are: only the grid is wrong
        a = trirast_port_pkg::edge_a(vx, vy);
        b = trirast_port_pkg::edge_b(vx, vy);
        c = trirast_port_pkg::edge_c(vx, vy);
        bias = trirast_port_pkg::edge_bias(vx, vy);
      end
      default: $fatal(1, "port_check_tb: unknown case '%s'", name);
    endcase
    repeat (2) @(negedge clk);
    rst_n = 1'b1;
    @(negedge clk);
    valid = 1'b1;
    @(negedge clk);
    valid = 1'b0;
    repeat (2) @(negedge clk);
    $display("port_check_tb %s: no assertion fired", name);
    $finish;
  end
endmodule
