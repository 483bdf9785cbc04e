// Testbench kit: the span monitor. It watches the span port: `take` is a handshake (span_valid
// and span_ready high at a rising edge); it checks the port's rule that an offered span stays on
// the port, unchanged, until it is taken, and with +spans_out=FILE writes every span taken, one
// line "tag y x_begin x_end cycle" (decimal) per handshake.
module trirast_kit_monitor #(
  parameter int TagBits = 32,
  parameter int PixBits = 15
) (
  input  logic               clk,
  input  logic               rst_n,
  input  logic [63:0]        cycle,
  input  logic               span_valid,
  input  logic               span_ready,
  input  logic [TagBits-1:0] span_tag,
  input  logic [PixBits-1:0] span_y,
  input  logic [PixBits-1:0] span_x_begin,
  input  logic [PixBits:0]   span_x_end,
  output logic               take,
  output int                 protocol_errors
);
  localparam int SpanBits = TagBits + 2 * PixBits + PixBits + 1;
  string path;
  int fd;
  logic held;                   // a span was offered and not taken in the previous cycle
  logic [SpanBits-1:0] held_span;

  assign take = span_valid && span_ready;

  initial begin
    fd = 0;
    protocol_errors = 0;
    if ($value$plusargs("spans_out=%s", path)) begin
      fd = $fopen(path, "w");
      if (fd == 0) $fatal(1, "kit monitor: +spans_out=%s: cannot write", path);
    end
  end

  always @(posedge clk or negedge rst_n) begin
    if (!rst_n) begin
      held <= 1'b0;
    end else begin
      if (held && (!span_valid || {span_tag, span_y, span_x_begin, span_x_end} != held_span)) begin
        if (protocol_errors == 0)
          $display("kit monitor: cycle %0d: the span offered in cycle %0d (tag %0d) left the port untaken",
                   cycle, cycle - 1, held_span[SpanBits-1 -: TagBits]);
        protocol_errors <= protocol_errors + 1;
      end
      held <= span_valid && !span_ready;
      held_span <= {span_tag, span_y, span_x_begin, span_x_end};
      if (take && fd != 0) begin
        $fwrite(fd, "%0d %0d %0d %0d %0d\n", span_tag, span_y, span_x_begin, span_x_end, cycle);
        $fflush(fd);
      end
    end
  end
endmodule
