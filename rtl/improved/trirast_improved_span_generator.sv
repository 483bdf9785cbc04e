// Stage 5, span_generator (docs/unit.md, section 5), for one row: combines the three walkers'
// states into at most one span. Out if any edge is out; else begin = max(0, mirrored bounds),
// end = min(Xmax + 1, non-mirrored bounds); a span when begin < end. Box-relative.
`include "trirast_ports.svh"

module trirast_improved_span_generator (
  input  logic [5:0]                                 state_i,   // edge k: [2k +: 2]
  input  logic [3*trirast_pkg::WalkerXBits-1:0]      x_i,       // edge k: X' (when bound)
  input  logic [2:0]                                 mirror_i,  // edge k bounds the begin
  input  logic [trirast_pkg::BoxBits-1:0]            xmax_i,
  output logic                                       valid_o,   // a span leaves for this row
  output logic [trirast_pkg::BoxBits:0]              begin_o,   // first covered i
  output logic [trirast_pkg::BoxBits:0]              end_o      // one past the last covered i
);
  `TRIRAST_PKG_NAMES
  localparam int Box1Bits = BoxBits + 1;

  // The whole row as a function (its temporaries are local: see docs/rtl.md, Icarus).
  function automatic logic [2*Box1Bits:0] gen(input logic [5:0] st,
                                              input logic [3*WalkerXBits-1:0] xs,
                                              input logic [2:0] mirror,
                                              input logic [BoxBits-1:0] xmax);
    logic out;
    logic [Box1Bits-1:0] b, e;
    logic signed [WalkerXBits-1:0] x;
    // The restored bound: Xmax - X' (mirrored) or X' + 1. Only its low BoxBits + 1 bits are
    // used: a bound edge has 0 <= X' <= Xmax, so the bound lies in [0, Xmax + 1].
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [WalkerXBits-1:0] bound;
    /* verilator lint_on UNUSEDSIGNAL */
    out = 1'b0;
    b   = '0;
    e   = Box1Bits'(xmax) + 1'b1;
    for (int k = 0; k < 3; k++) begin
      x = xs[k*WalkerXBits +: WalkerXBits];
      bound = mirror[k] ? $signed(WalkerXBits'(xmax)) - x : x + 1'b1;
      if (st[2*k +: 2] == RowOut) out = 1'b1;
      if (st[2*k +: 2] == RowBound) begin
        if (mirror[k]) begin
          if (Box1Bits'(bound) > b) b = Box1Bits'(bound);
        end else begin
          if (Box1Bits'(bound) < e) e = Box1Bits'(bound);
        end
      end
    end
    gen = {!out && (b < e), b, e};
  endfunction

  assign {valid_o, begin_o, end_o} = gen(state_i, x_i, mirror_i, xmax_i);

endmodule
