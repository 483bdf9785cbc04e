// The port bundles the units share, spelled once: the triangle port, the span port, the timing
// observation, the hand-offs and the improved units' lane results, each as a declaration macro
// and a connection macro; the control register with its reset; the package's names.
// Macros, not packed structs: Icarus 11 aborts on a package-scoped struct type and Yosys 0.23
// refuses `import` (docs/rtl.md, "Port bundles and register macros"). A macro expands to the same declarations in
// every tool, so the synthesized netlists do not depend on it.
// Widths are trirast_pkg's (rtl/common/trirast_pkg.sv); a macro that names CountBits needs the
// including module's parameter of that name.
`ifndef TRIRAST_PORTS_SVH
`define TRIRAST_PORTS_SVH

// ---- a control register with its reset value (clock clk_i, active-low asynchronous reset
// rst_ni; datapath registers have no reset: they are written before they are read) ----
`define TRIRAST_FLOP_AR(q, d, reset_value) \
  always_ff @(posedge clk_i or negedge rst_ni) begin \
    if (!rst_ni) q <= reset_value; \
    else q <= d; \
  end

// ---- every top's clock, reset and viewport (static configuration: the viewport's width - 1 and
// height - 1, the last pixel's index) ----
//   clk_i : the clock; every register takes its value at the rising edge
//   rst_ni : asynchronous reset, active low: every control register to its idle value
//   cfg_vp_xmax_i, cfg_vp_ymax_i : the viewport's last pixel, width - 1 and height - 1
//                                  (static during a run)
`define TRIRAST_TOP_CLOCK_AND_VIEWPORT \
  input  logic                                  clk_i, \
  input  logic                                  rst_ni, \
  input  logic [trirast_pkg::PixBits-1:0]       cfg_vp_xmax_i, \
  input  logic [trirast_pkg::PixBits-1:0]       cfg_vp_ymax_i

// ---- the triangle port: one set-up triangle per valid/ready handshake ----
//   tri_valid_i : a triangle is on the port (held, with its fields, until tri_ready_o)
//   tri_ready_o : the unit takes the triangle at this rising edge if tri_valid_i
//   tri_tag_i : returned with the triangle's spans
//   tri_vx_i, tri_vy_i : vertex k at [k*VertexBits +: VertexBits], signed, in 1/2^SubpixelBits
//                        pixel (1/256 at the default S = 8)
//   tri_a_i, tri_b_i : edge k's A and B at [k*CoefBits +: CoefBits], signed
//   tri_c_i : edge k's C at [k*EdgeBits +: EdgeBits], signed
//   tri_bias_i : bit k = 1: edge k's bias is -1 (the coverage rule's tie-break)
// The traditional unit's port carries the vertices only (TRIRAST_TRIANGLE_PORT_VERTICES).
`define TRIRAST_TRIANGLE_PORT_VERTICES \
  input  logic                                  tri_valid_i, \
  output logic                                  tri_ready_o, \
  input  logic [trirast_pkg::TagBits-1:0]       tri_tag_i, \
  input  logic [3*trirast_pkg::VertexBits-1:0]  tri_vx_i, \
  input  logic [3*trirast_pkg::VertexBits-1:0]  tri_vy_i
`define TRIRAST_TRIANGLE_PORT \
  `TRIRAST_TRIANGLE_PORT_VERTICES, \
  input  logic [3*trirast_pkg::CoefBits-1:0]    tri_a_i, \
  input  logic [3*trirast_pkg::CoefBits-1:0]    tri_b_i, \
  input  logic [3*trirast_pkg::EdgeBits-1:0]    tri_c_i, \
  input  logic [2:0]                            tri_bias_i
// The set-up stage's tri_ready_o drives the top's stage_tri_ready, which the top gates with rst_ni
// (TRIRAST_TRIANGLE_READY_GATE): no triangle is taken while rst_ni is low (docs/port.md, "Clock,
// reset and configuration").
`define TRIRAST_TRIANGLE_READY_GATE \
  logic stage_tri_ready; \
  assign tri_ready_o = rst_ni && stage_tri_ready;
`define TRIRAST_CONNECT_TRIANGLE_PORT_VERTICES \
  .tri_valid_i (tri_valid_i), \
  .tri_ready_o (stage_tri_ready), \
  .tri_tag_i   (tri_tag_i), \
  .tri_vx_i    (tri_vx_i), \
  .tri_vy_i    (tri_vy_i)
`define TRIRAST_CONNECT_TRIANGLE_PORT \
  `TRIRAST_CONNECT_TRIANGLE_PORT_VERTICES, \
  .tri_a_i     (tri_a_i), \
  .tri_b_i     (tri_b_i), \
  .tri_c_i     (tri_c_i), \
  .tri_bias_i  (tri_bias_i)
// A top's check of the triangle port's preconditions (trirast_triangle_port_check, docs/port.md,
// "Preconditions"), for simulation only: the caller encloses it in `ifndef SYNTHESIS and
// `ifndef FORMAL. A port without edge functions passes '0 for a, b, c and bias.
`define TRIRAST_TRIANGLE_PORT_CHECK(has_edges, reads_c, has_box, a, b, c, bias) \
  trirast_triangle_port_check #(.HasEdges (has_edges), .ReadsC (reads_c), .HasBox (has_box)) \
      u_port_check ( \
    .clk_i (clk_i), .rst_ni (rst_ni), \
    .cfg_vp_xmax_i (cfg_vp_xmax_i), .cfg_vp_ymax_i (cfg_vp_ymax_i), \
    .tri_valid_i (tri_valid_i), .tri_ready_i (tri_ready_o), .tri_vx_i (tri_vx_i), \
    .tri_vy_i (tri_vy_i), .tri_a_i (a), .tri_b_i (b), .tri_c_i (c), .tri_bias_i (bias));
// A setup stage's trirast_box_stage (improved, half-space): the triangle port's fields in (the
// stage registers them at accept), the hand-off's box out; the edge terms (a_o, b_o, el_o, er_o)
// are the caller's to connect.
`define TRIRAST_CONNECT_BOX_STAGE(accept, box_en, empty) \
  .clk_i     (clk_i), \
  .rst_ni    (rst_ni), \
  .vp_xmax_i (vp_xmax_i), \
  .vp_ymax_i (vp_ymax_i), \
  .accept_i  (accept), \
  .tag_i     (tri_tag_i), \
  .vx_i      (tri_vx_i), \
  .vy_i      (tri_vy_i), \
  .a_i       (tri_a_i), \
  .b_i       (tri_b_i), \
  .c_i       (tri_c_i), \
  .bias_i    (tri_bias_i), \
  .box_i     (box_en), \
  .empty_o   (empty), \
  .tag_o     (hand_tag_o), \
  .x0_o      (hand_x0_o), \
  .y0_o      (hand_y0_o), \
  .xmax_o    (hand_xmax_o), \
  .ymax_o    (hand_ymax_o)

// A top's setup stage (improved, half-space): clock, reset, the viewport, the triangle port, the
// empty-box retirement and the hand-off's handshake and box.
`define TRIRAST_CONNECT_SETUP_STAGE \
  .clk_i (clk_i), .rst_ni (rst_ni), .vp_xmax_i (cfg_vp_xmax_i), .vp_ymax_i (cfg_vp_ymax_i), \
  `TRIRAST_CONNECT_TRIANGLE_PORT, \
  .box_retire_o (box_retire_o), .box_retire_tag_o (box_retire_tag_o), \
  .hand_valid_o (hand_valid), .hand_ready_i (hand_ready), \
  `TRIRAST_CONNECT_HANDOFF_BOX(_o)

// ---- the span port: one span {tag, y, x_begin, x_end (exclusive)} per valid/ready handshake ----
//   span_valid_o : a span is on the port (held, with its fields, until span_ready_i)
//   span_ready_i : the downstream takes the span at this rising edge if span_valid_o
//   span_tag_o : the tag of the triangle the span belongs to
//   span_y_o : the span's pixel row
//   span_x_begin_o : its first pixel
//   span_x_end_o : one past its last pixel (exclusive; one bit wider, a span may end at the
//                  viewport's width)
`define TRIRAST_SPAN_PORT \
  output logic                                  span_valid_o, \
  input  logic                                  span_ready_i, \
  output logic [trirast_pkg::TagBits-1:0]       span_tag_o, \
  output logic [trirast_pkg::PixBits-1:0]       span_y_o, \
  output logic [trirast_pkg::PixBits-1:0]       span_x_begin_o, \
  output logic [trirast_pkg::PixBits:0]         span_x_end_o
// A top's trirast_span_port: the walk stage's pushes in (push, push_data), its occupancy out to
// fifo_count_o, the span port out.
`define TRIRAST_CONNECT_SPAN_PORT \
  .clk_i (clk_i), .rst_ni (rst_ni), \
  .push_i (push), .push_data_i (push_data), .count_o (fifo_count_o), \
  .span_valid_o (span_valid_o), .span_ready_i (span_ready_i), .span_tag_o (span_tag_o), \
  .span_y_o (span_y_o), .span_x_begin_o (span_x_begin_o), .span_x_end_o (span_x_end_o)

// ---- the walk stage's timing observation (the harness's per-triangle timing) ----
//   walk_busy_o : a triangle walks (half-space unit: or a span is in the span FIFO's push register)
//   walk_stall_o : ... and waits for FIFO room this cycle
//   walk_last_o : its last group or row goes
//   walk_retire_o : ... and it had no span
//   walk_tag_o : the walking triangle's tag
//   fifo_count_o : the span FIFO's occupancy at the cycle's start
`define TRIRAST_WALK_OBSERVATION \
  output logic                                  walk_busy_o, \
  output logic                                  walk_stall_o, \
  output logic                                  walk_last_o, \
  output logic                                  walk_retire_o, \
  output logic [trirast_pkg::TagBits-1:0]       walk_tag_o, \
  output logic [CountBits-1:0]                  fifo_count_o

// A top's walk stage (improved, traditional): its pushes, its occupancy input and its
// observation outputs.
`define TRIRAST_CONNECT_WALK_STAGE_OUTPUTS \
  .fifo_count_i (fifo_count_o), \
  .push_o       (push), \
  .push_data_o  (push_data), \
  .busy_o       (walk_busy_o), \
  .stall_o      (walk_stall_o), \
  .last_o       (walk_last_o), \
  .retire_o     (walk_retire_o), \
  .tag_o        (walk_tag_o), \
  .row_o        (walk_row)

// The hand-off's observation (improved, improved2, half-space tops): handoff_o in the cycle the
// walk stage loads, with the loaded box's Xmax and Ymax.
`define TRIRAST_ASSIGN_HANDOFF_OBSERVATION(xmax, ymax) \
  assign handoff_o = hand_valid && hand_ready; \
  assign {box_xmax_o, box_ymax_o} = {xmax, ymax};

// ---- the hand-off's box: the triangle's tag, box corner (x0, y0) and extent (Xmax, Ymax) ----
// direction (input or output) and the port suffix (_i or _o) are the module's side of it.
`define TRIRAST_HANDOFF_BOX(direction, suffix) \
  direction logic [trirast_pkg::TagBits-1:0]     hand_tag``suffix, \
  direction logic [trirast_pkg::PixBits-1:0]     hand_x0``suffix, \
  direction logic [trirast_pkg::PixBits-1:0]     hand_y0``suffix, \
  direction logic [trirast_pkg::BoxBits-1:0]     hand_xmax``suffix, \
  direction logic [trirast_pkg::BoxBits-1:0]     hand_ymax``suffix
// A walk stage takes the hand-off's box into its registers' next values (tag_d .. ymax_d).
`define TRIRAST_LOAD_HANDOFF_BOX \
  {tag_d, x0_d, y0_d, xmax_d, ymax_d} = {hand_tag_i, hand_x0_i, hand_y0_i, hand_xmax_i, hand_ymax_i};
`define TRIRAST_CONNECT_HANDOFF_BOX(suffix) \
  .hand_tag``suffix  (hand_tag), \
  .hand_x0``suffix   (hand_x0), \
  .hand_y0``suffix   (hand_y0), \
  .hand_xmax``suffix (hand_xmax), \
  .hand_ymax``suffix (hand_ymax)

// ---- the improved units' edge hand-off: each edge lane's results for its walker (edge k at
// [k*width +: width]): mirror, direction, |D|, the quotient and remainder steps, the saturated
// step, and the entry row, state, x and error term (docs/unit.md, sections 3-5). ----
`define TRIRAST_IMPROVED_HANDOFF_EDGES(direction, suffix) \
  direction logic [2:0]                            hand_mirror``suffix, \
  direction logic [2:0]                            hand_dir_down``suffix, \
  direction logic [3*trirast_pkg::StepBits-1:0]    hand_d``suffix, \
  direction logic [3*trirast_pkg::QuotBits-1:0]    hand_qs``suffix, \
  direction logic [3*trirast_pkg::RemBits-1:0]     hand_rs``suffix, \
  direction logic [2:0]                            hand_ssat``suffix, \
  direction logic [2:0]                            hand_enters``suffix, \
  direction logic [3*trirast_pkg::RowBits-1:0]     hand_j_entry``suffix, \
  direction logic [5:0]                            hand_entry_state``suffix, \
  direction logic [3*trirast_pkg::WalkerXBits-1:0] hand_entry_x``suffix
`define TRIRAST_CONNECT_IMPROVED_HANDOFF_EDGES(suffix) \
  .hand_mirror``suffix      (hand_mirror), \
  .hand_dir_down``suffix    (hand_dir_down), \
  .hand_d``suffix           (hand_d), \
  .hand_qs``suffix          (hand_qs), \
  .hand_rs``suffix          (hand_rs), \
  .hand_ssat``suffix        (hand_ssat), \
  .hand_enters``suffix      (hand_enters), \
  .hand_j_entry``suffix     (hand_j_entry), \
  .hand_entry_state``suffix (hand_entry_state), \
  .hand_entry_x``suffix     (hand_entry_x)

// ---- one improved edge lane's results, the walker's start registers (docs/unit.md, section
// 4): mirror (a > 0: a left edge), direction (b >= 0: X' grows down the box), D = |a|, the
// slope's quotient q_s and remainder r_s, the saturated slope, whether the edge enters the box at
// a row <= Ymax, that row j_entry, the row state there (RowOut/RowBound/RowClear) and X' there. ----
`define TRIRAST_IMPROVED_EDGE_RESULT(direction, suffix) \
  direction logic                                     mirror``suffix, \
  direction logic                                     dir_down``suffix, \
  direction logic [trirast_pkg::StepBits-1:0]         d``suffix, \
  direction logic [trirast_pkg::QuotBits-1:0]         qs``suffix, \
  direction logic [trirast_pkg::RemBits-1:0]          rs``suffix, \
  direction logic                                     ssat``suffix, \
  direction logic                                     enters``suffix, \
  direction logic [trirast_pkg::RowBits-1:0]          j_entry``suffix, \
  direction logic [1:0]                               entry_state``suffix, \
  direction logic signed [trirast_pkg::WalkerXBits-1:0] entry_x``suffix

// ---- the traditional unit's hand-off: the triangle's tag, its pixels sorted p0..p2 (at
// [k*CoordIntBits +: CoordIntBits]) and per line e (0 long, 1 and 2 short) the step direction,
// the major axis, the major and minor deltas and the initial decision value. ----
`define TRIRAST_TRAD_HANDOFF(direction, suffix) \
  direction logic [trirast_pkg::TagBits-1:0]           hand_tag``suffix, \
  direction logic [3*trirast_pkg::CoordIntBits-1:0]    hand_px``suffix, \
  direction logic [3*trirast_pkg::CoordIntBits-1:0]    hand_py``suffix, \
  direction logic [2:0]                                hand_sx_neg``suffix, \
  direction logic [2:0]                                hand_x_major``suffix, \
  direction logic [3*trirast_pkg::CoordIntBits-1:0]    hand_dmaj``suffix, \
  direction logic [3*trirast_pkg::CoordIntBits-1:0]    hand_dmin``suffix, \
  direction logic [3*(trirast_pkg::CoordIntBits+3)-1:0] hand_d0``suffix
`define TRIRAST_CONNECT_TRAD_HANDOFF(suffix) \
  .hand_tag``suffix     (hand_tag), \
  .hand_px``suffix      (hand_px), \
  .hand_py``suffix      (hand_py), \
  .hand_sx_neg``suffix  (hand_sx_neg), \
  .hand_x_major``suffix (hand_x_major), \
  .hand_dmaj``suffix    (hand_dmaj), \
  .hand_dmin``suffix    (hand_dmin), \
  .hand_d0``suffix      (hand_d0)

// ---- the same bundles as signals: in the module that connects two stages (prefix hand_), or
// as a testbench's struct fields (prefix empty) ----
`define TRIRAST_HANDOFF_BOX_SIGNALS(prefix) \
  logic [trirast_pkg::TagBits-1:0] prefix``tag; \
  logic [trirast_pkg::PixBits-1:0] prefix``x0, prefix``y0; \
  logic [trirast_pkg::BoxBits-1:0] prefix``xmax, prefix``ymax;
`define TRIRAST_IMPROVED_HANDOFF_EDGES_SIGNALS(prefix) \
  logic [2:0] prefix``mirror, prefix``dir_down, prefix``ssat, prefix``enters; \
  logic [3*trirast_pkg::StepBits-1:0] prefix``d; \
  logic [3*trirast_pkg::QuotBits-1:0] prefix``qs; \
  logic [3*trirast_pkg::RemBits-1:0] prefix``rs; \
  logic [3*trirast_pkg::RowBits-1:0] prefix``j_entry; \
  logic [5:0] prefix``entry_state; \
  logic [3*trirast_pkg::WalkerXBits-1:0] prefix``entry_x;

// ---- the package's names in a module's scope: what `import trirast_pkg::*` would give (Yosys
// 0.23 refuses import), the widths of docs/unit.md "Widths" and the row states; and the short
// names the second-generation unit's arithmetic is written in. A module uses what it needs. ----
`define TRIRAST_PKG_NAMES \
  /* verilator lint_off UNUSEDPARAM */ \
  localparam int SubpixelBits = trirast_pkg::SubpixelBits; \
  localparam int CoordIntBits = trirast_pkg::CoordIntBits; \
  localparam int FracBits = trirast_pkg::FracBits; \
  localparam int VertexBits = trirast_pkg::VertexBits; \
  localparam int CoefBits = trirast_pkg::CoefBits; \
  localparam int StepBits = trirast_pkg::StepBits; \
  localparam int EdgeBits = trirast_pkg::EdgeBits; \
  localparam int BoxBits = trirast_pkg::BoxBits; \
  localparam int QuotBits = trirast_pkg::QuotBits; \
  localparam int RemBits = trirast_pkg::RemBits; \
  localparam int WalkerXBits = trirast_pkg::WalkerXBits; \
  localparam int NumerBits = trirast_pkg::NumerBits; \
  localparam int RowBits = trirast_pkg::RowBits; \
  localparam int PixBits = trirast_pkg::PixBits; \
  localparam int TagBits = trirast_pkg::TagBits; \
  localparam logic [1:0] RowOut = trirast_pkg::RowOut; \
  localparam logic [1:0] RowBound = trirast_pkg::RowBound; \
  localparam logic [1:0] RowClear = trirast_pkg::RowClear; \
  /* verilator lint_on UNUSEDPARAM */
`define TRIRAST_PKG_SHORT_NAMES \
  /* verilator lint_off UNUSEDPARAM */ \
  localparam int F  = FracBits,  P  = VertexBits, CB = CoefBits, EB = EdgeBits; \
  localparam int PB = PixBits,   BB = BoxBits,    TB = TagBits,  SB = StepBits; \
  localparam int QB = QuotBits,  RB = RemBits,    WB = RowBits,  XB = WalkerXBits; \
  /* verilator lint_on UNUSEDPARAM */

`endif  // TRIRAST_PORTS_SVH
