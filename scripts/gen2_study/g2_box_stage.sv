// gen2 study prototype (not a unit; scripts/gen2_study.sh): the box stage B of the recommended
// gen2 front end (docs/gen2-design.md). Takes an accepted triangle (its register: tag, vertices,
// A, B, bias; no C: the corner values are vertex-relative), computes in one cycle the pixel box
// as gen1's interface does (rtl/common/trirast_box_stage.sv), the empty flag, and the corner stage's
// operands: per edge k the magnitudes and signs of dxL = cx0 - vx_k and dy = cy0 - vy_k, all
// registered into the corner stage's input register when that stage takes the triangle.
// Split = 1: two pipeline cycles, B1 (the vertices' min and max, registered with the triangle)
// and B2 (clip, empty, operands); each holds a triangle, so the stage still takes one per cycle.
module g2_box_stage #(
  parameter int Split = 0
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic [trirast_pkg::PixBits-1:0]      vp_xmax_i,
  input  logic [trirast_pkg::PixBits-1:0]      vp_ymax_i,
  input  logic                                 accept_i,
  input  logic [trirast_pkg::TagBits-1:0]      tag_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] vx_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] vy_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]   a_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]   b_i,
  input  logic [2:0]                           bias_i,
  input  logic                                 take_i,    // the corner stage takes the triangle
  output logic                                 full_o,    // B holds a triangle
  output logic                                 empty_o,   // its box has no pixel centre
  // ---- the corner stage's input register ----
  output logic [trirast_pkg::TagBits-1:0]      c_tag_o,
  output logic [trirast_pkg::PixBits-1:0]      c_x0_o,
  output logic [trirast_pkg::PixBits-1:0]      c_y0_o,
  output logic [trirast_pkg::BoxBits-1:0]      c_xmax_o,
  output logic [trirast_pkg::BoxBits-1:0]      c_ymax_o,
  output logic [3*trirast_pkg::CoefBits-1:0]   c_a_o,
  output logic [3*trirast_pkg::CoefBits-1:0]   c_b_o,
  output logic [2:0]                           c_bias_o,
  output logic [6*(trirast_pkg::VertexBits+1)-1:0] c_mag_o,  // edge k: |dxL| at 2k, |dy| at 2k+1
  output logic [5:0]                           c_neg_o    // their signs
);
  localparam int F = trirast_pkg::FracBits;
  localparam int P = trirast_pkg::VertexBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int PB = trirast_pkg::PixBits;
  localparam int BB = trirast_pkg::BoxBits;
  localparam int TB = trirast_pkg::TagBits;
  localparam int WBits = P + 2;
  localparam int MW = P + 1;
  localparam logic signed [WBits-1:0] Half = WBits'(1) << (F - 1);

  logic full_q;
  logic [TB-1:0] tag_q;
  logic [3*P-1:0] vx_q, vy_q;
  logic [3*CB-1:0] a_q, b_q;
  logic [2:0] bias_q;

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

  // B1 -> B2 (Split = 1): the triangle and its extent move on together.
  logic signed [WBits-1:0] mnx, mxx, mny, mxy;
  logic [TB-1:0] tag2;
  logic [3*P-1:0] vx2, vy2;
  logic [3*CB-1:0] a2, b2;
  logic [2:0] bias2;
  if (Split != 0) begin : g_split
    logic signed [WBits-1:0] mnx_q, mxx_q, mny_q, mxy_q;
    logic [TB-1:0] tag2_q;
    logic [3*P-1:0] vx2_q, vy2_q;
    logic [3*CB-1:0] a2_q, b2_q;
    logic [2:0] bias2_q;
    always_ff @(posedge clk_i) begin
      mnx_q <= min3(vx_q);  mxx_q <= max3(vx_q);  mny_q <= min3(vy_q);  mxy_q <= max3(vy_q);
      tag2_q <= tag_q;  vx2_q <= vx_q;  vy2_q <= vy_q;  a2_q <= a_q;  b2_q <= b_q;
      bias2_q <= bias_q;
    end
    assign {mnx, mxx, mny, mxy} = {mnx_q, mxx_q, mny_q, mxy_q};
    assign {tag2, vx2, vy2, a2, b2, bias2} = {tag2_q, vx2_q, vy2_q, a2_q, b2_q, bias2_q};
  end else begin : g_one
    assign mnx = min3(vx_q);
    assign mxx = max3(vx_q);
    assign mny = min3(vy_q);
    assign mxy = max3(vy_q);
    assign {tag2, vx2, vy2, a2, b2, bias2} = {tag_q, vx_q, vy_q, a_q, b_q, bias_q};
  end

  logic signed [WBits-1:0] fx, lx, fy, ly, cx0, cy0;
  always_comb begin
    fx = -((Half - mnx) >>> F);
    if (fx < 0) fx = '0;
    lx = (mxx - Half) >>> F;
    if (lx > $signed(WBits'(vp_xmax_i))) lx = $signed(WBits'(vp_xmax_i));
    fy = -((Half - mny) >>> F);
    if (fy < 0) fy = '0;
    ly = (mxy - Half) >>> F;
    if (ly > $signed(WBits'(vp_ymax_i))) ly = $signed(WBits'(vp_ymax_i));
    empty_o = (fx > lx) || (fy > ly);
    cx0 = (fx <<< F) + Half;
    cy0 = (fy <<< F) + Half;
  end

  logic [6*MW-1:0] mag;
  logic [5:0] neg;
  for (genvar k = 0; k < 3; k++) begin : g_edge
    logic signed [WBits-1:0] dx, dy;
    assign dx = cx0 - coord(vx2, k);
    assign dy = cy0 - coord(vy2, k);
    assign neg[2*k]     = dx[WBits-1];
    assign neg[2*k+1]   = dy[WBits-1];
    assign mag[2*k*MW +: MW]     = dx[WBits-1] ? MW'(-dx) : MW'(dx);
    assign mag[(2*k+1)*MW +: MW] = dy[WBits-1] ? MW'(-dy) : MW'(dy);
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) full_q <= 1'b0;
    else if (accept_i) full_q <= 1'b1;
    else if (take_i || empty_o) full_q <= 1'b0;   // an empty box retires in B
  end
  always_ff @(posedge clk_i) begin
    if (accept_i) begin
      tag_q <= tag_i;  vx_q <= vx_i;  vy_q <= vy_i;  a_q <= a_i;  b_q <= b_i;  bias_q <= bias_i;
    end
    if (take_i) begin
      c_tag_o  <= tag2;
      c_x0_o   <= PB'(fx);
      c_y0_o   <= PB'(fy);
      c_xmax_o <= BB'(lx - fx);
      c_ymax_o <= BB'(ly - fy);
      c_a_o    <= a2;
      c_b_o    <= b2;
      c_bias_o <= bias2;
      c_mag_o  <= mag;
      c_neg_o  <= neg;
    end
  end
  assign full_o = full_q;

endmodule
