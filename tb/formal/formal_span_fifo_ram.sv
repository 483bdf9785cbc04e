// Formal harness of the second-generation unit's span FIFO in block RAM
// (rtl/common/trirast_span_fifo_ram.sv: the improved2 unit's span port with FifoRam 1, its
// default; docs/formal.md, "Span FIFO and span port"). The inputs are free but for the contract
// of the walk stage that drives it (rtl/improved2/trirast_improved2_walk_stage.sv): a span is
// written (wr_i, wdata_i) in the cycle before it is pushed (push_i: the push register, loaded from
// wr_i), a write only when count + push < FifoDepth (the stage's credit), none in reset. The
// properties, whenever the unit is out of reset, are formal_span_port.sv's: CountRef,
// ValidIsCount, SpanHeld, and InOrder for one arbitrary written span (its value on the port
// exactly when every span written before it has left); invariants on the pointers, the storage
// and the read register make them inductive.
module formal_span_fifo_ram #(
  parameter int FifoDepth = 8,
  parameter int EntryBits = trirast_pkg::TagBits + 3 * trirast_pkg::PixBits + 1
) (
  input logic clk_i
);
  localparam int CountBits = $clog2(FifoDepth + 1);
  localparam int PtrBits = (FifoDepth > 1) ? $clog2(FifoDepth) : 1;

  (* anyseq *) logic rst_ni;
  (* anyseq *) logic ready_i;
  (* anyseq *) logic wr_i;
  (* anyseq *) logic [EntryBits-1:0] wdata_i;
  (* anyseq *) logic f_pick;   // track this cycle's write

  logic push_i;   // the walk stage's push register: last cycle's write
  logic [CountBits-1:0] count_o;
  logic valid_o;
  logic [EntryBits-1:0] data_o;
  logic [PtrBits-1:0] f_wptr, f_rptr;
  logic [FifoDepth*EntryBits-1:0] f_mem;

  trirast_span_fifo_ram #(.FifoDepth (FifoDepth), .EntryBits (EntryBits)) dut (
    .clk_i (clk_i), .rst_ni (rst_ni), .wr_i (wr_i), .wdata_i (wdata_i), .push_i (push_i),
    .count_o (count_o), .valid_o (valid_o), .ready_i (ready_i), .data_o (data_o),
    .f_wptr_o (f_wptr), .f_rptr_o (f_rptr), .f_mem_o (f_mem));

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) push_i <= 1'b0;
    else push_i <= wr_i;
  end
  logic pop;
  assign pop = valid_o && ready_i;

  // ---- the environment ----
  logic f_first_q = 1'b1;
  always @(posedge clk_i) f_first_q <= 1'b0;
  always @* begin
    if (f_first_q) assume (!rst_ni);
    if (!rst_ni) assume (!wr_i);
    else if (wr_i) assume (32'(count_o) + 32'(push_i) < FifoDepth);
  end

  // ---- reference count, held span ----
  logic [CountBits:0] f_count_q;
  logic f_wait_q;
  logic [EntryBits-1:0] f_span_q;
  always @(posedge clk_i) begin
    if (!rst_ni) f_count_q <= '0;
    else f_count_q <= f_count_q + (CountBits + 1)'(push_i) - (CountBits + 1)'(pop);
    f_wait_q <= rst_ni && valid_o && !ready_i;
    f_span_q <= data_o;
  end

  // ---- one tracked span: written (f_pend_q: its push is this cycle), then in the FIFO with
  // f_ahead_q entries ahead of it ----
  logic f_trk_q, f_pend_q;
  logic [EntryBits-1:0] f_val_q;
  logic [CountBits-1:0] f_ahead_q;
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      f_trk_q <= 1'b0;
      f_pend_q <= 1'b0;
    end else if (!f_trk_q && f_pick && wr_i) begin
      f_trk_q  <= 1'b1;
      f_pend_q <= 1'b1;
      f_val_q  <= wdata_i;
    end else if (f_trk_q && f_pend_q) begin
      f_pend_q  <= 1'b0;
      f_ahead_q <= count_o - CountBits'(pop);
    end else if (f_trk_q) begin
      if (pop && f_ahead_q == '0) f_trk_q <= 1'b0;
      f_ahead_q <= f_ahead_q - CountBits'(pop);
    end
  end
  logic [PtrBits-1:0] f_slot;
  logic [EntryBits-1:0] f_stored, f_head;
  assign f_slot = f_pend_q ? PtrBits'(f_wptr - 1'b1) : PtrBits'(f_rptr + PtrBits'(f_ahead_q));
  always @* begin
    f_stored = '0;
    f_head = '0;
    for (int k = 0; k < FifoDepth; k++) begin
      if (f_slot == PtrBits'(k)) f_stored = f_mem[k*EntryBits +: EntryBits];
      if (f_rptr == PtrBits'(k)) f_head = f_mem[k*EntryBits +: EntryBits];
    end
  end

  always @* begin
    if (rst_ni) begin
      CountRef: assert (32'(count_o) == 32'(f_count_q) && 32'(count_o) <= FifoDepth);
      ValidIsCount: assert (valid_o == (count_o != '0));
      NoPushWhenFull: assert (32'(count_o) + 32'(push_i) <= FifoDepth);
      if (f_wait_q) SpanHeld: assert (valid_o && data_o == f_span_q);
      if (f_trk_q && !f_pend_q) begin
        InOrderAhead: assert (f_ahead_q < count_o);
        if (f_ahead_q == '0) InOrderHead: assert (valid_o && data_o == f_val_q);
      end
      // invariants: pointers (a written span not yet pushed counts in wptr), the tracked
      // span's slot, the read register shows the head
      PtrCount: assert (f_wptr == PtrBits'(f_rptr + PtrBits'(count_o) + PtrBits'(push_i)));
      if (f_trk_q && f_pend_q) PendingPushed: assert (push_i);
      if (f_trk_q) TrackedStored: assert (f_stored == f_val_q);
      if (valid_o) ReadRegIsHead: assert (data_o == f_head);
    end
  end

  always @* begin
    if (rst_ni) begin
      CoverFull: cover (32'(count_o) == FifoDepth && f_trk_q && f_ahead_q != '0);
      CoverWrap: cover (f_trk_q && f_ahead_q == '0 && pop && f_rptr == PtrBits'(FifoDepth - 1));
    end
  end
endmodule
