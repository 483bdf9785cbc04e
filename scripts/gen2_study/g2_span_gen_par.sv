// gen2 study prototype (not a unit; scripts/gen2_study.sh): the span generator of one row with
// parallel compares. Takes the three walkers' restored bounds (g2_walker_cs keeps them in
// registers), computes the six ordered compares b_i < b_j at once and derives from them, in one
// level of selection each: begin = max(0, mirrored bounds), end = min(Xmax + 1, other bounds),
// and valid = no edge out and every mirrored bound < every other bound (= begin < end, since a
// bound edge's bound lies in [0, Xmax + 1]).
module g2_span_gen_par (
  input  logic [5:0]                          state_i,
  input  logic [3*(trirast_pkg::BoxBits+1)-1:0] bound_i,
  input  logic [2:0]                          mirror_i,
  input  logic [trirast_pkg::BoxBits-1:0]     xmax_i,
  output logic                                valid_o,
  output logic [trirast_pkg::BoxBits:0]       begin_o,
  output logic [trirast_pkg::BoxBits:0]       end_o
);
  localparam int B1 = trirast_pkg::BoxBits + 1;
  localparam logic [1:0] RowOut = trirast_pkg::RowOut;
  localparam logic [1:0] RowBound = trirast_pkg::RowBound;

  logic [B1-1:0] bnd [3];
  logic [2:0] isb, ism, isn;    // bound; bound and mirrored (begin); bound, not mirrored (end)
  logic out;
  logic lt [3][3];
  for (genvar k = 0; k < 3; k++) begin : g_k
    assign bnd[k] = bound_i[k*B1 +: B1];
    assign isb[k] = state_i[2*k +: 2] == RowBound;
    assign ism[k] = isb[k] && mirror_i[k];
    assign isn[k] = isb[k] && !mirror_i[k];
  end
  assign out = (state_i[1:0] == RowOut) || (state_i[3:2] == RowOut) || (state_i[5:4] == RowOut);
  for (genvar i = 0; i < 3; i++) begin : g_i
    for (genvar j = 0; j < 3; j++) begin : g_j
      if (i != j) begin : g_lt
        assign lt[i][j] = bnd[i] < bnd[j];
      end else begin : g_eq
        assign lt[i][j] = 1'b0;
      end
    end
  end

  // begin: the OR of the mirrored bounds that no other mirrored bound exceeds (ties select equal
  // values, so the OR is still that value); end: likewise the smallest non-mirrored bound, or
  // Xmax + 1 when there is none.
  always_comb begin
    logic ok, top, low;
    logic [B1-1:0] e;
    begin_o = '0;
    e = '0;
    for (int i = 0; i < 3; i++) begin
      top = ism[i];
      low = isn[i];
      for (int j = 0; j < 3; j++) begin
        if (j != i) begin
          if (ism[j] && lt[i][j]) top = 1'b0;
          if (isn[j] && lt[j][i]) low = 1'b0;
        end
      end
      if (top) begin_o = begin_o | bnd[i];
      if (low) e = e | bnd[i];
    end
    end_o = (isn == 3'b000) ? B1'(xmax_i) + 1'b1 : e;
    ok = !out;
    for (int i = 0; i < 3; i++) begin
      for (int j = 0; j < 3; j++) begin
        if (i != j && ism[i] && isn[j] && !lt[i][j]) ok = 1'b0;
      end
    end
    valid_o = ok;
  end

endmodule
