// Stage 4b, edge_walker (x3): Bresenham stepping with adders only (docs/unit.md, section 4).
// Loaded at the hand-off with the lane's results (slope, entry row, entry x), it presents the
// state of NumEndpoints consecutive rows j .. j + N - 1 per cycle (a chain of N row steps) and
// advances by the runtime group size when the walk stage processes the group.
`include "trirast_ports.svh"

module trirast_improved_edge_walker #(
  parameter int NumEndpoints = 1  // rows presented per cycle (hardware)
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  // ---- load (hand-off): the lane's results ----
  input  logic                                 load_i,
  `TRIRAST_IMPROVED_EDGE_RESULT(input, _i),
  input  logic [trirast_pkg::RemBits-1:0]      entry_e_i,
  // ---- walking ----
  input  logic [trirast_pkg::BoxBits-1:0]      xmax_i,        // the walked triangle's Xmax
  input  logic [trirast_pkg::RowBits-1:0]      row_i,         // j: first row of the group
  input  logic                                 adv_i,         // the group is processed
  input  logic [2:0]                           adv_rows_i,    // rows per group (1..N)
  output logic                                 mirror_o,      // bounds the span's begin
  output logic [2*NumEndpoints-1:0]            row_state_o,   // row j + r: state (RowOut/..)
  output logic [NumEndpoints*trirast_pkg::WalkerXBits-1:0] row_x_o  // row j + r: X'
);
  `TRIRAST_PKG_NAMES

  // Constants of the walked edge.
  logic mirror_q, mirror_d, dir_q, dir_d, ssat_q, ssat_d, enters_q, enters_d;
  logic [StepBits-1:0] d_q, d_d;
  logic [QuotBits-1:0] qs_q, qs_d;
  logic [RemBits-1:0] rs_q, rs_d, ee_q, ee_d;
  logic [RowBits-1:0] je_q, je_d;
  logic [1:0] est_q, est_d;
  logic signed [WalkerXBits-1:0] ex_q, ex_d;
  // The current row's registers: state, X', Bresenham error e (X'*D + e = T + j*b).
  logic [1:0] st_q, st_d;
  logic signed [WalkerXBits-1:0] x_q, x_d;
  logic [RemBits-1:0] e_q, e_d;

  // Rows j .. j + N: row 0 is the registers, row r + 1 one step after row r.
  localparam int RowStBits = 2 + WalkerXBits + RemBits;  // {state, X', e}
  logic [RowStBits-1:0] row_r [0:NumEndpoints] /* verilator split_var */;
  logic [1:0] st_r [0:NumEndpoints];
  logic signed [WalkerXBits-1:0] x_r [0:NumEndpoints];
  logic [RemBits-1:0] e_r [0:NumEndpoints];

  // One row step of {state, X', e} to row j_next (a function: its temporaries are local, so the
  // always_comb below assigns each row once, as Icarus needs).
  function automatic logic [RowStBits-1:0] step(input logic [RowStBits-1:0] cur,
                                                input logic [RowBits-1:0] j_next);
    logic [1:0] st;
    logic signed [WalkerXBits-1:0] x1;
    logic [RemBits:0] e1;
    st = cur[RowStBits-1 -: 2];
    x1 = cur[RemBits +: WalkerXBits];
    e1 = {1'b0, cur[RemBits-1:0]};
    if (enters_q && j_next == je_q) begin
      // The entry row: load the entry state.
      st = est_q;
      x1 = ex_q;
      e1 = {1'b0, ee_q};
    end else if (st == RowBound) begin
      if (dir_q) begin
        // dir +: X' += q_s, e += r_s, carry one when e reaches D; clear once X' >= Xmax.
        x1 = x1 + WalkerXBits'(qs_q);
        e1 = e1 + {1'b0, rs_q};
        if (e1 >= {1'b0, d_q}) begin
          e1 = e1 - {1'b0, d_q};
          x1 = x1 + 1'b1;
        end
        st = (ssat_q || x1 >= $signed(WalkerXBits'(xmax_i))) ? RowClear : RowBound;
      end else begin
        // dir -: X' -= q_s, e -= r_s, borrow one when e goes negative; out once X' < 0.
        x1 = x1 - WalkerXBits'(qs_q);
        e1 = e1 - {1'b0, rs_q};
        if (e1[RemBits]) begin
          e1 = e1 + {1'b0, d_q};
          x1 = x1 - 1'b1;
        end
        st = (ssat_q || x1[WalkerXBits-1]) ? RowOut : RowBound;
      end
    end
    step = {st, x1, e1[RemBits-1:0]};
  endfunction

  assign row_r[0] = {st_q, x_q, e_q};
  for (genvar r = 0; r < NumEndpoints; r++) begin : g_step
    assign row_r[r+1] = step(row_r[r], row_i + RowBits'(r + 1));
  end
  for (genvar r = 0; r <= NumEndpoints; r++) begin : g_split
    assign st_r[r] = row_r[r][RowStBits-1 -: 2];
    assign x_r[r]  = row_r[r][RemBits +: WalkerXBits];
    assign e_r[r]  = row_r[r][RemBits-1:0];
  end

  always_comb begin
    {mirror_d, dir_d, ssat_d, enters_d, d_d, qs_d, rs_d, ee_d, je_d, est_d, ex_d, st_d, x_d, e_d} =
        {mirror_q, dir_q, ssat_q, enters_q, d_q, qs_q, rs_q, ee_q, je_q, est_q, ex_q, st_q, x_q,
         e_q};
    if (load_i) begin
      // One assignment each: as a single concatenation this load maps to 93 more xc7 LUTs at the
      // small widths (ABC; the same logic).
      mirror_d = mirror_i;
      dir_d    = dir_down_i;
      ssat_d   = ssat_i;
      enters_d = enters_i;
      d_d      = d_i;
      qs_d     = qs_i;
      rs_d     = rs_i;
      ee_d     = entry_e_i;
      je_d     = j_entry_i;
      est_d    = entry_state_i;
      ex_d     = entry_x_i;
      // Row 0: before the entry the edge is out (dir +) or clear (dir -).
      if (enters_i && j_entry_i == '0) begin
        st_d = entry_state_i;
        x_d  = entry_x_i;
        e_d  = entry_e_i;
      end else begin
        st_d = dir_down_i ? RowOut : RowClear;
        x_d  = entry_x_i;
        e_d  = entry_e_i;
      end
    end else if (adv_i) begin
      // Advance by the group: row j + adv_rows.
      for (int r = 1; r <= NumEndpoints; r++) begin
        if (32'(adv_rows_i) == r) begin
          st_d = st_r[r];
          x_d  = x_r[r];
          e_d  = e_r[r];
        end
      end
    end
  end

  `TRIRAST_FLOP_AR(st_q, st_d, RowOut)

  // Datapath registers: no reset (loaded at the hand-off before use).
  always_ff @(posedge clk_i) begin
    {mirror_q, dir_q, ssat_q, enters_q, d_q, qs_q, rs_q, ee_q, je_q, est_q, ex_q, x_q, e_q} <=
        {mirror_d, dir_d, ssat_d, enters_d, d_d, qs_d, rs_d, ee_d, je_d, est_d, ex_d, x_d, e_d};
  end

  assign mirror_o = mirror_q;
  for (genvar r = 0; r < NumEndpoints; r++) begin : g_out
    assign row_state_o[2*r +: 2]     = st_r[r];
    assign row_x_o[r*WalkerXBits +: WalkerXBits] = x_r[r];
  end

endmodule
