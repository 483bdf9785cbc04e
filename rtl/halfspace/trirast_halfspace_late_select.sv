// The span emitter's late select (u_upd): which rows' runs this cycle's pieces set, formed for an
// accepted unit and for one that is not, and picked by the unit test's accept last. A module of
// its own, kept by synthesis (keep_hierarchy) as trirast_halfspace_walk_decide is, so that only
// this mux lies between the test and the runs' registers.
(* keep_hierarchy *)
module trirast_halfspace_late_select #(
  parameter int Bits = 8
) (
  input  logic            sel_i,
  input  logic [Bits-1:0] if_set_i,
  input  logic [Bits-1:0] if_clear_i,
  output logic [Bits-1:0] o
);
  assign o = sel_i ? if_set_i : if_clear_i;
endmodule
