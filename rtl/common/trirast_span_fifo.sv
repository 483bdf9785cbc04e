// Stage 6, span_fifo (docs/timing.md, "Span FIFO and sink"): FifoDepth entries between the walk
// stage and the sink. Up to NumEndpoints pushes per cycle (the non-empty rows of a group, packed
// in row order), one pop per cycle. span_valid_o = (count > 0), the output shows the oldest entry.
// A span pushed in cycle t can be popped from t + 1; count_o is the occupancy at the start of the
// cycle (the walk stage's admission test uses it, so a pop does not make room in its own cycle).
`include "trirast_assert.svh"

module trirast_span_fifo #(
  parameter int NumEndpoints = 1,  // push ports
  parameter int FifoDepth = 8,     // entries (a power of two)
  parameter int EntryBits = 8,     // bits of one span
  parameter int CountBits = $clog2(FifoDepth + 1)  // derived: do not override
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic [NumEndpoints-1:0]             push_i,    // push_i[r]: row r of the group has a span
  input  logic [NumEndpoints*EntryBits-1:0]   data_i,    // row r's span at [r*EntryBits +: EntryBits]
  output logic [CountBits-1:0]                count_o,   // occupancy at the start of the cycle
  output logic                                valid_o,   // span_valid_o
  input  logic                                ready_i,   // span_ready_i
  output logic [EntryBits-1:0]                data_o     // the oldest entry
`ifdef FORMAL
  ,
  // Formal proofs only (tb/formal/, docs/formal.md; FORMAL is defined by Yosys's read_verilog
  // -formal and by no simulation or synthesis flow): the pointers and the storage, read by the
  // proof's invariants.
  output logic [$clog2(FifoDepth)-1:0]        f_wptr_o,
  output logic [$clog2(FifoDepth)-1:0]        f_rptr_o,
  output logic [FifoDepth*EntryBits-1:0]      f_mem_o    // entry k at [k*EntryBits +: EntryBits]
`endif
);
  localparam int PtrBits = $clog2(FifoDepth);
  localparam int PushBits = $clog2(NumEndpoints + 1);

  logic [EntryBits-1:0] mem_q [FifoDepth];
  logic [PtrBits-1:0] wptr_q, wptr_d, rptr_q, rptr_d;
  logic [CountBits-1:0] count_q, count_d;
  logic pop;
  logic [PushBits-1:0] pushes;
  // Write slot of row r: the write pointer plus the spans of the rows before it.
  logic [PtrBits-1:0] slot [NumEndpoints];

  // Spans among rows 0 .. r - 1 of the group.
  function automatic logic [PushBits-1:0] spans_before(input logic [NumEndpoints-1:0] push,
                                                       input int r);
    logic [PushBits-1:0] n;
    n = '0;
    for (int k = 0; k < NumEndpoints; k++) begin
      if (k < r) n = n + PushBits'(push[k]);
    end
    spans_before = n;
  endfunction

  for (genvar r = 0; r < NumEndpoints; r++) begin : g_slot
    assign slot[r] = wptr_q + PtrBits'(spans_before(push_i, r));
  end

  always_comb begin
    valid_o = count_q != '0;
    pop     = valid_o && ready_i;
    pushes  = spans_before(push_i, NumEndpoints);
    wptr_d  = wptr_q + PtrBits'(pushes);
    rptr_d  = rptr_q + PtrBits'(pop);
    count_d = count_q + CountBits'(pushes) - CountBits'(pop);
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wptr_q  <= '0;
      rptr_q  <= '0;
      count_q <= '0;
    end else begin
      wptr_q  <= wptr_d;
      rptr_q  <= rptr_d;
      count_q <= count_d;
    end
  end

  // Storage: written in place (a RAM, no reset), the usual exception to the _d/_q form.
  always_ff @(posedge clk_i) begin
    for (int r = 0; r < NumEndpoints; r++) begin
      if (push_i[r]) mem_q[slot[r]] <= data_i[r*EntryBits +: EntryBits];
    end
  end

  assign count_o = count_q;
  assign data_o  = mem_q[rptr_q];
`ifdef FORMAL
  assign f_wptr_o = wptr_q;
  assign f_rptr_o = rptr_q;
  for (genvar k = 0; k < FifoDepth; k++) begin : g_f_mem
    assign f_mem_o[k*EntryBits +: EntryBits] = mem_q[k];
  end
`endif

  // No push into a full FIFO: the walk stage admits a group only when count + n <= DEPTH at the
  // start of the cycle (DEPTH <= FifoDepth), so the pushes fit without the cycle's pop.
  `ASSERT(FifoNoOverflow_A, 32'(count_q) + 32'(pushes) <= FifoDepth, clk_i, !rst_ni)
  // No pop from an empty FIFO, and the occupancy in 0..FifoDepth.
  `ASSERT_IMPLIES(FifoNoUnderflow_A, pop, count_q != '0, clk_i, !rst_ni)
  `ASSERT(FifoCountInRange_A, 32'(count_q) <= FifoDepth, clk_i, !rst_ni)
  `ASSERT_INIT(FifoDepthPow2_A, FifoDepth >= 1 && (FifoDepth & (FifoDepth - 1)) == 0)

  // Cover points (docs/coverage.md): empty, full (FifoDepth entries: reachable when the run's
  // DEPTH is the build's), and a pop in two cycles in a row.
  `COVER(SpanFifoEmpty_C, count_q == '0, clk_i, !rst_ni)
  `COVER(SpanFifoFull_C, 32'(count_q) == FifoDepth, clk_i, !rst_ni)
  `COVER(SpanFifoPopBackToBack_C, pop && $past(pop), clk_i, !rst_ni)

endmodule
