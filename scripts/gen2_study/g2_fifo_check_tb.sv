// gen2 study (scripts/gen2_study.sh --check): trirast_span_fifo_ram (block-RAM storage, registered read,
// bypass) against rtl/trirast_span_fifo.sv (NumEndpoints 1) at depths 2, 4, 8, 16 and 32, on the same
// random pushes (only when count < depth, as the walk stage admits them) and sink readiness, with
// phases of mostly pushing, mostly popping and both. Every cycle count_o and valid_o must be equal,
// and data_o whenever valid_o. Prints "g2_fifo_check_tb: N errors".
module g2_fifo_check_tb;
  localparam int EB = 24;
  localparam int Cycles = 40000;
  logic clk = 1'b0, rst_n = 1'b0;
  int errors = 0, pops = 0;

  for (genvar g = 1; g < 6; g++) begin : g_depth
    localparam int D = 1 << g;
    localparam int CB = $clog2(D + 1);
    logic push, ready, v1, v2;
    logic [EB-1:0] din, d1, d2;
    logic [CB-1:0] c1, c2;
    trirast_span_fifo #(.NumEndpoints (1), .FifoDepth (D), .EntryBits (EB)) u_ref (
      .clk_i (clk), .rst_ni (rst_n), .push_i (push), .data_i (din), .count_o (c1),
      .valid_o (v1), .ready_i (ready), .data_o (d1));
    trirast_span_fifo_ram #(.FifoDepth (D), .EntryBits (EB)) u_ram (
      .clk_i (clk), .rst_ni (rst_n), .push_i (push), .data_i (din), .count_o (c2),
      .valid_o (v2), .ready_i (ready), .data_o (d2));
    initial begin
      push = 1'b0;  ready = 1'b0;  din = '0;
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
        push  = (32'(c1) < D) && ($urandom % 100 < pp);
        ready = $urandom % 100 < pr;
        din   = EB'($urandom);
        #1;
        if (c1 != c2 || v1 != v2 || (v1 && d1 != d2)) begin
          errors++;
          if (errors < 10)
            $display("g2_fifo_check_tb: depth %0d cycle %0d: count %0d / %0d valid %0d / %0d data %h / %h",
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
    $display("g2_fifo_check_tb: depths 2, 4, 8, 16, 32, %0d cycles each, %0d spans popped", Cycles, pops);
    $display("g2_fifo_check_tb: %0d errors", errors);
    $finish;
  end
endmodule
