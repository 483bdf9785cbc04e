// Testbench kit: the downstream of the span port, a ready signal that is a function of the cycle
// alone (docs/timing.md, "Sink patterns"; model/common/sink_pattern.hpp), the patterns of
// trirast's --sink-stall that can be replayed without seeing the spans:
//   +sink=none                                  ready in every cycle
//   +sink=periodic +sink_ready=R +sink_stall=S  ready in cycle c when c % (R + S) < R
//   +sink=random +sink_seed=X +sink_percent=P   not ready in cycle c when
//                                               splitmix64(X * 0x9E3779B97F4A7C15 + c) % 100 < P
// (--sink-stall queue:RATE:CAPACITY reacts to the spans it takes; trirast raster --vectors
// refuses it.) Cycle 0 is the first cycle after reset.
module trirast_kit_downstream (
  input  logic [63:0] cycle,
  output logic        span_ready
);
  string kind;
  int kind_id;  // 0 none, 1 periodic, 2 random
  longint unsigned ready_n, stall_n, seed, percent;

  // sink_mix of model/common/sink_pattern.cpp: the splitmix64 finaliser of seed * golden + cycle.
  function automatic logic [63:0] sink_mix(input logic [63:0] s, input logic [63:0] c);
    logic [63:0] z;
    z = s * 64'h9E3779B97F4A7C15 + c;
    z = z + 64'h9E3779B97F4A7C15;
    z = (z ^ (z >> 30)) * 64'hBF58476D1CE4E5B9;
    z = (z ^ (z >> 27)) * 64'h94D049BB133111EB;
    return z ^ (z >> 31);
  endfunction

  initial begin
    if (!$value$plusargs("sink=%s", kind)) kind = "none";
    if (!$value$plusargs("sink_ready=%d", ready_n)) ready_n = 1;
    if (!$value$plusargs("sink_stall=%d", stall_n)) stall_n = 0;
    if (!$value$plusargs("sink_seed=%d", seed)) seed = 0;
    if (!$value$plusargs("sink_percent=%d", percent)) percent = 0;
    if (kind == "none") kind_id = 0;
    else if (kind == "periodic") kind_id = 1;
    else if (kind == "random") kind_id = 2;
    else $fatal(1, "kit downstream: +sink=%s: expected none, periodic or random", kind);
    if (kind_id == 1 && ready_n == 0) $fatal(1, "kit downstream: +sink_ready=0: never ready");
    if (kind_id == 2 && percent > 99) $fatal(1, "kit downstream: +sink_percent=%0d: 0..99", percent);
  end

  always_comb begin
    case (kind_id)
      1: span_ready = (cycle % (ready_n + stall_n)) < ready_n;
      2: span_ready = (sink_mix(seed, cycle) % 64'd100) >= percent;
      default: span_ready = 1'b1;
    endcase
  end
endmodule
