// gen2 study prototype (not a unit; scripts/gen2_study.sh): three redesigned lanes
// (rtl/improved2/trirast_improved2_edge_lane.sv, normalizer folded in) fed as g1_lanes.sv feeds gen1's, with the
// iteration count of an x division (adaptive: Qx = bits(Xmax) + 1; fixed: Q) computed once and
// registered at the load (the lanes read it from the next cycle on). Boundary mode: step.
module g2_lanes #(
  parameter int Adaptive = 1,
  parameter int PreIter = 0  // trirast_improved2_edge_lane's PreIter
) (
  input  logic                               clk_i,
  input  logic                               rst_ni,
  input  logic                               load_i,
  input  logic [3*trirast_pkg::CoefBits-1:0] a_i,
  input  logic [3*trirast_pkg::CoefBits-1:0] b_i,
  input  logic [3*trirast_pkg::EdgeBits-1:0] el_i,
  input  logic [3*trirast_pkg::EdgeBits-1:0] er_i,
  input  logic [trirast_pkg::BoxBits-1:0]    xmax_i,
  input  logic [trirast_pkg::BoxBits-1:0]    ymax_i,
  output logic [2:0]                         busy_o,
  output logic [2:0]                         done_o,
  output logic [3*trirast_pkg::StepBits-1:0] d_o,
  output logic [3*trirast_pkg::QuotBits-1:0] qs_o,
  output logic [3*trirast_pkg::RemBits-1:0]  rs_o,
  output logic [2:0]                         ssat_o,
  output logic [2:0]                         enters_o,
  output logic [3*trirast_pkg::RowBits-1:0]  j_entry_o,
  output logic [5:0]                         entry_state_o,
  output logic [3*trirast_pkg::WalkerXBits-1:0] entry_x_o,
  output logic [3*trirast_pkg::RemBits-1:0]  entry_e_o,
  output logic [2:0]                         mirror_o,
  output logic [2:0]                         dir_down_o
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

  // Adaptive: registered at the load. Fixed: a constant (so the lanes' shifters vanish).
  logic [IterBits-1:0] m_q;
  if (Adaptive != 0) begin : g_adaptive
    always_ff @(posedge clk_i) begin
      if (load_i) m_q <= bits_plus_one(xmax_i);
    end
  end else begin : g_fixed
    assign m_q = IterBits'(QB);
  end

  for (genvar k = 0; k < 3; k++) begin : g_edge
    /* verilator lint_off PINCONNECTEMPTY */
    trirast_improved2_edge_lane #(.FixedM ((Adaptive != 0) ? 0 : QB), .PreIter (PreIter)) u_lane (
      .clk_i (clk_i), .rst_ni (rst_ni), .m_i (m_q), .load_i (load_i),
      .a_i (a_i[k*CB +: CB]), .b_i (b_i[k*CB +: CB]),
      .e_i (trirast_pkg::lane_reads_right(a_i[k*CB +: CB], b_i[k*CB +: CB])
            ? er_i[k*EB +: EB] : el_i[k*EB +: EB]),   // the value at the lane's column
      .xmax_i (xmax_i), .ymax_i (ymax_i),
      .busy_o (busy_o[k]), .done_o (done_o[k]),
      .horiz_o (), .mirror_o (mirror_o[k]), .dir_down_o (dir_down_o[k]),
      .d_o (d_o[k*SB +: SB]), .qs_o (qs_o[k*QB +: QB]), .rs_o (rs_o[k*RB +: RB]),
      .ssat_o (ssat_o[k]), .enters_o (enters_o[k]), .j_entry_o (j_entry_o[k*WB +: WB]),
      .entry_state_o (entry_state_o[2*k +: 2]), .entry_x_o (entry_x_o[k*XB +: XB]),
      .entry_e_o (entry_e_o[k*RB +: RB]));
    /* verilator lint_on PINCONNECTEMPTY */
  end

endmodule
