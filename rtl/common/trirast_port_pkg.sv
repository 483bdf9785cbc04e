// A port triangle formed from three vertices exactly as the CLI's setup forms it
// (model/common/setup.cpp, docs/coverage-rule.md, docs/port.md "Preconditions"): the vertices
// scaled to the arithmetic's 1/2^FracBits pixel, v1 and v2 swapped when they run the other way
// (twice the signed area, area2, < 0: counter-clockwise as seen on screen, y down), and per edge
// k (from v[k] to v[(k+1)%3]) the edge function E = A x + B y + C with its top-left bias:
//   A = v[k].y - v[k+1].y,  B = v[k+1].x - v[k].x,  C = v[k].x v[k+1].y - v[k].y v[k+1].x,
//   bias = 0 for a left edge (A > 0) or a top edge (A = 0, B > 0), -1 (bit 1) otherwise.
// A zero-area triangle (area2 = 0 after snapping) is degenerate: setup drops it, and no unit's
// port may be given one.
//
// For testbenches and for the port's precondition checks (trirast_triangle_port_check), not for
// synthesis. Every result is a packed vector (or a task's outputs) at the port's packing, vertex
// or edge k at [k*W +: W]: Icarus 11 aborts on package-scoped struct types (docs/rtl.md).
//
//   vertex_from_subpixel(v)          a coordinate in 1/2^SubpixelBits pixel (as the CLI snaps it)
//                                    -> the port's 1/2^FracBits pixel (x 2 at S = 0, else x 1)
//   tri_area2(vx, vy)                twice the signed area of the vertices as given (AreaBits)
//   tri_degenerate(vx, vy)           area2 == 0
//   tri_swapped(vx, vy)              area2 < 0: setup swaps v1 and v2
//   tri_order_x(vx, vy), tri_order_y(vx, vy)
//                                    the vertices in setup's order (v1, v2 swapped if area2 < 0)
//   edge_a(vx, vy), edge_b(vx, vy)   A, B of the three edges of the vertices AS GIVEN
//   edge_c(vx, vy)                   C of the three edges (3 x EdgeBits)
//   edge_bias(vx, vy)                bit k = 1: edge k's bias is -1
//   form_port_triangle(sx, sy, degenerate, swapped, vx, vy, a, b, c, bias)
//                                    all of it from vertices in 1/2^SubpixelBits pixel (sx, sy):
//                                    the port's tri_vx_i .. tri_bias_i for setup's order.
// The edge functions take the vertices in the order to use: pass tri_order_x/y's (or the port's
// vertices, to check a port triangle against its vertices).
// Simulation only: a synthesis tool (which defines SYNTHESIS) reads nothing of it (Yosys 0.23
// also refuses one package's names in another's parameters).
`ifndef SYNTHESIS  // simulation only: neither synthesis nor the formal flow (Yosys)
`ifndef FORMAL

package trirast_port_pkg;

  // Each edge function takes both axes (one call form for all) and keeps the bits the port
  // has of a wider difference.
  /* verilator lint_off UNUSEDSIGNAL */

  localparam int P = trirast_pkg::VertexBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int F = trirast_pkg::FracBits;
  localparam int S = trirast_pkg::SubpixelBits;
  // Twice the area: a difference of two products of (p + 1)-bit differences.
  localparam int AreaBits = 2 * P + 3;

  // One vertex coordinate (k = 0..2) of a packed triple, sign-extended to W bits.
  function automatic logic signed [AreaBits-1:0] coord(input logic [3*P-1:0] v, input int k);
    coord = AreaBits'($signed(v[k*P +: P]));
  endfunction

  function automatic logic [P-1:0] vertex_from_subpixel(input logic [P-1:0] v);
    vertex_from_subpixel = v << (F - S);
  endfunction

  function automatic logic signed [AreaBits-1:0] tri_area2(input logic [3*P-1:0] vx,
                                                           input logic [3*P-1:0] vy);
    tri_area2 = (coord(vx, 1) - coord(vx, 0)) * (coord(vy, 2) - coord(vy, 0)) -
                (coord(vy, 1) - coord(vy, 0)) * (coord(vx, 2) - coord(vx, 0));
  endfunction

  function automatic logic tri_degenerate(input logic [3*P-1:0] vx, input logic [3*P-1:0] vy);
    tri_degenerate = tri_area2(vx, vy) == '0;
  endfunction

  function automatic logic tri_swapped(input logic [3*P-1:0] vx, input logic [3*P-1:0] vy);
    logic signed [AreaBits-1:0] area2;
    area2 = tri_area2(vx, vy);
    tri_swapped = area2[AreaBits-1];
  endfunction

  // One axis of the vertices in setup's order (w: the same axis; the area reads both).
  function automatic logic [3*P-1:0] order_axis(input logic [3*P-1:0] w, input logic swap);
    order_axis = swap ? {w[P +: P], w[2*P +: P], w[0 +: P]} : w;
  endfunction
  function automatic logic [3*P-1:0] tri_order_x(input logic [3*P-1:0] vx,
                                                 input logic [3*P-1:0] vy);
    tri_order_x = order_axis(vx, tri_swapped(vx, vy));
  endfunction
  function automatic logic [3*P-1:0] tri_order_y(input logic [3*P-1:0] vx,
                                                 input logic [3*P-1:0] vy);
    tri_order_y = order_axis(vy, tri_swapped(vx, vy));
  endfunction

  function automatic logic [3*CB-1:0] edge_a(input logic [3*P-1:0] vx, input logic [3*P-1:0] vy);
    logic signed [AreaBits-1:0] d;
    for (int k = 0; k < 3; k++) begin
      d = coord(vy, k) - coord(vy, (k + 1) % 3);
      edge_a[k*CB +: CB] = d[CB-1:0];
    end
  endfunction

  function automatic logic [3*CB-1:0] edge_b(input logic [3*P-1:0] vx, input logic [3*P-1:0] vy);
    logic signed [AreaBits-1:0] d;
    for (int k = 0; k < 3; k++) begin
      d = coord(vx, (k + 1) % 3) - coord(vx, k);
      edge_b[k*CB +: CB] = d[CB-1:0];
    end
  endfunction

  function automatic logic [3*EB-1:0] edge_c(input logic [3*P-1:0] vx, input logic [3*P-1:0] vy);
    logic signed [AreaBits-1:0] d;
    for (int k = 0; k < 3; k++) begin
      d = coord(vx, k) * coord(vy, (k + 1) % 3) - coord(vy, k) * coord(vx, (k + 1) % 3);
      edge_c[k*EB +: EB] = d[EB-1:0];
    end
  endfunction

  function automatic logic [2:0] edge_bias(input logic [3*P-1:0] vx, input logic [3*P-1:0] vy);
    logic signed [AreaBits-1:0] a, b;
    for (int k = 0; k < 3; k++) begin
      a = coord(vy, k) - coord(vy, (k + 1) % 3);
      b = coord(vx, (k + 1) % 3) - coord(vx, k);
      // Top-left rule: a left edge (A > 0) or a top edge (A == 0, B > 0) owns its centres.
      edge_bias[k] = !(a > 0 || (a == 0 && b > 0));
    end
  endfunction

  task automatic form_port_triangle(input logic [3*P-1:0] sx, input logic [3*P-1:0] sy,
                                    output logic degenerate, output logic swapped,
                                    output logic [3*P-1:0] vx, output logic [3*P-1:0] vy,
                                    output logic [3*CB-1:0] a, output logic [3*CB-1:0] b,
                                    output logic [3*EB-1:0] c, output logic [2:0] bias);
    logic [3*P-1:0] ux, uy;
    for (int k = 0; k < 3; k++) begin
      ux[k*P +: P] = vertex_from_subpixel(sx[k*P +: P]);
      uy[k*P +: P] = vertex_from_subpixel(sy[k*P +: P]);
    end
    degenerate = tri_degenerate(ux, uy);
    swapped = tri_swapped(ux, uy);
    vx = tri_order_x(ux, uy);
    vy = tri_order_y(ux, uy);
    a = edge_a(vx, vy);
    b = edge_b(vx, vy);
    c = edge_c(vx, vy);
    bias = edge_bias(vx, vy);
  endtask

  /* verilator lint_on UNUSEDSIGNAL */

endpackage

`endif  // FORMAL
`endif  // SYNTHESIS
