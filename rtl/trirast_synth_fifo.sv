// Registered wrapper of the span FIFO alone for place and route (scripts/synth.sh: per-stage Fmax;
// not part of the unit). Its push inputs are bits of a serially loaded shift register, its outputs
// are captured by flip-flops with no logic in between and read back through a serial shift
// register. NumEndpoints and FifoDepth are the synthesized defaults.
module trirast_synth_fifo (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic shift_i,   // shift the input word by one bit
  input  logic din_i,     // the bit shifted in
  input  logic load_i,    // copy the captured outputs into the output shift register
  output logic dout_o     // the output shift register's last bit
);
  localparam int N = trirast_pkg::DefaultEndpoints;
  localparam int Depth = trirast_pkg::DefaultFifoDepth;
  localparam int CountBits = $clog2(Depth + 1);
  localparam int EntryBits = trirast_pkg::TagBits + 3 * trirast_pkg::PixBits + 1;
  localparam int InBits = N + N * EntryBits + 1;  // {push, data, span_ready}
  localparam int OutBits = CountBits + 1 + EntryBits;  // {count, span_valid, head}

  logic [InBits-1:0] in_q;
  logic [OutBits-1:0] out_d, out_q, sh_q;
  logic [CountBits-1:0] count;
  logic valid;
  logic [EntryBits-1:0] head;

  trirast_span_fifo #(
    .NumEndpoints (N),
    .FifoDepth    (Depth),
    .EntryBits    (EntryBits)
  ) u_span_fifo (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .push_i  (in_q[InBits-1 -: N]),
    .data_i  (in_q[1 +: N * EntryBits]),
    .count_o (count),
    .valid_o (valid),
    .ready_i (in_q[0]),
    .data_o  (head)
  );

  assign out_d = {count, valid, head};

  // Wrapper registers: no reset (the FIFO's pointers are reset through rst_ni).
  always_ff @(posedge clk_i) begin
    if (shift_i) in_q <= {in_q[InBits-2:0], din_i};
    out_q <= out_d;
    if (load_i) sh_q <= out_q;
    else sh_q <= {1'b0, sh_q[OutBits-1:1]};
  end

  assign dout_o = sh_q[0];

endmodule
