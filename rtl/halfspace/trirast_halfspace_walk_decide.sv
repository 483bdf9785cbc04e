// The half-space tile walker's decision (u_decide of trirast_halfspace_tile_walker.sv):
// the unit test's outcome from its six signs (rejected, accepted) picks the walker's controls
// among their three values formed beforehand (rejected, accepted, neither). A module of its own,
// kept by synthesis (keep_hierarchy), so that its few inputs bound the logic between the test's
// carry chains and the walker's registers: flattened, the tools mixed the signs into the deep
// control of the registers' terms (measured on iCE40: six LUTs after the carry chain).
(* keep_hierarchy *)
module trirast_halfspace_walk_decide #(
  parameter bit Tiles = 1'b1,
  parameter int CtlBits = 6
) (
  input  logic [2:0]         out_i,         // the unit's corners all outside edge k
  input  logic [2:0]         all_in_i,      // ... all inside edge k
  input  logic [CtlBits-1:0] if_reject_i,
  input  logic [CtlBits-1:0] if_accept_i,
  input  logic [CtlBits-1:0] if_neither_i,
  input  logic [2:0]         state_if_reject_i,
  input  logic [2:0]         state_if_accept_i,
  input  logic [2:0]         state_if_neither_i,
  output logic               reject_o,
  output logic               accept_o,      // tiles only
  output logic [CtlBits-1:0] ctl_o,
  output logic [2:0]         state_o
);
  assign reject_o = |out_i;
  assign accept_o = Tiles && &all_in_i;  // all inside every edge: none rejects
  assign ctl_o = reject_o ? if_reject_i : accept_o ? if_accept_i : if_neither_i;
  assign state_o = reject_o ? state_if_reject_i : accept_o ? state_if_accept_i : state_if_neither_i;
endmodule
