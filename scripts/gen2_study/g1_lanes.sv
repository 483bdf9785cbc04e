// gen2 study reference (not a unit; scripts/gen2_study.sh): the first generation's three edge
// normalizers and three edge lanes (rtl/improved/trirast_improved_edge_normalizer.sv, rtl/improved/trirast_improved_edge_lane.sv)
// connected as in rtl/improved/trirast_improved_setup_stage.sv, fed with the interface's outputs (A, B, E_L, E_R,
// Xmax, Ymax), so that the lanes are measured with the operand structure they see in the unit
// (D = |A|*u and s = |B|*u have F zero low bits) and with the iteration counts of the adaptive
// divider computed as there. TieMode = 1: the boundary mode tied to step and the divider to
// adaptive (what a build parameter instead of the runtime inputs would give).
module g1_lanes #(
  parameter int TieMode = 0
) (
  input  logic                               clk_i,
  input  logic                               rst_ni,
  input  logic                               divide_i,
  input  logic                               adaptive_i,
  input  logic                               load_i,
  input  logic [3*trirast_pkg::CoefBits-1:0] a_i,
  input  logic [3*trirast_pkg::CoefBits-1:0] b_i,
  input  logic [3*trirast_pkg::EdgeBits-1:0] el_i,
  input  logic [3*trirast_pkg::EdgeBits-1:0] er_i,
  input  logic [trirast_pkg::BoxBits-1:0]    xmax_i,
  input  logic [trirast_pkg::BoxBits-1:0]    ymax_i,
  output logic [2:0]                         busy_o,
  output logic [2:0]                         done_next_o,
  output logic [3*trirast_pkg::QuotBits-1:0] qs_o,
  output logic [3*trirast_pkg::RemBits-1:0]  rs_o,
  output logic [2:0]                         ssat_o,
  output logic [2:0]                         enters_o,
  output logic [3*trirast_pkg::RowBits-1:0]  j_entry_o,
  output logic [5:0]                         entry_state_o,
  output logic [3*trirast_pkg::WalkerXBits-1:0] entry_x_o,
  output logic [3*trirast_pkg::RemBits-1:0]  entry_e_o,
  output logic [2:0]                         flags_o   // mirror of each lane (the others alike)
);
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int SB = trirast_pkg::StepBits;
  localparam int QB = trirast_pkg::QuotBits;
  localparam int RB = trirast_pkg::RemBits;
  localparam int WB = trirast_pkg::RowBits;
  localparam int XB = trirast_pkg::WalkerXBits;
  localparam int IterBits = $clog2(trirast_pkg::QuotBits + 1);

  function automatic logic [IterBits-1:0] bits_plus_one(input logic [trirast_pkg::BoxBits-1:0] v);
    logic [IterBits-1:0] n;
    n = IterBits'(1);
    for (int i = 0; i < trirast_pkg::BoxBits; i++) begin
      if (v[i]) n = IterBits'(i + 1);
    end
    bits_plus_one = n + 1'b1;
  endfunction

  logic [IterBits-1:0] qx, qy;
  logic divide, adaptive;
  assign divide   = (TieMode != 0) ? 1'b0 : divide_i;
  assign adaptive = (TieMode != 0) ? 1'b1 : adaptive_i;
  assign qx = adaptive ? bits_plus_one(xmax_i) : IterBits'(trirast_pkg::QuotBits);
  assign qy = adaptive ? bits_plus_one(ymax_i) : IterBits'(trirast_pkg::QuotBits);

  for (genvar k = 0; k < 3; k++) begin : g_edge
    logic horiz, mirror, dir_down;
    logic signed [EB-1:0] t, t1;
    logic [SB-1:0] d, s;
    trirast_improved_edge_normalizer u_normalizer (
      .a_i (a_i[k*CB +: CB]), .b_i (b_i[k*CB +: CB]),
      .el_i (el_i[k*EB +: EB]), .er_i (er_i[k*EB +: EB]),
      .horiz_o (horiz), .mirror_o (mirror), .dir_down_o (dir_down),
      .t_o (t), .t1_o (t1), .d_o (d), .s_o (s));
    /* verilator lint_off PINCONNECTEMPTY */
    trirast_improved_edge_lane u_lane (
      .clk_i (clk_i), .rst_ni (rst_ni), .divide_i (divide), .qx_i (qx), .qy_i (qy),
      .load_i (load_i), .horiz_i (horiz), .mirror_i (mirror), .dir_down_i (dir_down),
      .t_i (t), .t1_i (t1), .d_i (d), .s_i (s), .xmax_i (xmax_i), .ymax_i (ymax_i),
      .busy_o (busy_o[k]), .done_next_o (done_next_o[k]), .div_o (),
      .horiz_o (), .mirror_o (flags_o[k]), .dir_down_o (), .d_o (),
      .qs_o (qs_o[k*QB +: QB]), .rs_o (rs_o[k*RB +: RB]), .ssat_o (ssat_o[k]),
      .enters_o (enters_o[k]), .j_entry_o (j_entry_o[k*WB +: WB]),
      .entry_state_o (entry_state_o[2*k +: 2]), .entry_x_o (entry_x_o[k*XB +: XB]),
      .entry_e_o (entry_e_o[k*RB +: RB]));
    /* verilator lint_on PINCONNECTEMPTY */
  end

endmodule
