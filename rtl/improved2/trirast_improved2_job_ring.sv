// The second-generation improved unit's job ring (rtl/improved2/trirast_improved2.f; trirast_improved2_top's
// walk-stage fields): a pipeline's per-job fields written once, as a job enters the pipeline, and
// read by a stage further down in the same order, so that the stage needs no copy of them. A
// memory of Words words read through its output register (Yosys maps it to block RAM,
// SB_RAM40_4K), written at the write pointer (we_i, then the next word) and read at the read
// pointer: next_i moves the read pointer to the next word, and q_o shows that word from the cycle
// after next_i until the next next_i. The caller keeps fewer than Words jobs between the write of
// a word and its last read, so no write meets the word being read (RingNoCollision_A), and the
// memory needs no read-during-write bypass.
`include "trirast_assert.svh"

module trirast_improved2_job_ring #(
  parameter int Bits  = 1,
  parameter int Words = 4   // a power of two
) (
  input  logic            clk_i,
  input  logic            rst_ni,
  input  logic            we_i,     // write d_i into the next word
  input  logic [Bits-1:0] d_i,
  input  logic            next_i,   // read the next word (from the next cycle on)
  output logic [Bits-1:0] q_o
);
  localparam int PW = $clog2(Words);
  (* ram_style = "block", no_rw_check *) logic [Bits-1:0] mem [Words];
  logic [PW-1:0] wp_q, rp_q, rp_d;
  logic [Bits-1:0] rdata_q;      // the memory's output register (no reset)

  assign rp_d = rp_q + PW'(next_i);
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wp_q <= '0;
      rp_q <= '1;   // the first next_i reads word 0
    end else begin
      if (we_i) wp_q <= wp_q + 1'b1;
      rp_q <= rp_d;
    end
  end
  always_ff @(posedge clk_i) begin
    if (we_i) mem[wp_q] <= d_i;
  end
  always_ff @(posedge clk_i) begin
    rdata_q <= mem[rp_d];
  end
  assign q_o = rdata_q;

  `ASSERT_IMPLIES(RingNoCollision_A, we_i, wp_q != rp_d, clk_i, !rst_ni)

endmodule
