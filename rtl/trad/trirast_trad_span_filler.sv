// Stage 3 of the traditional unit, TradSpanFiller (model/trad_bresenham.*): the leftmost and
// rightmost pixel the three lines put on the row being walked, accumulated over the row's cycles
// from the walkers' step pixels (and the start pixel p0 on the first row); at the row's end the
// span [leftmost, rightmost + 1), clipped to the viewport [0, W) x [0, H), is valid when non-empty.
`include "trirast_ports.svh"

module trirast_trad_span_filler #(
  parameter int WBits = 18  // signed bits of a pixel coordinate and of the row
) (
  input  logic                                 clk_i,
  input  logic [trirast_pkg::PixBits-1:0]      vp_xmax_i,   // W - 1
  input  logic [trirast_pkg::PixBits-1:0]      vp_ymax_i,   // H - 1
  input  logic                                 load_i,      // a triangle: its first row has p0
  input  logic signed [WBits-1:0]              load_x_i,    // p0.x
  input  logic                                 a_step_i,    // long walker's step pixel
  input  logic signed [WBits-1:0]              a_x_i,
  input  logic                                 b_step_i,    // short walker's step pixel
  input  logic signed [WBits-1:0]              b_x_i,
  input  logic                                 row_end_i,   // the row's last cycle
  input  logic signed [WBits-1:0]              row_i,
  output logic                                 valid_o,     // row_end_i and a span
  output logic [trirast_pkg::PixBits-1:0]      y_o,
  output logic [trirast_pkg::PixBits-1:0]      begin_o,
  output logic [trirast_pkg::PixBits:0]        end_o        // exclusive
);
  `TRIRAST_PKG_NAMES

  logic signed [WBits-1:0] lo_q, lo_d, hi_q, hi_d;  // the row's pixels so far
  logic any_q, any_d;                               // ... if any

  // Merge the long walker's pixel, then the short walker's.
  logic signed [WBits-1:0] lo_a, hi_a, lo_n, hi_n;
  logic any_a, any_n;
  assign lo_a  = (!any_q || (a_step_i && a_x_i < lo_q)) ? a_x_i : lo_q;
  assign hi_a  = (!any_q || (a_step_i && a_x_i > hi_q)) ? a_x_i : hi_q;
  assign any_a = any_q || a_step_i;
  assign lo_n  = (!any_a || (b_step_i && b_x_i < lo_a)) ? b_x_i : lo_a;
  assign hi_n  = (!any_a || (b_step_i && b_x_i > hi_a)) ? b_x_i : hi_a;
  assign any_n = any_a || b_step_i;

  // Clip: begin = max(lo, 0), end = min(hi + 1, W).
  logic signed [WBits-1:0] w, h1, span_begin, span_end, hi1;
  logic in_rows;
  assign w          = WBits'({1'b0, vp_xmax_i}) + WBits'(1);
  assign h1         = WBits'({1'b0, vp_ymax_i});  // H - 1, as a signed value
  assign hi1        = hi_n + WBits'(1);
  assign span_begin = (lo_n < WBits'(0)) ? WBits'(0) : lo_n;
  assign span_end   = (hi1 > w) ? w : hi1;
  assign in_rows    = (row_i >= WBits'(0)) && (row_i <= h1);
  assign valid_o    = row_end_i && any_n && in_rows && (span_begin < span_end);
  assign y_o        = row_i[PixBits-1:0];
  assign begin_o    = span_begin[PixBits-1:0];
  assign end_o      = span_end[PixBits:0];

  assign lo_d  = load_i ? load_x_i : lo_n;
  assign hi_d  = load_i ? load_x_i : hi_n;
  assign any_d = load_i || (any_n && !row_end_i);

  // No reset: loaded at the hand-off before it is read.
  always_ff @(posedge clk_i) begin
    lo_q  <= lo_d;
    hi_q  <= hi_d;
    any_q <= any_d;
  end

  // Upper bits of the clipped values are 0 when valid_o (0 <= begin < end <= W <= 2^PixBits).
  logic unused_upper;
  assign unused_upper = ^{row_i[WBits-1:PixBits], span_begin[WBits-1:PixBits],
                          span_end[WBits-1:PixBits+1]};

endmodule
