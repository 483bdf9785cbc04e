// The registered shell of every place-and-route wrapper (scripts/synth.sh, Fmax only; not part of
// a unit): the design's InBits inputs are the bits of a shift register loaded serially through
// din_i (in_q_o), its OutBits outputs (out_d_i) are captured by flip-flops with no logic in between
// and read back through a second, serial shift register. So every timed path is register ->
// design logic -> register, and a wrapper needs five pins. The wrappers (rtl/improved/trirast_improved_synth_walk.sv,
// and those scripts/synth_wrap.py generates) only map their design's ports onto in_q_o / out_d_i.
module trirast_synth_shell #(
  parameter int InBits = 1,   // bits of the design's inputs
  parameter int OutBits = 1   // bits of the design's outputs
) (
  input  logic               clk_i,
  input  logic               shift_i,   // shift the input word by one bit
  input  logic               din_i,     // the bit shifted in (at the LSB)
  input  logic               load_i,    // copy the captured outputs into the output shift register
  output logic               dout_o,    // the output shift register's last bit
  output logic [InBits-1:0]  in_q_o,    // the design's inputs
  input  logic [OutBits-1:0] out_d_i    // the design's outputs
);
  logic [InBits-1:0] in_q;
  logic [OutBits-1:0] out_q, sh_q;

  // Shell registers: no reset (the design's own control registers are reset through its rst_ni).
  always_ff @(posedge clk_i) begin
    if (shift_i) in_q <= InBits'({in_q, din_i});
    out_q <= out_d_i;
    if (load_i) sh_q <= out_q;
    else sh_q <= sh_q >> 1;
  end

  assign in_q_o = in_q;
  assign dout_o = sh_q[0];

endmodule
