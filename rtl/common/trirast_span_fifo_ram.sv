// The second-generation improved unit's span FIFO in block RAM (rtl/improved2/trirast_improved2.f, FifoRam 1;
// docs/improved2.md, "Build choices"): the span FIFO of rtl/common/trirast_span_fifo.sv
// (NumEndpoints 1) with its storage in a memory read through a register, so synth_ice40 maps it to
// block RAM (SB_RAM40_4K) instead of FifoDepth * EntryBits flip-flops. The same cycles and outputs
// whenever valid_o is 1: a span pushed in cycle t shows from t + 1, count_o is the occupancy at the
// start of the cycle.
// The memory is written a cycle ahead of the push: the walk stage registers its push (push_i in
// t), and it writes the span into the memory from the cycle before (wr_i, wdata_i in t - 1: the
// push register's inputs), so the read register, loaded every cycle from the next cycle's head
// (rptr + pop), finds a span pushed in t in the memory at the end of t: no collision of a write
// with a read that is shown, and no bypass register. (A write at the end of t - 1 reads the old
// word at its address only when that address is the head of an empty FIFO in t: not shown. The
// written slot is free: the push in t has room, so the FIFO holds fewer than FifoDepth entries
// then, and the tail is not the head of a non-empty FIFO.)
`include "trirast_assert.svh"
module trirast_span_fifo_ram #(
  parameter int FifoDepth = 8,     // entries (a power of two)
  parameter int EntryBits = 8,     // bits of one span
  parameter int CountBits = $clog2(FifoDepth + 1)  // derived: do not override
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  input  logic                 wr_i,      // the push of the next cycle: write wdata_i
  input  logic [EntryBits-1:0] wdata_i,
  input  logic                 push_i,    // a span is pushed (written the cycle before)
  output logic [CountBits-1:0] count_o,   // occupancy at the start of the cycle
  output logic                 valid_o,
  input  logic                 ready_i,
  output logic [EntryBits-1:0] data_o     // the oldest entry (when valid_o)
`ifdef FORMAL
  ,
  // Formal proofs only (tb/formal/, docs/formal.md; FORMAL is defined by Yosys's read_verilog
  // -formal and by no simulation or synthesis flow): the pointers and the storage.
  output logic [((FifoDepth > 1) ? $clog2(FifoDepth) : 1)-1:0] f_wptr_o,
  output logic [((FifoDepth > 1) ? $clog2(FifoDepth) : 1)-1:0] f_rptr_o,
  output logic [FifoDepth*EntryBits-1:0] f_mem_o   // entry k at [k*EntryBits +: EntryBits]
`endif
);
  localparam int PtrBits = (FifoDepth > 1) ? $clog2(FifoDepth) : 1;

  (* no_rw_check *) logic [EntryBits-1:0] mem [FifoDepth];   // a collision is not shown
  logic [PtrBits-1:0] wptr_q, rptr_q, rptr_d;   // wptr_q: the slot of the next write
  logic [CountBits-1:0] count_q;
  logic pop;
  logic [EntryBits-1:0] rdata_q;

  assign valid_o = count_q != '0;
  assign pop     = valid_o && ready_i;
  assign rptr_d  = rptr_q + PtrBits'(pop);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wptr_q  <= '0;
      rptr_q  <= '0;
      count_q <= '0;
    end else begin
      wptr_q  <= wptr_q + PtrBits'(wr_i);
      rptr_q  <= rptr_d;
      count_q <= count_q + CountBits'(push_i) - CountBits'(pop);
    end
  end

  // Storage and its registered read (a RAM: no reset).
  always_ff @(posedge clk_i) begin
    if (wr_i) mem[wptr_q] <= wdata_i;
  end
  always_ff @(posedge clk_i) begin
    rdata_q <= mem[rptr_d];
  end

  assign count_o = count_q;
  assign data_o  = rdata_q;
`ifdef FORMAL
  assign f_wptr_o = wptr_q;
  assign f_rptr_o = rptr_q;
  for (genvar k = 0; k < FifoDepth; k++) begin : g_f_mem
    assign f_mem_o[k*EntryBits +: EntryBits] = mem[k];
  end
`endif

  // Cover points (docs/coverage.md), as trirast_span_fifo's: empty, full (FifoDepth entries), and
  // a pop in two cycles in a row.
  `COVER(SpanFifoEmpty_C, count_q == '0, clk_i, !rst_ni)
  `COVER(SpanFifoFull_C, 32'(count_q) == FifoDepth, clk_i, !rst_ni)
  `COVER(SpanFifoPopBackToBack_C, pop && $past(pop), clk_i, !rst_ni)

endmodule
