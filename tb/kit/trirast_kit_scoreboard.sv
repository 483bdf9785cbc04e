// Testbench kit: the scoreboard. It reads the expected results of trirast raster --vectors
// (+kit_dir=DIR: spans.hex, expect.hex) and holds the unit's outputs against them:
//   * each triangle's spans, in order (span i of triangle p must be line first_p + i of
//     spans.hex), and their number; and each span's position in the span port's whole output
//     (the order of triangles' spans among one another);
//   * each triangle's accept cycle (its triangle-port handshake), first-span and done cycles (its
//     first and last span handshakes, or the cycle it retired without a span).
// It prints the first difference (triangle, what, expected, got) as it happens, counts the rest,
// and ends the simulation: "PASS: ..." and $finish, or "FAIL: ..." and $fatal (a non-zero exit in
// both simulators). +gap=N (the driver's idle cycles) or +kit_cycles=0 turn the cycle checks off
// (the expected cycles are those of back-to-back triangles and the vectors' downstream); the PASS
// line says so. The run also fails when it outlasts the expected last cycle by +kit_slack cycles
// (default 10000; with gaps, plus gap + 1 per triangle) or the monitor saw the port's rule broken.
module trirast_kit_scoreboard #(
  parameter int TagBits = 32,
  parameter int PixBits = 15,
  parameter int MaxTris = 1,
  parameter int MaxSpans = 1
) (
  input  logic               clk,
  input  logic               rst_n,
  input  logic [63:0]        cycle,
  // the triangle port: a handshake of triangle accept_tag
  input  logic               accept,
  input  logic [31:0]        accept_tag,
  // a triangle that leaves without a span (an empty box, collinear pixels, a walk with none)
  input  logic               retire,
  input  logic [TagBits-1:0] retire_tag,
  input  logic               retire2,
  input  logic [TagBits-1:0] retire2_tag,
  // the span port (the monitor's take)
  input  logic               take,
  input  logic [TagBits-1:0] span_tag,
  input  logic [PixBits-1:0] span_y,
  input  logic [PixBits-1:0] span_x_begin,
  input  logic [PixBits:0]   span_x_end,
  // every triangle went in and the unit holds none
  input  logic               all_sent,
  input  logic               unit_idle,
  input  int                 protocol_errors
);
  localparam int SpanBits = TagBits + 2 * PixBits + PixBits + 1;
  // The vectors' format this scoreboard reads (app/io/kit_vectors.cpp, kKitFormat).
  localparam int KitFormat = 1;
  int format;
  logic [32+SpanBits-1:0] exp_spans [MaxSpans];  // {order, tag, y, x_begin, x_end}
  logic [31:0] taken;  // spans taken so far (the next span's order)
  logic [159:0] expect_q [MaxTris];  // {first, count, accept, first_span, done}
  logic [31:0] got_count [MaxTris];
  logic [63:0] got_first [MaxTris], got_done [MaxTris];
  logic got_any [MaxTris];
  logic got_accepted [MaxTris];
  int ntris, nspans, gap, check_cycles, errors, k;
  longint unsigned last, slack, limit;
  string dir, cycles_said;
  logic over;

  initial begin
    if (!$value$plusargs("kit_dir=%s", dir)) $fatal(1, "kit scoreboard: +kit_dir=DIR missing");
    if (!$value$plusargs("kit_format=%d", format) || format != KitFormat)
      $fatal(1, "kit scoreboard: +kit_format: the vectors in %s are not of format %0d (write them again with trirast raster --vectors)",
             dir, KitFormat);
    if (!$value$plusargs("ntris=%d", ntris)) $fatal(1, "kit scoreboard: +ntris missing");
    if (!$value$plusargs("nspans=%d", nspans)) $fatal(1, "kit scoreboard: +nspans missing");
    if (!$value$plusargs("last=%d", last)) $fatal(1, "kit scoreboard: +last missing");
    if (!$value$plusargs("gap=%d", gap)) gap = 0;
    if (!$value$plusargs("kit_cycles=%d", check_cycles)) check_cycles = 1;
    if (!$value$plusargs("kit_slack=%d", slack)) slack = 10000;
    if (gap != 0) check_cycles = 0;
    if (ntris > MaxTris || nspans > MaxSpans)
      $fatal(1, "kit scoreboard: %0d triangles, %0d spans exceed the bench's MaxTris %0d, MaxSpans %0d",
             ntris, nspans, MaxTris, MaxSpans);
    if (ntris > 0) $readmemh({dir, "/expect.hex"}, expect_q, 0, ntris - 1);
    if (nspans > 0) $readmemh({dir, "/spans.hex"}, exp_spans, 0, nspans - 1);
    for (k = 0; k < ntris; k = k + 1) begin
      got_count[k] = 0;
      got_any[k] = 1'b0;
      got_accepted[k] = 1'b0;
    end
    limit = last + slack + longint'(ntris) * longint'(gap + 1) * (gap != 0 ? 1 : 0);
    errors = 0;
    taken = 0;
    over = 1'b0;
  end

  // The first difference is printed in full; later ones are counted (up to 10 more printed).
  // During the run a line names the cycle; at its end, "end of run".
  task automatic differ(input string what);
    if (errors <= 10) begin
      if (over) $display("kit scoreboard: end of run: %s", what);
      else $display("kit scoreboard: cycle %0d: %s", cycle, what);
    end
    errors = errors + 1;
  endtask

  task automatic retired(input logic [TagBits-1:0] tag);
    if (tag >= TagBits'(ntris)) begin
      differ($sformatf("a triangle with tag %0d (of %0d triangles) retired", tag, ntris));
    end else begin
      if (!got_any[tag]) check_cycle(int'(tag), "first-span (retire)", cycle, expect_q[tag][63:32]);
      got_any[tag] = 1'b1;
      got_first[tag] = cycle;
      got_done[tag] = cycle;
    end
  endtask

  task automatic check_cycle(input int p, input string what, input logic [63:0] got,
                             input logic [31:0] expected);
    if (check_cycles != 0 && got != 64'(expected))
      differ($sformatf("triangle %0d: %s cycle %0d, expected %0d", p, what, got, expected));
  endtask

  task automatic finish_run;
    int p;
    for (p = 0; p < ntris; p = p + 1) begin
      if (!got_accepted[p]) differ($sformatf("triangle %0d: never accepted", p));
      if (got_count[p] != expect_q[p][127:96])
        differ($sformatf("triangle %0d: %0d spans, expected %0d", p, got_count[p],
                         expect_q[p][127:96]));
      if (!got_any[p]) begin
        differ($sformatf("triangle %0d: neither a span nor a retirement", p));
      end else begin
        check_cycle(p, "done", got_done[p], expect_q[p][31:0]);
      end
    end
    if (protocol_errors != 0) begin
      $display("kit scoreboard: the span port's rule broken %0d times (kit monitor)", protocol_errors);
      errors = errors + protocol_errors;
    end
    if (errors == 0) begin
      if (check_cycles != 0) cycles_said = "accept, first-span and done cycles identical";
      else cycles_said = "cycles NOT checked (+gap or +kit_cycles=0)";
      $display("PASS: %0d triangles, %0d spans identical and in order; %s; the unit idle from cycle %0d", ntris,
               nspans, cycles_said, cycle);
      $finish;
    end else begin
      $fatal(1, "FAIL: %0d differences from %s (the first printed above)", errors, dir);
    end
  endtask

  always @(posedge clk) begin
    if (rst_n && !over) begin
      if (all_sent && unit_idle) begin
        over = 1'b1;
        finish_run();
      end else if (cycle > limit) begin
        differ($sformatf("timeout: the run outlasts the expected last cycle %0d by %0d cycles",
                         last, slack));
        over = 1'b1;
        finish_run();
      end else begin
        if (accept) begin
          if (accept_tag >= 32'(ntris)) begin
            differ($sformatf("triangle %0d (of %0d) accepted", accept_tag, ntris));
          end else begin
            got_accepted[accept_tag] = 1'b1;
            check_cycle(int'(accept_tag), "accept", cycle, expect_q[accept_tag][95:64]);
          end
        end
        if (retire) retired(retire_tag);
        if (retire2) retired(retire2_tag);
        if (take) begin
          if (span_tag >= TagBits'(ntris)) begin
            differ($sformatf("span y %0d [%0d, %0d) of tag %0d: no such triangle", span_y,
                             span_x_begin, span_x_end, span_tag));
          end else begin : span_check
            logic [31:0] first, count, i;
            logic [32+SpanBits-1:0] want;
            first = expect_q[span_tag][159:128];
            count = expect_q[span_tag][127:96];
            i = got_count[span_tag];
            want = exp_spans[first + i];
            if (i >= count)
              differ($sformatf("triangle %0d: span %0d y %0d [%0d, %0d) is one more than the %0d expected",
                               span_tag, i, span_y, span_x_begin, span_x_end, count));
            else if ({span_tag, span_y, span_x_begin, span_x_end} != want[SpanBits-1:0])
              differ($sformatf("triangle %0d: span %0d is y %0d [%0d, %0d), expected y %0d [%0d, %0d)",
                               span_tag, i, span_y, span_x_begin, span_x_end,
                               want[2 * PixBits + PixBits : 2 * PixBits + 1],
                               want[2 * PixBits : PixBits + 1], want[PixBits:0]));
            else if (want[32+SpanBits-1:SpanBits] != taken)
              differ($sformatf("triangle %0d: span %0d y %0d [%0d, %0d) is span %0d of the output, expected %0d",
                               span_tag, i, span_y, span_x_begin, span_x_end, taken,
                               want[32+SpanBits-1:SpanBits]));
            if (!got_any[span_tag]) begin
              got_first[span_tag] = cycle;
              check_cycle(int'(span_tag), "first-span", cycle, expect_q[span_tag][63:32]);
            end
            got_any[span_tag] = 1'b1;
            got_done[span_tag] = cycle;
            got_count[span_tag] = i + 1;
          end
          taken = taken + 1;
        end
      end
    end
  end
endmodule
