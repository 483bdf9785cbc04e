// Stage 1, interface (docs/unit.md, section 1): holds the accepted triangle, computes its pixel
// bounding box (setup StBox, registered) and the box-relative edge terms (setup StEdge,
// combinational): a = A*u, b = B*u and the corner values E_L = E(c(x0, y0)) + bias,
// E_R = E(c(x1, y0)) + bias. The corner values are the unit's only multipliers: with the pixel
// centre c = x*u + h, A*c = (A*x << F) + (A << (F - 1)), so each is a (p + 1) x PixBits product.
// BoxAtAccept (the half-space unit) forms the box's first and last pixels from the port's
// vertices in the accept cycle and registers them with the triangle: StBox keeps the clip at 0 and
// one subtraction per axis (Xmax, Ymax and the empty test). The cycles are the same; the logic
// moves into the port's cycle, whose inputs come from the upstream's registers (docs/port.md).
`include "trirast_assert.svh"
`include "trirast_ports.svh"

module trirast_box_stage #(
  parameter bit BoxAtAccept = 1'b0  // 1: first/last pixel from the port's vertices at accept
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  // ---- configuration ----
  input  logic [trirast_pkg::PixBits-1:0]       vp_xmax_i,  // viewport width - 1
  input  logic [trirast_pkg::PixBits-1:0]       vp_ymax_i,  // viewport height - 1
  // ---- the triangle port's data (taken with accept_i) ----
  input  logic                                  accept_i,   // setup StIdle handshake
  input  logic [trirast_pkg::TagBits-1:0]       tag_i,
  input  logic [3*trirast_pkg::VertexBits-1:0]  vx_i,       // vertex k x at [k*p +: p], signed
  input  logic [3*trirast_pkg::VertexBits-1:0]  vy_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]    a_i,        // edge k: A (signed)
  input  logic [3*trirast_pkg::CoefBits-1:0]    b_i,        // edge k: B (signed)
  input  logic [3*trirast_pkg::EdgeBits-1:0]    c_i,        // edge k: C (signed)
  input  logic [2:0]                            bias_i,     // edge k: 1 = bias -1 (not top-left)
  // ---- bounding box ----
  input  logic                                  box_i,      // setup StBox: register the box
  output logic                                  empty_o,    // in StBox: no pixel centre in the box
  output logic [trirast_pkg::TagBits-1:0]       tag_o,
  output logic [trirast_pkg::PixBits-1:0]       x0_o,
  output logic [trirast_pkg::PixBits-1:0]       y0_o,
  output logic [trirast_pkg::BoxBits-1:0]       xmax_o,     // x1 - x0
  output logic [trirast_pkg::BoxBits-1:0]       ymax_o,     // y1 - y0
  // ---- the accepted triangle's vertices and bias (a digit-serial corner unit's operands) ----
  output logic [3*trirast_pkg::VertexBits-1:0]  vx_o,
  output logic [3*trirast_pkg::VertexBits-1:0]  vy_o,
  output logic [2:0]                            bias_o,
  // ---- edge terms (valid from StEdge on) ----
  output logic [3*trirast_pkg::CoefBits-1:0]    a_o,        // A of edge k (a = A*u)
  output logic [3*trirast_pkg::CoefBits-1:0]    b_o,        // B of edge k (b = B*u)
  output logic [3*trirast_pkg::EdgeBits-1:0]    el_o,       // E_L of edge k
  output logic [3*trirast_pkg::EdgeBits-1:0]    er_o        // E_R of edge k
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES
  localparam int WBits = P + 2;                   // box arithmetic
  localparam int ProdBits = CoefBits + PixBits + 1;  // A * x (x unsigned)
  localparam logic signed [WBits-1:0] Half = WBits'(1) << (F - 1);  // h = u/2

  // The accepted triangle.
  logic [TagBits-1:0] tag_q, tag_d;
  logic [3*P-1:0] vx_q, vx_d, vy_q, vy_d;
  logic [3*CoefBits-1:0] a_q, a_d, b_q, b_d;
  logic [3*EdgeBits-1:0] c_q, c_d;
  logic [2:0] bias_q, bias_d;
  // Its box.
  logic [PixBits-1:0] x0_q, x0_d, y0_q, y0_d;
  logic [BoxBits-1:0] xmax_q, xmax_d, ymax_q, ymax_d;

  // First and last pixel whose centre lies in [lo, hi], clipped to [0, limit]:
  // first = ceil((lo - h)/u) = -((h - lo) >> F), last = floor((hi - h)/u) = (hi - h) >> F.
  logic [PixBits-1:0] box_x0, box_y0;  // the box's first pixel
  logic [BoxBits-1:0] xmax, ymax;      // its x1 - x0, y1 - y0

  // Vertex k of a packed coordinate triple, sign-extended to WBits.
  function automatic logic signed [WBits-1:0] coord(input logic [3*P-1:0] v, input int k);
    coord = {{2{v[k*P+P-1]}}, v[k*P +: P]};
  endfunction
  function automatic logic signed [WBits-1:0] min3(input logic [3*P-1:0] v);
    logic signed [WBits-1:0] m;
    m = coord(v, 0);
    if (coord(v, 1) < m) m = coord(v, 1);
    if (coord(v, 2) < m) m = coord(v, 2);
    min3 = m;
  endfunction
  function automatic logic signed [WBits-1:0] max3(input logic [3*P-1:0] v);
    logic signed [WBits-1:0] m;
    m = coord(v, 0);
    if (coord(v, 1) > m) m = coord(v, 1);
    if (coord(v, 2) > m) m = coord(v, 2);
    max3 = m;
  endfunction
  // ceil((lo - h)/u) = -((h - lo) >> F), clipped below at 0.
  function automatic logic signed [WBits-1:0] first_px(input logic signed [WBits-1:0] lo);
    logic signed [WBits-1:0] f;
    f = -((Half - lo) >>> F);
    first_px = (f < 0) ? '0 : f;
  endfunction
  // floor((hi - h)/u) = (hi - h) >> F, clipped above at the viewport's last pixel.
  function automatic logic signed [WBits-1:0] last_px(input logic signed [WBits-1:0] hi,
                                                      input logic [PixBits-1:0] limit);
    logic signed [WBits-1:0] l;
    l = (hi - Half) >>> F;
    last_px = (l > $signed(WBits'(limit))) ? $signed(WBits'(limit)) : l;
  endfunction

  // The StBox form, from the held vertices: the improved unit's box, and BoxAtAccept's reference.
  logic signed [WBits-1:0] held_fx, held_lx, held_fy, held_ly;
  logic held_empty;
  logic [BoxBits-1:0] held_xmax, held_ymax;
  assign held_fx = first_px(min3(vx_q));
  assign held_lx = last_px(max3(vx_q), vp_xmax_i);
  assign held_fy = first_px(min3(vy_q));
  assign held_ly = last_px(max3(vy_q), vp_ymax_i);
  assign held_empty = (held_fx > held_lx) || (held_fy > held_ly);
  assign {held_xmax, held_ymax} = {BoxBits'(held_lx - held_fx), BoxBits'(held_ly - held_fy)};

  // The box's first and last pixel of three vertices (BoxAtAccept), two short carry chains deep:
  // three compares select the smallest and the largest vertex; then, side by side, each one's pixel
  // and the last pixel's clip, vmax >= thr with thr = (limit + 1)*u + h, the first coordinate whose
  // last pixel (vmax - h) >> F passes limit. The first pixel is left unclipped: StBox clips it at
  // 0 by its sign, before the subtraction that gives Xmax and the empty test. A compare is two
  // chains of half the width side by side (the high halves' order, or their equality and the low
  // halves' order); a pixel is the coordinate's pixel part plus or minus its fraction's carry:
  // ceil((v - h)/u) = (v >> F) + (frac > h), floor((v - h)/u) = (v >> F) - (frac < h).
  localparam int LoBits = WBits / 2;
  localparam logic [F-1:0] FracBelowHalf = F'((1 << (F - 1)) - 1);  // h - 1, F bits
  function automatic logic lt_halves(input logic signed [WBits-1:0] a,
                                     input logic signed [WBits-1:0] b);
    lt_halves = $signed(a[WBits-1:LoBits]) < $signed(b[WBits-1:LoBits]) ||
                (a[WBits-1:LoBits] == b[WBits-1:LoBits] && a[LoBits-1:0] < b[LoBits-1:0]);
  endfunction
  function automatic logic [2*WBits-1:0] first_last(input logic [3*P-1:0] v,
                                                    input logic signed [WBits-1:0] limit,
                                                    input logic signed [WBits-1:0] thr);
    logic signed [WBits-1:0] vmin, vmax;
    logic [WBits-F-1:0] f, l;  // pixels, signed
    logic lt01, lt02, lt12;
    lt01 = lt_halves(coord(v, 0), coord(v, 1));
    lt02 = lt_halves(coord(v, 0), coord(v, 2));
    lt12 = lt_halves(coord(v, 1), coord(v, 2));
    vmin = (lt01 && lt02) ? coord(v, 0) : lt12 ? coord(v, 1) : coord(v, 2);
    vmax = (!lt01 && !lt02) ? coord(v, 0) : !lt12 ? coord(v, 1) : coord(v, 2);
    f = vmin[WBits-1:F] + (WBits-F)'(vmin[F-1] && (vmin[F-1:0] & FracBelowHalf) != '0);  // ceil
    l = vmax[WBits-1:F] - (WBits-F)'(!vmax[F-1]);                     // floor((vmax - h)/u)
    first_last = {{{F{f[WBits-F-1]}}, f},
                  lt_halves(vmax, thr) ? {{F{l[WBits-F-1]}}, l} : limit};
  endfunction

  if (BoxAtAccept) begin : g_box_at_accept
    logic signed [WBits-1:0] fx_q, lx_q, fy_q, ly_q;
    // The clip thresholds from the viewport, registered in every cycle, reset included: the
    // viewport is static and applied before reset is released (docs/port.md), so at accept they
    // are its own, and the clip at accept equals the clip in StBox.
    logic signed [WBits-1:0] xthr_q, ythr_q;
    always_ff @(posedge clk_i) begin
      xthr_q <= ((WBits'(vp_xmax_i) + 1) << F) + Half;
      ythr_q <= ((WBits'(vp_ymax_i) + 1) << F) + Half;
      if (accept_i) begin
        {fx_q, lx_q} <= first_last(vx_i, WBits'(vp_xmax_i), xthr_q);
        {fy_q, ly_q} <= first_last(vy_i, WBits'(vp_ymax_i), ythr_q);
      end
    end
    // One subtraction per axis: its sign is the empty test, its low bits Xmax (Ymax).
    logic signed [WBits-1:0] fx, fy;
    logic signed [WBits:0] dx, dy;
    assign fx = fx_q[WBits-1] ? '0 : fx_q;
    assign fy = fy_q[WBits-1] ? '0 : fy_q;
    assign {box_x0, box_y0} = {PixBits'(fx), PixBits'(fy)};
    assign dx = (WBits+1)'(lx_q) - (WBits+1)'(fx);
    assign dy = (WBits+1)'(ly_q) - (WBits+1)'(fy);
    assign {xmax, ymax} = {BoxBits'(dx), BoxBits'(dy)};
    assign empty_o = dx[WBits] || dy[WBits];
    // The same box as the StBox form's (simulation, formal; synthesis removes the held form).
    `ASSERT_IMPLIES(BoxAtAcceptIsBox_A, box_i, fx == held_fx && fy == held_fy &&
                    empty_o == held_empty && (empty_o || (xmax == held_xmax && ymax == held_ymax)),
                    clk_i, !rst_ni)
  end else begin : g_box_in_stbox
    assign {box_x0, box_y0} = {PixBits'(held_fx), PixBits'(held_fy)};
    assign {xmax, ymax, empty_o} = {held_xmax, held_ymax, held_empty};
  end

  always_comb begin
    {tag_d, vx_d, vy_d, a_d, b_d, c_d, bias_d, x0_d, y0_d, xmax_d, ymax_d} =
        {tag_q, vx_q, vy_q, a_q, b_q, c_q, bias_q, x0_q, y0_q, xmax_q, ymax_q};
    if (accept_i) begin
      {tag_d, vx_d, vy_d, a_d, b_d, c_d, bias_d} = {tag_i, vx_i, vy_i, a_i, b_i, c_i, bias_i};
    end
    if (box_i) begin
      // The box fits BoxBits (the harness rejects larger ones, as the model does).
      x0_d   = box_x0;
      y0_d   = box_y0;
      xmax_d = xmax;
      ymax_d = ymax;
    end
  end

  // Datapath registers: no reset (written by the handshake before they are read).
  always_ff @(posedge clk_i) begin
    {tag_q, vx_q, vy_q, a_q, b_q, c_q, bias_q, x0_q, y0_q, xmax_q, ymax_q} <=
        {tag_d, vx_d, vy_d, a_d, b_d, c_d, bias_d, x0_d, y0_d, xmax_d, ymax_d};
  end

  // Corner values. The products are exact; the sums are taken modulo 2^EdgeBits, exact because
  // E_L and E_R fit EdgeBits (docs/unit.md, "Widths").
  logic [PixBits-1:0] x1;
  assign x1 = x0_q + PixBits'(xmax_q);

  for (genvar k = 0; k < 3; k++) begin : g_corner
    logic signed [CoefBits-1:0] ak, bk;
    logic signed [ProdBits-1:0] ax0, ax1, by0;
    logic signed [EdgeBits-1:0] common, ak_h, bk_h;
    assign ak  = a_q[k*CoefBits +: CoefBits];
    assign bk  = b_q[k*CoefBits +: CoefBits];
    assign ax0 = ak * $signed({1'b0, x0_q});
    assign ax1 = ak * $signed({1'b0, x1});
    assign by0 = bk * $signed({1'b0, y0_q});
    // A*h and B*h with h = 2^(F-1).
    assign ak_h = {{(EdgeBits - CoefBits){ak[CoefBits-1]}}, ak} <<< (F - 1);
    assign bk_h = {{(EdgeBits - CoefBits){bk[CoefBits-1]}}, bk} <<< (F - 1);
    // B*c(y0) + C + bias, shared by both corners.
    assign common = ({{(EdgeBits - ProdBits){by0[ProdBits-1]}}, by0} <<< F) + bk_h +
                    $signed(c_q[k*EdgeBits +: EdgeBits]) - EdgeBits'(bias_q[k]);
    assign el_o[k*EdgeBits +: EdgeBits] =
        ({{(EdgeBits - ProdBits){ax0[ProdBits-1]}}, ax0} <<< F) + ak_h + common;
    assign er_o[k*EdgeBits +: EdgeBits] =
        ({{(EdgeBits - ProdBits){ax1[ProdBits-1]}}, ax1} <<< F) + ak_h + common;
  end

  assign {tag_o, x0_o, y0_o, xmax_o, ymax_o, a_o, b_o, vx_o, vy_o, bias_o} =
      {tag_q, x0_q, y0_q, xmax_q, ymax_q, a_q, b_q, vx_q, vy_q, bias_q};

  // rst_ni is unused: the interface holds only data registers.
  logic unused_rst;
  assign unused_rst = rst_ni;

endmodule
