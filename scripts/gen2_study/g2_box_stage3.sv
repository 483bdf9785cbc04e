// gen2 study prototype (not a unit; scripts/gen2_study.sh): the box stage B of the recommended
// gen2 front end (docs/gen2-design.md, section 2) in three pipelined steps, with valid bits and
// back-pressure. Same function as g2_box_stage.sv (gen1's box, rtl/common/trirast_box_stage.sv, and the
// corner stage's operands |dxL|, |dy| with their signs), retimed so that no step has more than
// one carry chain in series:
//  step 1  per vertex the first pixel whose centre is at or right of it, ceil((v - h)/u) =
//          (v + h - 1) >>> F, and the last at or left of it, floor((v - h)/u) = (v - h) >>> F,
//          beside three comparators per axis; the min (max) vertex selects its first (last)
//          pixel (both monotone in v, so the first pixel of the min is the min of the firsts);
//  step 2  the clip to [0, vp] and the empty test from those registered pixel indices and the
//          viewport (fx > lx is: last < 0, first > vp or first > last; three comparators side
//          by side, not clip -> compare);
//  step 3  Xmax = lx - fx, Ymax, and per edge k dxL = cx0 - vx_k (cx0 = {fx, h}, no adder) and
//          dy, the magnitude chosen between cx0 - v and v - cx0 (no negation after the subtract).
// The empty flag is a register in the last step: an empty triangle retires from it without
// reaching the stall chain through a comparator.
//  PortMinMax = 0: the triangle register, then a register after each step (steps 1, 2 and the
//      operands into the corner stage's register): three copies of the triangle in flight,
//      the corner stage's register written one cycle later than g2_box_stage's Split = 1;
//  PortMinMax = 1: step 1 on the triangle port's data, before the triangle register (the port's
//      producer must drive them from a register): two copies, the same latency as Split = 1.
// Handshake: ready_o says the first register can take a triangle this cycle (accept_i only then);
// full_o says the last step holds a triangle, empty_o (with full_o) that its box has no pixel
// centre: it retires in that cycle; take_i (only with full_o and not empty_o) writes it into the
// corner stage's register. Every step holds while the one after it is full and not leaving.
// The viewport (vp_*) is configuration: constant while triangles are in flight.
module g2_box_stage3 #(
  parameter int PortMinMax = 0
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic [trirast_pkg::PixBits-1:0]      vp_xmax_i,
  input  logic [trirast_pkg::PixBits-1:0]      vp_ymax_i,
  input  logic                                 accept_i,  // the triangle port hands one over
  input  logic [trirast_pkg::TagBits-1:0]      tag_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] vx_i,
  input  logic [3*trirast_pkg::VertexBits-1:0] vy_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]   a_i,
  input  logic [3*trirast_pkg::CoefBits-1:0]   b_i,
  input  logic [2:0]                           bias_i,
  output logic                                 ready_o,   // the first register can take one
  input  logic                                 take_i,    // the corner stage takes the triangle
  output logic                                 full_o,    // the last step holds a triangle
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
  localparam int XB = WBits - F;  // signed pixel index before the clip
  localparam logic signed [WBits-1:0] Half = WBits'(1) << (F - 1);
  localparam int TriBits = TB + 6 * P + 6 * CB + 3;  // tag, vertices, A, B, bias

  function automatic logic signed [WBits-1:0] coord(input logic [3*P-1:0] v, input int k);
    coord = {{2{v[k*P+P-1]}}, v[k*P +: P]};
  endfunction
  // ceil((v - h)/u) = (v + h - 1) >>> F and floor((v - h)/u) = (v - h) >>> F of vertex k.
  function automatic logic signed [XB-1:0] first_of(input logic [3*P-1:0] v, input int k);
    logic signed [WBits-1:0] t;
    t = coord(v, k) + (Half - 1);
    first_of = XB'(t >>> F);
  endfunction
  function automatic logic signed [XB-1:0] last_of(input logic [3*P-1:0] v, input int k);
    logic signed [WBits-1:0] t;
    t = coord(v, k) - Half;
    last_of = XB'(t >>> F);
  endfunction
  // Step 1 for one axis: {first pixel of the min, last pixel of the max}, signed XB bits each.
  // Three comparators serve both: the min is vertex 0 if it is below both others, else 1 if
  // below 2, else 2 (ties pick equal values); the max likewise.
  function automatic logic [2*XB-1:0] extent(input logic [3*P-1:0] v);
    logic lt01, lt02, lt12;
    lt01 = coord(v, 0) < coord(v, 1);
    lt02 = coord(v, 0) < coord(v, 2);
    lt12 = coord(v, 1) < coord(v, 2);
    extent[2*XB-1:XB] = (lt01 && lt02) ? first_of(v, 0) : (lt12 ? first_of(v, 1) : first_of(v, 2));
    extent[XB-1:0]    = (!lt01 && !lt02) ? last_of(v, 0) : (!lt12 ? last_of(v, 1) : last_of(v, 2));
  endfunction
  // Step 2 for one axis: {empty, first pixel clipped, last pixel clipped} (PB bits each; when the
  // axis is not empty 0 <= first <= last <= vp, so they fit).
  function automatic logic [2*PB:0] clip(input logic [2*XB-1:0] e, input logic [PB-1:0] vp);
    logic signed [XB-1:0] f, l, lim;
    f = e[2*XB-1:XB];
    l = e[XB-1:0];
    lim = $signed(XB'(vp));
    clip[2*PB] = (l < 0) || (f > lim) || (f > l);
    clip[2*PB-1:PB] = f[XB-1] ? '0 : PB'(f);
    clip[PB-1:0] = (l > lim) ? vp : PB'(l);
  endfunction

  // ---- the triangle register (R1) and its step-1 result ----
  logic v1_q;
  logic [TriBits-1:0] tri1_q;
  logic [4*XB-1:0] ext_port, ext1;
  assign ext_port = {extent(vx_i), extent(vy_i)};

  // ---- R2 / R3: step by step ----
  logic v2_q, v3_q, e3_q;
  logic [TriBits-1:0] tri3_q;
  logic [4*PB-1:0] box3_q;   // fx, lx, fy, ly
  logic adv1, adv2, adv3;    // the step's register is free or its triangle leaves this cycle
  logic [4*XB-1:0] ext2;
  logic [TriBits-1:0] tri2;
  logic v2;

  assign adv3 = !v3_q || take_i || e3_q;
  assign ready_o = adv1;

  if (PortMinMax != 0) begin : g_port
    // R1 holds the triangle and its extent; R1 -> step 2 -> R3 (the last step).
    logic [4*XB-1:0] ext1_q;
    always_ff @(posedge clk_i) if (accept_i) ext1_q <= ext_port;
    assign adv1 = !v1_q || adv3;
    assign adv2 = adv3;
    assign {ext2, tri2, v2} = {ext1_q, tri1_q, v1_q};
    assign ext1 = ext1_q;
  end else begin : g_three
    // R1 holds the triangle; step 1 -> R2 (triangle copy and extent) -> step 2 -> R3.
    logic [4*XB-1:0] ext2_q;
    logic [TriBits-1:0] tri2_q;
    logic [3*P-1:0] vx1, vy1;
    assign vx1 = tri1_q[TriBits-TB-1 -: 3*P];
    assign vy1 = tri1_q[TriBits-TB-3*P-1 -: 3*P];
    assign ext1 = {extent(vx1), extent(vy1)};
    assign adv2 = !v2_q || adv3;
    assign adv1 = !v1_q || adv2;
    always_ff @(posedge clk_i) begin
      if (adv2) begin
        ext2_q <= ext1;
        tri2_q <= tri1_q;
      end
    end
    assign {ext2, tri2, v2} = {ext2_q, tri2_q, v2_q};
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      v1_q <= 1'b0;
      v2_q <= 1'b0;
      v3_q <= 1'b0;
    end else begin
      if (adv1) v1_q <= accept_i;
      if (adv2) v2_q <= v1_q;   // unused when PortMinMax = 1
      if (adv3) v3_q <= v2;
    end
  end

  // Step 2 -> R3.
  logic [2*PB:0] cx, cy;
  assign cx = clip(ext2[4*XB-1:2*XB], vp_xmax_i);
  assign cy = clip(ext2[2*XB-1:0], vp_ymax_i);
  always_ff @(posedge clk_i) begin
    if (accept_i) tri1_q <= {tag_i, vx_i, vy_i, a_i, b_i, bias_i};
    if (adv3) begin
      tri3_q <= tri2;
      box3_q <= {cx[2*PB-1:0], cy[2*PB-1:0]};
      e3_q   <= cx[2*PB] || cy[2*PB];
    end
  end

  // Step 3 -> the corner stage's register.
  logic [TB-1:0] tag3;
  logic [3*P-1:0] vx3, vy3;
  logic [3*CB-1:0] a3, b3;
  logic [2:0] bias3;
  logic [PB-1:0] fx3, lx3, fy3, ly3;
  assign {tag3, vx3, vy3, a3, b3, bias3} = tri3_q;
  assign {fx3, lx3, fy3, ly3} = box3_q;
  logic signed [WBits-1:0] cx0, cy0;
  assign cx0 = $signed(WBits'({fx3, Half[F-1:0]}));
  assign cy0 = $signed(WBits'({fy3, Half[F-1:0]}));

  logic [6*MW-1:0] mag;
  logic [5:0] neg;
  for (genvar k = 0; k < 3; k++) begin : g_edge
    logic signed [WBits-1:0] dxp, dxn, dyp, dyn;
    assign dxp = cx0 - coord(vx3, k);
    assign dxn = coord(vx3, k) - cx0;
    assign dyp = cy0 - coord(vy3, k);
    assign dyn = coord(vy3, k) - cy0;
    assign neg[2*k]     = dxp[WBits-1];
    assign neg[2*k+1]   = dyp[WBits-1];
    assign mag[2*k*MW +: MW]     = dxp[WBits-1] ? MW'(dxn) : MW'(dxp);
    assign mag[(2*k+1)*MW +: MW] = dyp[WBits-1] ? MW'(dyn) : MW'(dyp);
  end

  always_ff @(posedge clk_i) begin
    if (take_i) begin
      c_tag_o  <= tag3;
      c_x0_o   <= fx3;
      c_y0_o   <= fy3;
      c_xmax_o <= BB'(lx3 - fx3);
      c_ymax_o <= BB'(ly3 - fy3);
      c_a_o    <= a3;
      c_b_o    <= b3;
      c_bias_o <= bias3;
      c_mag_o  <= mag;
      c_neg_o  <= neg;
    end
  end
  assign full_o = v3_q;
  assign empty_o = e3_q;

endmodule
