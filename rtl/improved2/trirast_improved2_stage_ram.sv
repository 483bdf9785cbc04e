// A pipeline stage's register held in block RAM (rtl/improved2/trirast_improved2.f; trirast_improved2_top's
// CRam): for a stage whose fields are first read two cycles after they are written, the register
// can be a memory of two words read through its output register, which synth_ice40 maps to
// SB_RAM40_4K blocks (16 bits each) instead of Bits flip-flops, each of which takes a logic cell
// of its own when it is loaded from another register.
// q_o is the word of the last we_i from the second cycle after it on (the previous word until
// then), and holds until two cycles after the next we_i. The words alternate between the two
// addresses, so the read of a cycle (the last written word) never meets that cycle's write.
module trirast_improved2_stage_ram #(
  parameter int Bits = 1
) (
  input  logic            clk_i,
  input  logic            rst_ni,
  input  logic            we_i,
  input  logic [Bits-1:0] d_i,
  output logic [Bits-1:0] q_o
);
  (* ram_style = "block" *) logic [Bits-1:0] mem [2];
  logic wsel_q;                  // the address the next write takes
  logic [Bits-1:0] rdata_q;      // the memory's output register (no reset)

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) wsel_q <= 1'b0;
    else if (we_i) wsel_q <= !wsel_q;
  end
  always_ff @(posedge clk_i) begin
    if (we_i) mem[wsel_q] <= d_i;
  end
  always_ff @(posedge clk_i) begin
    rdata_q <= mem[!wsel_q];
  end
  assign q_o = rdata_q;

endmodule
