// The half-space unit's stamp tester (docs/unit.md "The half-space unit", stage 3): in one cycle
// the three edge functions at the StampSize x StampSize pixel centres from box pixel (i0, j0):
// E = e + di*a + dj*b with a = A*u, b = B*u (constant multiples: adders); a pixel is covered when
// every E >= 0 (or its edge holds the whole stamp inside: inside_i) and it lies in the box: one
// bit per pixel (the walker forms each stamp row's piece from them). With tiles its values are
// tile-relative, the low EdgeBits of E (the walker's OffBits: exact for an edge that crosses the
// tile).
// The stamp origin is StampSize-aligned and inside the box (the walker asserts both,
// HalfspaceStampAligned_A and HalfspaceUnitInBox_A / HalfspaceStampInTile_A): a pixel's column is
// in the box unless the stamp holds Xmax's column and di passes Xmax's low bits (no compare of
// magnitudes); the same for rows.
module trirast_halfspace_stamp_tester #(
  parameter int StampSize = 2,
  parameter int EdgeBits = trirast_pkg::EdgeBits  // its values' bits (the walker's StampBits)
) (
  input  logic [3*EdgeBits-1:0]                  e_i,       // E of edge k at the stamp origin
  input  logic [2:0]                             inside_i,  // edge k holds the stamp inside
  input  logic [3*EdgeBits-1:0]                  a_i,       // a = A*u of edge k
  input  logic [3*EdgeBits-1:0]                  b_i,       // b = B*u of edge k
  input  logic [trirast_pkg::BoxBits:0]          i0_i,      // stamp origin, box-relative
  input  logic [trirast_pkg::BoxBits:0]          j0_i,
  input  logic [trirast_pkg::BoxBits-1:0]        xmax_i,
  input  logic [trirast_pkg::BoxBits-1:0]        ymax_i,
  output logic [StampSize*StampSize-1:0]         cover_o    // pixel (di, dj): bit dj*StampSize + di
);
  localparam int SL = $clog2(StampSize);
  localparam int SB = (SL > 0) ? SL : 1;  // a pixel's offset in the stamp (StampSize 1: 0)
  logic last_col, last_row;  // the stamp holds the box's last column (row)
  assign last_col = (i0_i >> SL) == ({1'b0, xmax_i} >> SL);
  assign last_row = (j0_i >> SL) == ({1'b0, ymax_i} >> SL);

  // Icarus 11: a combinational block writes each module-level variable once, from block-local
  // temporaries (docs/rtl.md, "Icarus"); a variable written twice glitches, and the glitch wakes
  // the blocks that read it (here the walker's) in the same time step, again and again.
  always_comb begin
    logic [StampSize*StampSize-1:0] covered;
    for (int dj = 0; dj < StampSize; dj++) begin
      for (int di = 0; di < StampSize; di++) begin
        logic in;
        in = (!last_col || SB'(di) <= SB'(xmax_i & trirast_pkg::BoxBits'(StampSize - 1))) &&
             (!last_row || SB'(dj) <= SB'(ymax_i & trirast_pkg::BoxBits'(StampSize - 1)));
        for (int k = 0; k < 3; k++) begin
          logic [EdgeBits-1:0] v;
          v = e_i[k*EdgeBits +: EdgeBits] + EdgeBits'(di) * a_i[k*EdgeBits +: EdgeBits] +
              EdgeBits'(dj) * b_i[k*EdgeBits +: EdgeBits];
          in = in && (inside_i[k] || !v[EdgeBits-1]);
        end
        covered[dj*StampSize + di] = in;
      end
    end
    cover_o = covered;
  end
endmodule
