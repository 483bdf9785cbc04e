// The half-space unit's span emitter (docs/unit.md "The half-space unit", stage 4; docs/timing.md):
// two buffers of UnitSize rows. The collect buffer widens each row's run [first, last] with the
// walker's pieces (stamp rows, accepted tiles) of the current band; at band_load_i (end of the
// band) the merged rows move to the emit buffer, which pushes one span per cycle, lowest row
// first, when the FIFO has room at the start of the cycle: count + pending < DEPTH, with pending
// the span in the push register in front of the span FIFO (trirast_halfspace_top: a span pushed
// in t is counted from the end of t + 1).
`include "trirast_assert.svh"

module trirast_halfspace_span_emitter #(
  parameter int UnitSize = 8,
  parameter int CountBits = 4,
  parameter int EntryBits = trirast_pkg::TagBits + 3 * trirast_pkg::PixBits + 1
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic [CountBits-1:0]                  fifo_depth_i,
  input  logic [CountBits-1:0]                  fifo_count_i,
  input  logic                                  fifo_pending_i,  // a span in the FIFO's push register
  // ---- the triangle (stable while the walk stage is busy) ----
  input  logic [trirast_pkg::TagBits-1:0]       tag_i,
  input  logic [trirast_pkg::PixBits-1:0]       x0_i,
  input  logic [trirast_pkg::PixBits-1:0]       y0_i,
  // ---- the walker's pieces of the current band, row r of the band ----
  input  logic [UnitSize-1:0]                   merge_i,
  input  logic [UnitSize*(trirast_pkg::BoxBits+1)-1:0] merge_first_i,
  input  logic [UnitSize*(trirast_pkg::BoxBits+1)-1:0] merge_last_i,
  // ---- band hand-over (a valid/ready pair: band_load_i only when free_o) ----
  input  logic                                  band_load_i,
  input  logic [trirast_pkg::BoxBits:0]         band_j0_i,
  output logic                                  any_o,    // the band has a row with a run
  output logic                                  free_o,   // nothing left to push after this cycle
  // ---- FIFO pushes ----
  output logic                                  push_o,
  output logic [EntryBits-1:0]                  push_data_o,
  output logic                                  stall_o   // a span waits for FIFO room
);
  localparam int PB = trirast_pkg::BoxBits + 1;
  localparam int PixBits = trirast_pkg::PixBits;
  localparam int RowBits = (UnitSize > 1) ? $clog2(UnitSize) : 1;

  logic [UnitSize-1:0] acc_q, acc_d, pend_q, pend_d, merged;
  logic [UnitSize*PB-1:0] accf_q, accf_d, accl_q, accl_d, outf_q, outf_d, outl_q, outl_d;
  logic [UnitSize*PB-1:0] mf, ml;
  logic [PB-1:0] outj0_q, outj0_d;
  logic room;
  logic [RowBits-1:0] row;
  logic [UnitSize-1:0] pend_next;

  // The collect buffer merged with this cycle's pieces. Every combinational block writes each
  // module-level variable once, from block-local temporaries (Icarus 11: see
  // trirast_halfspace_stamp_tester.sv).
  always_comb begin
    logic [UnitSize*PB-1:0] f, l;
    f = accf_q;
    l = accl_q;
    for (int r = 0; r < UnitSize; r++) begin
      if (merge_i[r]) begin
        if (!acc_q[r] || merge_first_i[r*PB +: PB] < accf_q[r*PB +: PB])
          f[r*PB +: PB] = merge_first_i[r*PB +: PB];
        if (!acc_q[r] || merge_last_i[r*PB +: PB] > accl_q[r*PB +: PB])
          l[r*PB +: PB] = merge_last_i[r*PB +: PB];
      end
    end
    merged = acc_q | merge_i;
    mf = f;
    ml = l;
  end
  assign any_o = |merged;

  // The emit buffer: the lowest pending row goes when the FIFO has room.
  assign room = (CountBits + 1)'(fifo_count_i) + (CountBits + 1)'(fifo_pending_i) <
                (CountBits + 1)'(fifo_depth_i);
  always_comb begin
    logic [RowBits-1:0] lowest;
    lowest = '0;
    for (int r = UnitSize - 1; r >= 0; r--) if (pend_q[r]) lowest = RowBits'(r);
    row = lowest;
  end
  assign push_o = |pend_q && room;
  assign stall_o = |pend_q && !room;
  always_comb begin
    logic [UnitSize-1:0] left;
    left = pend_q;
    if (push_o) left[row] = 1'b0;
    pend_next = left;
  end
  assign free_o = ~|pend_next;

  always_comb begin
    logic [PixBits-1:0] y, xb;
    logic [PixBits:0] xe;
    y = y0_i + PixBits'(outj0_q) + PixBits'(row);
    xb = x0_i + PixBits'(outf_q[row*PB +: PB]);
    xe = {1'b0, x0_i} + (PixBits+1)'(outl_q[row*PB +: PB]) + 1'b1;
    push_data_o = {tag_i, y, xb, xe};
  end

  assign acc_d = band_load_i ? '0 : merged;
  assign accf_d = mf;
  assign accl_d = ml;
  assign pend_d = band_load_i ? merged : pend_next;
  assign outf_d = band_load_i ? mf : outf_q;
  assign outl_d = band_load_i ? ml : outl_q;
  assign outj0_d = band_load_i ? band_j0_i : outj0_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      acc_q <= '0;
      pend_q <= '0;
    end else begin
      acc_q <= acc_d;
      pend_q <= pend_d;
    end
  end
  always_ff @(posedge clk_i) begin
    {accf_q, accl_q, outf_q, outl_q, outj0_q} <= {accf_d, accl_d, outf_d, outl_d, outj0_d};
  end

  // A band is handed over only when the previous one is out.
  `ASSERT_IMPLIES(HalfspaceBandLoadWhenFree_A, band_load_i, free_o, clk_i, !rst_ni)
  `ASSERT_KNOWN(HalfspaceEmitterKnown_A, {push_o, free_o, any_o, stall_o}, clk_i, !rst_ni)
  `ASSERT_KNOWN_IF(HalfspacePushDataKnown_A, push_o, push_data_o, clk_i, !rst_ni)
endmodule
