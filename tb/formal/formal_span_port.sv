// Formal harness of the span port and its FIFO (rtl/common/trirast_span_port.sv around
// rtl/common/trirast_span_fifo.sv; docs/formal.md, "Span FIFO and span port"). Every input is free
// in every cycle (anyseq) but for the walk stage's contract on the pushes; the properties hold
// whenever the unit is out of reset:
//   CountRef      count_o equals a reference count of the pushes minus the pops (no lost or
//                 invented entry: no overflow, no underflow), and is within 0..FifoDepth
//   ValidIsCount  span_valid_o exactly when the FIFO holds an entry (no pop from an empty FIFO)
//   SpanHeld      a span offered and not taken is offered again next cycle, unchanged
//   InOrder       one arbitrary push (any cycle, any of its rows, any value) is on the port, with
//                 its value, exactly when every entry pushed before it has left, and never
//                 earlier: so every span leaves unchanged and in push order (rows of a group in
//                 row order)
// Reset is assumed in the first cycle only; the inputs may reset the unit again at any time.
// Invariants on the FIFO's pointers and storage (its formal-only ports) make the properties
// inductive.
module formal_span_port #(
  parameter int NumEndpoints = 1,
  parameter int FifoDepth = 8,
  // Port 1: the span port (trirast_span_port, its entry {tag, y, x_begin, x_end}); Port 0: the
  // FIFO alone (trirast_span_fifo) with entries of EntryBits bits
  parameter bit Port = 1'b1,
  parameter int EntryBits = trirast_pkg::TagBits + 3 * trirast_pkg::PixBits + 1
) (
  input logic clk_i
);
  localparam int CountBits = $clog2(FifoDepth + 1);
  localparam int PtrBits = $clog2(FifoDepth);
  localparam int PushBits = $clog2(NumEndpoints + 1);

  (* anyseq *) logic rst_ni;
  (* anyseq *) logic span_ready_i;
  (* anyseq *) logic [NumEndpoints-1:0] push_i;
  (* anyseq *) logic [NumEndpoints*EntryBits-1:0] push_data_i;
  (* anyseq *) logic f_pick;                         // track this cycle's push ...
  (* anyseq *) logic [$clog2(NumEndpoints)+0:0] f_row; // ... of this row

  logic [CountBits-1:0] count_o;
  logic span_valid_o;
  logic [PtrBits-1:0] f_wptr, f_rptr;
  logic [FifoDepth*EntryBits-1:0] f_mem;
  logic [EntryBits-1:0] span;

  if (Port) begin : g_port
    logic [trirast_pkg::TagBits-1:0] span_tag_o;
    logic [trirast_pkg::PixBits-1:0] span_y_o, span_x_begin_o;
    logic [trirast_pkg::PixBits:0] span_x_end_o;
    trirast_span_port #(.NumEndpoints (NumEndpoints), .FifoDepth (FifoDepth)) dut (
      .clk_i (clk_i), .rst_ni (rst_ni), .push_i (push_i), .push_data_i (push_data_i),
      .count_o (count_o), .span_valid_o (span_valid_o), .span_ready_i (span_ready_i),
      .span_tag_o (span_tag_o), .span_y_o (span_y_o), .span_x_begin_o (span_x_begin_o),
      .span_x_end_o (span_x_end_o), .f_wptr_o (f_wptr), .f_rptr_o (f_rptr), .f_mem_o (f_mem));
    assign span = {span_tag_o, span_y_o, span_x_begin_o, span_x_end_o};
  end else begin : g_fifo
    trirast_span_fifo #(.NumEndpoints (NumEndpoints), .FifoDepth (FifoDepth),
                        .EntryBits (EntryBits)) dut (
      .clk_i (clk_i), .rst_ni (rst_ni), .push_i (push_i), .data_i (push_data_i),
      .count_o (count_o), .valid_o (span_valid_o), .ready_i (span_ready_i), .data_o (span),
      .f_wptr_o (f_wptr), .f_rptr_o (f_rptr), .f_mem_o (f_mem));
  end

  // Pushes among rows 0 .. r - 1 (r = NumEndpoints: all of them).
  function automatic logic [PushBits-1:0] before(input logic [NumEndpoints-1:0] p, input int r);
    logic [PushBits-1:0] n;
    n = '0;
    for (int k = 0; k < NumEndpoints; k++) if (k < r) n = n + PushBits'(p[k]);
    before = n;
  endfunction
  logic [PushBits-1:0] pushes;
  logic pop;
  assign pushes = before(push_i, NumEndpoints);
  assign pop = span_valid_o && span_ready_i;

  // ---- the environment: reset first; the walk stage admits a group only when its spans fit
  // (count + pushes <= FifoDepth at the start of the cycle, the cycle's pop not counted) ----
  logic f_first_q = 1'b1;
  always @(posedge clk_i) f_first_q <= 1'b0;
  always @* begin
    if (f_first_q) assume (!rst_ni);
    if (rst_ni) assume (32'(count_o) + 32'(pushes) <= FifoDepth);
  end

  // ---- reference count ----
  logic [CountBits:0] f_count_q;
  always @(posedge clk_i) begin
    if (!rst_ni) f_count_q <= '0;
    else f_count_q <= f_count_q + (CountBits + 1)'(pushes) - (CountBits + 1)'(pop);
  end

  // ---- the held span ----
  logic f_wait_q;
  logic [EntryBits-1:0] f_span_q;
  always @(posedge clk_i) begin
    f_wait_q <= rst_ni && span_valid_o && !span_ready_i;
    f_span_q <= span;
  end

  // ---- one tracked push: its value and the entries ahead of it ----
  logic f_trk_q;
  logic [EntryBits-1:0] f_val_q;
  logic [CountBits-1:0] f_ahead_q;
  logic f_take;
  logic [EntryBits-1:0] f_val;
  logic [PtrBits-1:0] f_slot;
  assign f_take = rst_ni && !f_trk_q && f_pick && 32'(f_row) < NumEndpoints && push_i[f_row];
  always @* begin
    f_val = '0;
    for (int r = 0; r < NumEndpoints; r++) if (32'(f_row) == r) f_val = push_data_i[r*EntryBits +: EntryBits];
  end
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      f_trk_q <= 1'b0;
    end else if (f_take) begin
      f_trk_q   <= 1'b1;
      f_val_q   <= f_val;
      f_ahead_q <= count_o + CountBits'(before(push_i, f_row)) - CountBits'(pop);
    end else if (f_trk_q) begin
      if (pop && f_ahead_q == '0) f_trk_q <= 1'b0;   // it left
      f_ahead_q <= f_ahead_q - CountBits'(pop);
    end
  end
  assign f_slot = f_rptr + PtrBits'(f_ahead_q);
  logic [EntryBits-1:0] f_stored;   // the tracked push's slot
  always @* begin
    f_stored = '0;
    for (int k = 0; k < FifoDepth; k++) if (f_slot == PtrBits'(k)) f_stored = f_mem[k*EntryBits +: EntryBits];
  end

  always @* begin
    if (rst_ni) begin
      // the properties
      CountRef: assert (32'(count_o) == 32'(f_count_q) && 32'(count_o) <= FifoDepth);
      ValidIsCount: assert (span_valid_o == (count_o != '0));
      if (f_wait_q) SpanHeld: assert (span_valid_o && span == f_span_q);
      if (f_trk_q) begin
        InOrderAhead: assert (f_ahead_q < count_o);
        if (f_ahead_q == '0) InOrderHead: assert (span_valid_o && span == f_val_q);
      end
      // invariants (the FIFO's state, for induction)
      PtrCount: assert (f_wptr == PtrBits'(f_rptr + PtrBits'(count_o)));
      if (f_trk_q) TrackedStored: assert (f_stored == f_val_q);
    end
  end

  // ---- reachability (yosys-smtbmc -c): the proof is not vacuous ----
  always @* begin
    if (rst_ni) begin
      CoverFull: cover (32'(count_o) == FifoDepth && f_trk_q && f_ahead_q != '0);
      CoverTrackedOut: cover (f_trk_q && f_ahead_q == '0 && pop);
      CoverWrap: cover (f_trk_q && f_ahead_q == '0 && pop && f_rptr == PtrBits'(FifoDepth - 1));
    end
  end
endmodule
