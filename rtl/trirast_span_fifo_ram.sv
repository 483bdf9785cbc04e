// The second-generation improved unit's span FIFO in block RAM (rtl/trirast_improved2.f, FifoRam 1;
// docs/gen2-design.md section 1, "Fitting the HX8K"): the span FIFO of rtl/trirast_span_fifo.sv
// (NumEndpoints 1) with its storage
// in a memory read through a register, so synth_ice40 maps it to block RAM (SB_RAM40_4K) instead of
// FifoDepth * EntryBits flip-flops. The same cycles and outputs whenever valid_o is 1: a span
// pushed
// in cycle t shows from t + 1, count_o is the occupancy at the start of the cycle.
// The read register is loaded every cycle from the next cycle's head (rptr + pop); when the push of
// the same cycle writes that address (an empty FIFO, or one entry being popped), the memory's read
// returns the old word, so the pushed span is also kept in a bypass register and shown instead.
module trirast_span_fifo_ram #(
  parameter int FifoDepth = 8,     // entries (a power of two)
  parameter int EntryBits = 8,     // bits of one span
  parameter int CountBits = $clog2(FifoDepth + 1)  // derived: do not override
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  input  logic                 push_i,
  input  logic [EntryBits-1:0] data_i,
  output logic [CountBits-1:0] count_o,   // occupancy at the start of the cycle
  output logic                 valid_o,
  input  logic                 ready_i,
  output logic [EntryBits-1:0] data_o     // the oldest entry (when valid_o)
);
  localparam int PtrBits = (FifoDepth > 1) ? $clog2(FifoDepth) : 1;

  (* no_rw_check *) logic [EntryBits-1:0] mem [FifoDepth];   // the bypass handles a collision
  logic [PtrBits-1:0] wptr_q, rptr_q, rptr_d;
  logic [CountBits-1:0] count_q;
  logic pop, byp_sel_q;
  logic [EntryBits-1:0] rdata_q, byp_q;

  assign valid_o = count_q != '0;
  assign pop     = valid_o && ready_i;
  assign rptr_d  = rptr_q + PtrBits'(pop);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wptr_q    <= '0;
      rptr_q    <= '0;
      count_q   <= '0;
      byp_sel_q <= 1'b0;
    end else begin
      wptr_q    <= wptr_q + PtrBits'(push_i);
      rptr_q    <= rptr_d;
      count_q   <= count_q + CountBits'(push_i) - CountBits'(pop);
      byp_sel_q <= push_i && (wptr_q == rptr_d);
    end
  end

  // Storage and its registered read (a RAM: no reset).
  always_ff @(posedge clk_i) begin
    if (push_i) mem[wptr_q] <= data_i;
  end
  always_ff @(posedge clk_i) begin
    rdata_q <= mem[rptr_d];
  end
  always_ff @(posedge clk_i) begin
    if (push_i) byp_q <= data_i;
  end

  assign count_o = count_q;
  assign data_o  = byp_sel_q ? byp_q : rdata_q;

endmodule
