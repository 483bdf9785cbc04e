// Formal harness of the box stage's accept-cycle form (rtl/common/trirast_box_stage.sv,
// BoxAtAccept 1: the half-space unit's; docs/formal.md "The box at accept"). The vertices, the
// edge terms and the accept are free in every cycle and the viewport is any constant; the box
// cycle follows each accept as in the setup stage's FSM (StIdle -> StBox). The property is the
// stage's own BoxAtAcceptIsBox_A: the first pixel, Xmax, Ymax and the empty test equal those of
// the StBox form (first_px/last_px of min3/max3 of the held vertices) for every triangle and
// viewport. A box cycle's state depends only on the accept before it and on the viewport
// thresholds registered in every cycle, so the induction closes at depth 3.
`include "trirast_ports.svh"

module formal_box_at_accept (
  input logic clk_i
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES

  (* anyseq *) logic rst_ni;
  (* anyseq *) logic accept_i;
  (* anyseq *) logic [3*P-1:0] vx_i, vy_i;
  (* anyseq *) logic [3*CB-1:0] a_i, b_i;
  (* anyseq *) logic [3*EB-1:0] c_i;
  (* anyseq *) logic [2:0] bias_i;
  (* anyseq *) logic [TB-1:0] tag_i;
  (* anyconst *) logic [PB-1:0] vp_xmax_i, vp_ymax_i;

  logic box_q = 1'b0;  // the FSM's StBox: the cycle after an accept
  always @(posedge clk_i) box_q <= rst_ni && accept_i;

  logic first_q = 1'b1;
  always @(posedge clk_i) first_q <= 1'b0;
  always @* begin
    if (first_q) assume (!rst_ni);
    if (!rst_ni || box_q) assume (!accept_i);
  end

  logic empty;
  logic [TB-1:0] tag_o;
  logic [PB-1:0] x0, y0;
  logic [BB-1:0] xmax, ymax;
  logic [3*P-1:0] vx_o, vy_o;
  logic [2:0] bias_o;
  logic [3*CB-1:0] a_o, b_o;
  logic [3*EB-1:0] el_o, er_o;
  trirast_box_stage #(.BoxAtAccept (1'b1)) dut (
    .clk_i (clk_i), .rst_ni (rst_ni), .vp_xmax_i (vp_xmax_i), .vp_ymax_i (vp_ymax_i),
    .accept_i (accept_i), .tag_i (tag_i), .vx_i (vx_i), .vy_i (vy_i), .a_i (a_i), .b_i (b_i),
    .c_i (c_i), .bias_i (bias_i), .box_i (box_q), .empty_o (empty), .tag_o (tag_o), .x0_o (x0),
    .y0_o (y0), .xmax_o (xmax), .ymax_o (ymax), .vx_o (vx_o), .vy_o (vy_o), .bias_o (bias_o),
    .a_o (a_o), .b_o (b_o), .el_o (el_o), .er_o (er_o));

  // Reachability: a box clipped by the viewport's last column, one starting at column 0 after the
  // clip at 0, and an empty one.
  always @(posedge clk_i) begin
    if (rst_ni && box_q) begin
      cover (!empty && dut.g_box_at_accept.lx_q == (P + 2)'(vp_xmax_i) &&
             vp_xmax_i != '0);
      cover (!empty && dut.g_box_at_accept.fx_q[P+1]);
      cover (empty);
    end
  end
endmodule
