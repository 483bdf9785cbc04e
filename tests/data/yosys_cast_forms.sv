// The size-cast forms scripts/check_yosys_casts.py rejects (ctest rtl_yosys_casts_planted: each
// line below must be found; the check passes only on rtl/ without them). Not a design.
module yosys_cast_forms #(parameter int PB = 8, parameter int BoxBits = 6) (
  input  logic [PB-1:0] x0_i,
  input  logic [1:0] row0, row1,
  input  logic [BoxBits-1:0] xmax, u,
  output logic [2*(PB+1)-1:0] xe_o,
  output logic [BoxBits-1:0] last_o
);
  assign last_o = xmax & ~BoxBits'(u - 1);
  assign xe_o = {{1'b0, x0_i} + (PB + 1)'(row1[1] ? 2 : 1),
                 {1'b0, x0_i} + (PB + 1)'(row0[1] ? 2 : 1)};
endmodule
