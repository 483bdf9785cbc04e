// The span FIFO and span port of a unit (trirast_improved_top, trirast_trad_top): the walk stage's pushes
// go into trirast_span_fifo (FifoDepth entries, NumEndpoints push ports, one pop per cycle), whose
// oldest entry {tag, y, x_begin, x_end} is the span port. count_o is the occupancy at the start
// of the cycle: the walk stage's admission test and the unit's fifo_count_o.
// The span port is a valid/ready handshake: a span stays on the port, unchanged, until the sink
// takes it (asserted below).
`include "trirast_assert.svh"

module trirast_span_port #(
  parameter int NumEndpoints = trirast_pkg::DefaultEndpoints,  // push ports (rows per group)
  parameter int FifoDepth = trirast_pkg::DefaultFifoDepth,     // entries (a power of two)
  parameter int CountBits = $clog2(FifoDepth + 1),             // derived: do not override
  parameter int EntryBits = trirast_pkg::TagBits + 3 * trirast_pkg::PixBits + 1  // derived
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  // ---- pushes from the walk stage ----
  input  logic [NumEndpoints-1:0]             push_i,        // push_i[r]: row r has a span
  input  logic [NumEndpoints*EntryBits-1:0]   push_data_i,   // row r's {tag, y, x_begin, x_end}
  output logic [CountBits-1:0]                count_o,       // occupancy at the cycle's start
  // ---- span port ----
  output logic                                span_valid_o,
  input  logic                                span_ready_i,
  output logic [trirast_pkg::TagBits-1:0]     span_tag_o,
  output logic [trirast_pkg::PixBits-1:0]     span_y_o,
  output logic [trirast_pkg::PixBits-1:0]     span_x_begin_o,
  output logic [trirast_pkg::PixBits:0]       span_x_end_o   // exclusive
`ifdef FORMAL
  ,
  // Formal proofs only (tb/formal/, docs/formal.md): the FIFO's pointers and storage.
  output logic [$clog2(FifoDepth)-1:0]        f_wptr_o,
  output logic [$clog2(FifoDepth)-1:0]        f_rptr_o,
  output logic [FifoDepth*EntryBits-1:0]      f_mem_o
`endif
);
  logic [EntryBits-1:0] head;

  trirast_span_fifo #(
    .NumEndpoints (NumEndpoints),
    .FifoDepth    (FifoDepth),
    .EntryBits    (EntryBits)
  ) u_span_fifo (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .push_i  (push_i),
    .data_i  (push_data_i),
    .count_o (count_o),
    .valid_o (span_valid_o),
    .ready_i (span_ready_i),
    .data_o  (head)
`ifdef FORMAL
    ,
    .f_wptr_o (f_wptr_o),
    .f_rptr_o (f_rptr_o),
    .f_mem_o  (f_mem_o)
`endif
  );

  assign {span_tag_o, span_y_o, span_x_begin_o, span_x_end_o} = head;

  `TRIRAST_SPAN_PORT_CHECKS(span_valid_o, span_ready_i, head, count_o)

endmodule
