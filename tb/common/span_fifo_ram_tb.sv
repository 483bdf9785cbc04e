// The span FIFO in block RAM (rtl/common/trirast_span_fifo_ram.sv: registered read, written a
// cycle ahead of the push) against the span FIFO in flip-flops (rtl/common/trirast_span_fifo.sv,
// NumEndpoints 1) at depths 2, 4, 8, 16 and 32, on the same random pushes and sink readiness, with
// phases of mostly pushing, mostly popping and both (tb/improved2/run_checks.sh --check-all, the
// improved2 unit's walk stage being its user; Verilator --binary). As that walk stage, the bench
// decides a push a cycle ahead, when count + (the push registered now) < depth, writes its span
// into the block-RAM FIFO then (wr_i, wdata_i) and registers push and span for both FIFOs' push_i
// (and the reference's data_i). Every cycle count_o and valid_o must be equal, and data_o
// whenever valid_o. Prints "span_fifo_ram_tb: N errors".
module span_fifo_ram_tb;
  localparam int EB = 24;
  localparam int Cycles = 40000;
  logic clk = 1'b0, rst_n = 1'b0;
  int errors = 0, pops = 0;

  for (genvar g = 1; g < 6; g++) begin : g_depth
    localparam int D = 1 << g;
    localparam int CB = $clog2(D + 1);
    logic push, wr, ready, v1, v2;
    logic [EB-1:0] din, wdata, d1, d2;
    logic [CB-1:0] c1, c2;
    trirast_span_fifo #(.NumEndpoints (1), .FifoDepth (D), .EntryBits (EB)) u_ref (
      .clk_i (clk), .rst_ni (rst_n), .push_i (push), .data_i (din), .count_o (c1),
      .valid_o (v1), .ready_i (ready), .data_o (d1));
    trirast_span_fifo_ram #(.FifoDepth (D), .EntryBits (EB)) u_ram (
      .clk_i (clk), .rst_ni (rst_n), .wr_i (wr), .wdata_i (wdata), .push_i (push),
      .count_o (c2), .valid_o (v2), .ready_i (ready), .data_o (d2));
    always_ff @(posedge clk) begin   // the walk stage's registered push
      push <= rst_n && wr;
      din  <= wdata;
    end
    initial begin
      wr = 1'b0;  ready = 1'b0;  wdata = '0;
      @(posedge rst_n);
      for (int t = 0; t < Cycles; t++) begin
        int pp, pr;
        // phases of 500 cycles: push 90% / pop 30%, push 30% / pop 90%, both 60%
        unique case ((t / 500) % 3)
          0: begin pp = 90; pr = 30; end
          1: begin pp = 30; pr = 90; end
          default: begin pp = 60; pr = 60; end
        endcase
        @(negedge clk);
        wr    = (32'(c1) + 32'(push) < D) && ($urandom % 100 < pp);
        ready = $urandom % 100 < pr;
        wdata = EB'($urandom);
        #1;
        if (c1 != c2 || v1 != v2 || (v1 && d1 != d2)) begin
          errors++;
          if (errors < 10)
            $display("span_fifo_ram_tb: depth %0d cycle %0d: count %0d / %0d valid %0d / %0d data %h / %h",
                     D, t, c1, c2, v1, v2, d1, d2);
        end
        if (v1 && ready) pops++;
      end
    end
  end

  always #5 clk = ~clk;
  initial begin
    repeat (3) @(negedge clk);
    rst_n = 1'b1;
    repeat (Cycles + 5) @(negedge clk);
    $display("span_fifo_ram_tb: depths 2, 4, 8, 16, 32, %0d cycles each, %0d spans popped", Cycles, pops);
    $display("span_fifo_ram_tb: %0d errors", errors);
    $finish;
  end
endmodule
