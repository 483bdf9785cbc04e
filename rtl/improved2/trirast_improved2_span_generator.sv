// The second-generation improved unit's span generator of one row (rtl/improved2/trirast_improved2.f), with
// parallel compares. Takes the three walkers' restored bounds minus one, b = bound - 1
// (trirast_improved2_edge_walker keeps them in registers; a bound row's bound lies in [1, Xmax], so b in
// [0, Xmax - 1]), computes the six ordered compares b_i < b_j at once and derives from them, in
// one level of selection each: begin - 1 = max(-1, mirrored b), end - 1 = min(Xmax, other b),
// and valid = no edge out and every mirrored b < every other b (= begin < end). The outputs are
// begin - 1 (BoxBits + 1 bits, two's complement: -1 when no mirrored bound) and end - 1: the walk
// stage adds x0 + 1 with one carry-in, and end needs no incrementer for its default Xmax + 1.
`include "trirast_ports.svh"

module trirast_improved2_span_generator (
  input  logic [5:0]                          state_i,
  input  logic [3*(trirast_pkg::BoxBits+1)-1:0] bound_i,
  input  logic [2:0]                          mirror_i,
  input  logic [trirast_pkg::BoxBits-1:0]     xmax_i,
  output logic                                valid_o,
  output logic [trirast_pkg::BoxBits:0]       begin_o,
  output logic [trirast_pkg::BoxBits:0]       end_o
);
  localparam int B1 = trirast_pkg::BoxBits + 1;
  `TRIRAST_PKG_NAMES

  // All in one always_comb over packed vectors: the six ordered compares b_i < b_j first (one
  // level), then the selections and the validity from them.
  always_comb begin
    logic [2:0] isb, ism, isn;   // bound; bound and mirrored (begin); bound, not mirrored (end)
    logic [8:0] lt;              // lt[3*i + j] = b_i < b_j
    logic out, ok, top, low;
    logic [B1-1:0] e;
    out = 1'b0;
    for (int k = 0; k < 3; k++) begin
      isb[k] = state_i[2*k +: 2] == RowBound;
      ism[k] = isb[k] && mirror_i[k];
      isn[k] = isb[k] && !mirror_i[k];
      if (state_i[2*k +: 2] == RowOut) out = 1'b1;
    end
    for (int i = 0; i < 3; i++) begin
      for (int j = 0; j < 3; j++) begin
        lt[3*i + j] = (i != j) && (bound_i[i*B1 +: B1] < bound_i[j*B1 +: B1]);
      end
    end
    // begin - 1: the AND of the mirrored b that no other mirrored b exceeds (ties select equal
    // values, so the AND is still that value), all ones (-1) when there is none; end - 1: the OR
    // of the smallest non-mirrored b likewise, or Xmax when there is none.
    begin_o = '1;   // -1: begin 0
    e = '0;
    for (int i = 0; i < 3; i++) begin
      top = ism[i];
      low = isn[i];
      for (int j = 0; j < 3; j++) begin
        if (j != i) begin
          if (ism[j] && lt[3*i + j]) top = 1'b0;
          if (isn[j] && lt[3*j + i]) low = 1'b0;
        end
      end
      if (top) begin_o = begin_o & bound_i[i*B1 +: B1];
      if (low) e = e | bound_i[i*B1 +: B1];
    end
    end_o = (isn == 3'b000) ? B1'(xmax_i) : e;
    ok = !out;
    for (int i = 0; i < 3; i++) begin
      for (int j = 0; j < 3; j++) begin
        if (i != j && ism[i] && isn[j] && !lt[3*i + j]) ok = 1'b0;
      end
    end
    valid_o = ok;
  end

endmodule
