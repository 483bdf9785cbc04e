// The triangle port's preconditions (docs/port.md, "Preconditions"), checked once for every top:
// a triangle taken at the port (tri_valid_i && tri_ready_o) must be one the CLI's setup forms
// (model/common/setup.cpp). A unit given another one does not fail in a way one can see: a
// triangle whose vertices run the other way, or one of zero area, is taken and walks no span.
// Each precondition is an assertion that names it (rtl/common/trirast_assert.svh; a Verilated
// model built with --assert stops with "[ASSERT FAILED] [instance] Name"):
//   TriNonDegenerate_A         twice the signed area of the vertices, area2, is not 0
//   TriOrientation_A           area2 is not < 0: v0, v1, v2 run clockwise as seen on screen (y
//                              down), the order setup makes by swapping v1 and v2
//   TriEdgesFromVertices_A, _B, _C, _Bias
//                              edge k's A, B, C and bias are those of the port's vertices v[k] ->
//                              v[(k+1)%3] by the coverage rule (HasEdges; C also ReadsC)
//   TriVertexOnGrid_A          at SubpixelBits = 0 (FracBits = 1) a vertex is a whole pixel, its
//                              low bit 0 (setup snaps to 1/2^S pixel, then scales to 1/2^F)
//   TriBoxInRange_A            the box (pixel centres within the vertices' extent, clipped to the
//                              viewport) is at most 2^BoxBits pixels on each axis (HasBox)
// The viewport needs no check: its last pixel (PixBits = CoordIntBits - 1 bits) is always inside
// the coordinate range, as the CLI's --coord-bits check asks.
// Simulation only: neither synthesis (SYNTHESIS) nor the formal flow (FORMAL: Yosys 0.23 refuses
// one package's names in another's parameters) reads it, and the tops instantiate it under the
// same two guards, so netlists and cycles do not change. The arithmetic is trirast_port_pkg's,
// the same a testbench forms its triangles with.
`ifndef SYNTHESIS
`ifndef FORMAL

`include "trirast_assert.svh"

module trirast_triangle_port_check #(
  parameter bit HasEdges = 1'b1,  // the port carries A, B, C, bias (all but the traditional unit)
  parameter bit ReadsC = 1'b1,    // ... and the unit reads C (not improved2: vertex-relative E)
  parameter bit HasBox = 1'b1     // the unit walks a BoxBits box (not the traditional unit)
) (
  input logic                                 clk_i,
  input logic                                 rst_ni,
  input logic [trirast_pkg::PixBits-1:0]      cfg_vp_xmax_i,
  input logic [trirast_pkg::PixBits-1:0]      cfg_vp_ymax_i,
  input logic                                 tri_valid_i,
  input logic                                 tri_ready_i,   // the top's tri_ready_o
  input logic [3*trirast_pkg::VertexBits-1:0] tri_vx_i,
  input logic [3*trirast_pkg::VertexBits-1:0] tri_vy_i,
  input logic [3*trirast_pkg::CoefBits-1:0]   tri_a_i,       // read when HasEdges
  input logic [3*trirast_pkg::CoefBits-1:0]   tri_b_i,
  input logic [3*trirast_pkg::EdgeBits-1:0]   tri_c_i,       // read when HasEdges && ReadsC
  input logic [2:0]                           tri_bias_i
);
  localparam int P = trirast_pkg::VertexBits;
  localparam int F = trirast_pkg::FracBits;
  localparam int S = trirast_pkg::SubpixelBits;
  localparam int PB = trirast_pkg::PixBits;
  localparam int AB = trirast_port_pkg::AreaBits;

  // Every check is evaluated in the cycle a triangle is taken and only then (ASSERT_IF: an
  // immediate assertion in a clocked block): the products and extents are in functions called
  // inside the assertions, not continuous assignments on the port.
  logic take;
  assign take = tri_valid_i && tri_ready_i;

  function automatic logic signed [AB-1:0] area2(input logic [3*P-1:0] vx, input logic [3*P-1:0] vy);
    area2 = trirast_port_pkg::tri_area2(vx, vy);
  endfunction

  // {empty, last - first} of one axis of the box: the pixels whose centres lie within the
  // vertices' extent, clipped to the viewport.
  function automatic logic [AB:0] axis_extent(input logic [3*P-1:0] v, input logic [PB-1:0] vp);
    logic signed [AB-1:0] lo, hi, first, last, h, u;
    lo = trirast_port_pkg::coord(v, 0);
    hi = lo;
    for (int k = 1; k < 3; k++) begin
      if (trirast_port_pkg::coord(v, k) < lo) lo = trirast_port_pkg::coord(v, k);
      if (trirast_port_pkg::coord(v, k) > hi) hi = trirast_port_pkg::coord(v, k);
    end
    u = AB'(1) <<< F;
    h = AB'(1) <<< (F - 1);
    first = (lo - h + u - 1) >>> F;  // ceil((lo - h) / u)
    last = (hi - h) >>> F;           // floor((hi - h) / u)
    if (first < 0) first = '0;
    if (last > $signed(AB'(vp))) last = AB'(vp);
    axis_extent = {first > last, last - first};
  endfunction

  function automatic logic box_in_range(input logic [AB:0] ext_x, input logic [AB:0] ext_y);
    box_in_range = ext_x[AB] || ext_y[AB] ||
                   (ext_x[AB-1:0] < (AB'(1) << trirast_pkg::BoxBits) &&
                    ext_y[AB-1:0] < (AB'(1) << trirast_pkg::BoxBits));
  endfunction

  `ASSERT_IF(TriNonDegenerate_A, take, area2(tri_vx_i, tri_vy_i) != '0, clk_i, !rst_ni)
  `ASSERT_IF(TriOrientation_A, take, area2(tri_vx_i, tri_vy_i) >= 0, clk_i, !rst_ni)
  if (HasEdges) begin : g_edges
    `ASSERT_IF(TriEdgesFromVertices_A, take,
               tri_a_i == trirast_port_pkg::edge_a(tri_vx_i, tri_vy_i), clk_i, !rst_ni)
    `ASSERT_IF(TriEdgesFromVertices_B, take,
               tri_b_i == trirast_port_pkg::edge_b(tri_vx_i, tri_vy_i), clk_i, !rst_ni)
    `ASSERT_IF(TriEdgesFromVertices_Bias, take,
               tri_bias_i == trirast_port_pkg::edge_bias(tri_vx_i, tri_vy_i), clk_i, !rst_ni)
    if (ReadsC) begin : g_c
      `ASSERT_IF(TriEdgesFromVertices_C, take,
                 tri_c_i == trirast_port_pkg::edge_c(tri_vx_i, tri_vy_i), clk_i, !rst_ni)
    end
  end
  if (F > S) begin : g_grid
    `ASSERT_IF(TriVertexOnGrid_A, take, tri_vx_i[0] == 1'b0 && tri_vx_i[P] == 1'b0 &&
               tri_vx_i[2*P] == 1'b0 && tri_vy_i[0] == 1'b0 && tri_vy_i[P] == 1'b0 &&
               tri_vy_i[2*P] == 1'b0, clk_i, !rst_ni)
  end
  if (HasBox) begin : g_box
    `ASSERT_IF(TriBoxInRange_A, take,
               box_in_range(axis_extent(tri_vx_i, cfg_vp_xmax_i), axis_extent(tri_vy_i, cfg_vp_ymax_i)),
               clk_i, !rst_ni)
  end

  logic unused;
  assign unused = ^{tri_a_i, tri_b_i, tri_c_i, tri_bias_i, cfg_vp_xmax_i, cfg_vp_ymax_i, take};

endmodule

`endif  // FORMAL
`endif  // SYNTHESIS
