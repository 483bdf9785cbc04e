// The improved unit, second generation (engine "improved2-rtl"; docs/timing.md, "The
// second-generation improved unit", for the cycle contract its SystemC model improved2-sc follows,
// docs/improved2.md for its design, and docs/rtl.md): the paper's
// adder-based divider, boundary traversal, Bresenham stepping with remainder accumulation and span
// generation, rebuilt as a pipeline of four stages so the next triangle's box and corner values are
// formed while the lanes and the walk stage work. Boundary mode step, adaptive divider (build
// choices here: no cfg ports for them). NumEndpoints N: the walk stage's rows per cycle (1, 2, 4;
// cfg_endpoints_i = n <= N at run time, as rtl/improved/trirast_improved_top.sv's; with N = 1 cfg_endpoints_i is
// unused). Triangle port and span port as rtl/improved/trirast_improved_top.sv's, but the unit reads only the
// vertices (and the tag): A, B and the bias are formed from them, and the corner values are
// vertex-relative, E = A*(cx - vx) + B*(cy - vy), so tri_a_i, tri_b_i, tri_bias_i are read only
// by the port's precondition checks (trirast_triangle_port_check: the port's are the vertices'),
// tri_c_i not at all.
//
//   [B] triangle register (tag, vertices) with the box (each axis's clipped first pixel and its
//       last pixel, clipped at the take) and its empty flag, formed from the port in the accept
//       cycle; an empty box retires here (box_retire_o)
//   [C] corner-stage register (tag, box, vertices, and A, B, A + B, bias formed from B's
//       vertices); corner values E_L per edge:
//       CornerForm 0: trirast_improved2_corner_products (multipliers, DSPs on xc7; no extra cycle);
//       CornerForm 1: trirast_corner_serial (MSB-first radix 16 on signed-digit pairs), started
//       as the triangle enters C: C holds it d + 1 cycles for E_L (d the fewest 4-bit digits in
//       which the operands fit signed); a box for the lanes then runs again, 1 + d' more cycles,
//       at x1 = x0 + Xmax, and forms E_R in the accumulators of the edges whose lane reads E_R
//       (the others hold E_L), so each accumulator ends with its lane's value. CornerForm 0
//       forms each edge's value at its lane's column directly. The direct 2x2 test
//       (trirast_improved2_direct_test_2x2) reads E_L's low bits, its far-from-0 flag and the steps A, B,
//       A + B.
//   [L] job register (tag, box, tiny flag, the 2x2 test's row spans); a box of more than 2 x 2
//       pixel centres loads the three edge lanes (trirast_improved2_edge_lane: normalizer, adder-based
//       divider, boundary traversal) in the same cycle; the job is handed off when the lanes are
//       done (a tiny box: at once).
//   [W] the walk stage (trirast_improved2_walk_stage: three edge walkers presenting n rows, a span
//       generator per row, a registered push of up to n spans with its credit against
//       cfg_fifo_depth_i; its tag and box from the job ring, JobRing), span FIFO (n push
//       ports) -> span port.
// Order: every job (lane or tiny) passes through L and W in acceptance order.
// Build choices, all with the same spans and cycles (docs/improved2.md, "Build choices"):
// FifoRam 1, the span FIFO in block RAM (trirast_span_fifo_ram; N = 1 only, N > 1 has
// flip-flops); WalkerCs 0, the walkers' carry-in step; TestHi 1, the 2x2 test on E_L >> F and
// A, B; CRam 1 (CornerForm 1 only), C's register in block RAM but for the vertices and the bias.
// The defaults are the iCE40 form; scripts/synth.sh builds the xc7 form with CornerForm 0.
`include "trirast_assert.svh"
`include "trirast_ports.svh"

module trirast_improved2_top #(
  parameter int NumEndpoints = trirast_pkg::DefaultEndpoints,  // rows per cycle (hardware)
  parameter int FifoDepth  = trirast_pkg::DefaultFifoDepth,
  parameter int CornerForm = 1,  // 0: products (DSPs on xc7); 1: MSB-first radix 16 (iCE40 HX)
  parameter bit FifoRam    = 1'b1,
  parameter bit WalkerCs   = 1'b0,
  parameter bit TestHi     = 1'b1,
  parameter bit CRam       = 1'b1,  // CornerForm 1 only: C's fields in block RAM
  parameter bit JobRing    = 1'b1,  // the walk stage's tag, box from a job ring (block RAM)
  // trirast_improved2_edge_lane's FixedM and PreIter (0, 0: the adaptive divider as measured; other
  // values change the lanes' cycles, docs/improved2.md "Build choices")
  parameter int LaneFixedM  = 0,
  parameter int LanePreIter = 0,
  parameter int CountBits = $clog2(FifoDepth + 1)  // derived: do not override
) (
  // ---- clock, reset and configuration (static) ----
  `TRIRAST_TOP_CLOCK_AND_VIEWPORT,
  input  logic [CountBits-1:0]                  cfg_fifo_depth_i, // --fifo-depth (<= FifoDepth)
  input  logic [2:0]                            cfg_endpoints_i,  // --endpoints (<= NumEndpoints)
  // ---- triangle port: one set-up triangle per handshake ----
  `TRIRAST_TRIANGLE_PORT,  // tri_c_i : not read (vertex-relative E)
  // ---- span port ----
  `TRIRAST_SPAN_PORT,
  // ---- observation (the harness's per-triangle cycles and module counters; traces) ----
  output logic                                  box_retire_o,      // an empty box retires (B)
  output logic [trirast_pkg::TagBits-1:0]       box_retire_tag_o, // ... its tag
  output logic                                  busy_o,            // a triangle is in the unit
  output logic                                  box_valid_o,       // B holds a triangle
  output logic                                  box_stall_o,       // ... waiting for C
  output logic [trirast_pkg::TagBits-1:0]       box_tag_o, // ... its tag
  output logic                                  corner_valid_o,    // C holds a triangle
  output logic                                  corner_stall_o,    // ... done, waiting for L
  output logic                                  job_valid_o,       // L holds a job
  output logic                                  job_ready_o,       // ... ready to hand off
  output logic [trirast_pkg::TagBits-1:0]       job_tag_o, // ... its tag
  output logic                                  handoff_o,         // the walk stage loads L's job
  output logic [trirast_pkg::BoxBits-1:0]       box_xmax_o,        // L's box: Xmax, Ymax
  output logic [trirast_pkg::BoxBits-1:0]       box_ymax_o, //   (valid with handoff_o)
  output logic [2:0]                            lane_busy_o,       // lane k works this cycle
  output logic [2:0]                            lane_div_o,        // ... a divider iteration
  output logic [2:0]                            lane_step_o,       // ... a traversal row step
  `TRIRAST_WALK_OBSERVATION
);
  `TRIRAST_PKG_NAMES
  `TRIRAST_PKG_SHORT_NAMES

  // ---------------------------------------------------------------- B: triangle register, box
  logic b_full_q;
  logic [TB-1:0] b_tag_q;
  logic [3*P-1:0] b_vx_q, b_vy_q;
  logic b_take, b_retire, c_free;

  // The box is formed from the port in the accept cycle and registered with the triangle (the
  // port holds the triangle while it is offered): B holds each axis's clipped first pixel, its
  // last pixel (clipped to the viewport at the take, a compare beside the Xmax subtraction) and
  // the empty flag, so the retire and move decisions read registers. The first pixel is kept at
  // PB bits: it is read only for a box that is not empty, where 0 <= first <= the clipped last
  // <= the viewport's last pixel.
  // Per axis, with u = 2^F, h = u / 2 and each vertex v = hi * u + lo: the first pixel whose
  // centre p * u + h is >= v is ceil((v - h) / u) = hi + (lo > h), the last one whose centre is
  // <= v is t = floor((v - h) / u) = hi - (lo < h); both grow with v, so the box's first pixel is
  // the smallest vertex's (by three compares of the vertices, beside the t subtractions) and its
  // last the largest vertex's t. Unclipped, the box is empty exactly when no vertex has lo = h and
  // the three t are equal (no pixel centre between the smallest and the largest vertex): that
  // test reads the t and the low bits only, and the box starts past the viewport exactly when
  // every vertex's first pixel does (a compare per vertex), so the empty flag is one carry chain
  // deep; the first pixel two, its clip to 0 read from the smallest vertex's hi beside its
  // increment.
  localparam int HB = (P - F + 2 > PB + 2) ? P - F + 2 : PB + 2;  // signed bits of hi, t, the box
  function automatic logic [PB+HB:0] axis_box(input logic [3*P-1:0] v, input logic [PB-1:0] vpi);
    logic signed [HB-1:0] hi [3];
    logic signed [HB-1:0] t [3];
    logic [2:0] lo_lt, lo_gt, lo_eq;
    logic signed [P+1:0] vw;
    /* verilator lint_off UNUSEDSIGNAL */   // first's bits above PB (read only for a box)
    logic signed [HB-1:0] vp, hmin, tmax, first;
    /* verilator lint_on UNUSEDSIGNAL */
    logic lt01, lt02, lt12, gtmin, all_neg, unclipped_empty, past_end, first_neg;
    vp = HB'(vpi);
    for (int k = 0; k < 3; k++) begin
      vw = {{2{v[k*P+P-1]}}, v[k*P +: P]};
      hi[k] = HB'(vw >>> F);
      lo_lt[k] = v[k*P +: F] < F'(1 << (F - 1));
      lo_eq[k] = v[k*P +: F] == F'(1 << (F - 1));
      lo_gt[k] = !lo_lt[k] && !lo_eq[k];
      t[k] = hi[k] - HB'(lo_lt[k]);
    end
    lt01 = $signed(v[0 +: P]) < $signed(v[P +: P]);
    lt02 = $signed(v[0 +: P]) < $signed(v[2*P +: P]);
    lt12 = $signed(v[P +: P]) < $signed(v[2*P +: P]);
    if (lt01 && lt02) begin
      hmin = hi[0];  gtmin = lo_gt[0];
    end else if (!lt01 && lt12) begin
      hmin = hi[1];  gtmin = lo_gt[1];
    end else begin
      hmin = hi[2];  gtmin = lo_gt[2];
    end
    if (!lt01 && !lt02) tmax = t[0];
    else if (lt01 && !lt12) tmax = t[1];
    else tmax = t[2];
    first = hmin + HB'(gtmin);
    // first < 0 (clipped to 0) from hmin, beside the increment: hmin < 0 but for hmin = -1, gt
    first_neg = hmin[HB-1] && !(hmin == '1 && gtmin);
    all_neg = t[0][HB-1] && t[1][HB-1] && t[2][HB-1];
    unclipped_empty = !(|lo_eq) && t[0] == t[1] && t[1] == t[2];
    // first > vp: the smallest vertex's first pixel hi + gt is past vp, so every vertex's is (a
    // compare per vertex, beside the vertex compares instead of after them)
    past_end = 1'b1;
    for (int k = 0; k < 3; k++) past_end = past_end && (lo_gt[k] ? hi[k] >= vp : hi[k] > vp);
    // The last pixel unclipped (tmax): B clips it to the viewport at the take.
    axis_box = {all_neg || past_end || unclipped_empty, PB'(first_neg ? '0 : first), tmax};
  endfunction

  logic b_empty_q;
  logic [PB-1:0] b_fx_q, b_fy_q;
  logic signed [HB-1:0] b_tx_q, b_ty_q;

  assign b_retire = b_full_q && b_empty_q;
  assign b_take   = b_full_q && !b_empty_q && c_free;
  assign tri_ready_o = rst_ni && (!b_full_q || b_retire || b_take);  // low in reset (docs/port.md)
  assign box_retire_o = b_retire;
  assign box_retire_tag_o = b_tag_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) b_full_q <= 1'b0;
    else if (tri_valid_i && tri_ready_o) b_full_q <= 1'b1;
    else if (b_retire || b_take) b_full_q <= 1'b0;
  end
  // The box is formed inside the accept branch (the same logic): a Verilated model then evaluates
  // it in accept cycles only, not on every change of the port's inputs.
  always_ff @(posedge clk_i) begin
    if (tri_valid_i && tri_ready_o) begin
      logic [PB+HB:0] xbox, ybox;   // {empty, first, last} per axis
      xbox = axis_box(tri_vx_i, cfg_vp_xmax_i);
      ybox = axis_box(tri_vy_i, cfg_vp_ymax_i);
      b_tag_q <= tri_tag_i;  b_vx_q <= tri_vx_i;  b_vy_q <= tri_vy_i;
      b_empty_q <= xbox[PB+HB] || ybox[PB+HB];
      {b_fx_q, b_tx_q} <= xbox[PB+HB-1:0];
      {b_fy_q, b_ty_q} <= ybox[PB+HB-1:0];
    end
  end

  // The edges' A, B and bias from B's vertices (edge k from vertex k to vertex k + 1, as the
  // set-up forms them: A = y_k - y_k+1, B = x_k+1 - x_k; the top-left rule's bias is 1 unless
  // A > 0, or A = 0 and B > 0), registered into C. The port's tri_a_i, tri_b_i and tri_bias_i
  // are read only by the assertion below (and tri_bias_i by E2Sum): the unit needs the vertices.
  function automatic logic [6*CB+2:0] edge_coefs(input logic [3*P-1:0] vx,
                                                  input logic [3*P-1:0] vy);
    logic [3*CB-1:0] ca, cb;
    logic [2:0] cbias;
    for (int k = 0; k < 3; k++) begin
      logic signed [CB-1:0] ak, bk;
      logic az, bz;
      ak = CB'($signed(vy[k*P +: P])) - CB'($signed(vy[((k+1)%3)*P +: P]));
      bk = CB'($signed(vx[((k+1)%3)*P +: P])) - CB'($signed(vx[k*P +: P]));
      az = vy[k*P +: P] == vy[((k+1)%3)*P +: P];
      bz = vx[k*P +: P] == vx[((k+1)%3)*P +: P];
      ca[k*CB +: CB] = ak;
      cb[k*CB +: CB] = bk;
      cbias[k] = !((!ak[CB-1] && !az) || (az && !bk[CB-1] && !bz));
    end
    edge_coefs = {ca, cb, cbias};
  endfunction
  logic [3*CB-1:0] b_a, b_b;
  logic [3*(CB+1)-1:0] b_p;   // A + B per edge: the corner unit's multiplicand, the 2x2 test's step
  logic [2:0] b_bias;
  logic [6*CB+2:0] b_coefs;   // one vector: a concatenation on the left is one call per part
  assign b_coefs = edge_coefs(b_vx_q, b_vy_q);
  assign {b_a, b_b, b_bias} = b_coefs;
  for (genvar k = 0; k < 3; k++) begin : g_p
    assign b_p[k*(CB+1) +: CB+1] = (CB+1)'($signed(b_a[k*CB +: CB])) +
                                   (CB+1)'($signed(b_b[k*CB +: CB]));
  end

  // ---------------------------------------------------------------- C: corner values
  logic c_full_q;
  logic [TB-1:0] c_tag_q;
  logic [PB-1:0] c_x0_q, c_y0_q;
  logic [BB-1:0] c_xmax_q, c_ymax_q;
  logic [3*P-1:0] c_vx_q, c_vy_q;
  logic [3*CB-1:0] c_a_q, c_b_q;
  logic [3*(CB+1)-1:0] c_p_q;
  logic [2:0] c_bias_q;
  logic c_tiny, c_ready, c_move, l_free;
  logic [3*EB-1:0] el, e_lane;   // el: E_L for the 2x2 test; e_lane: each lane's column value
  logic [2:0] e_far, e_fneg;     // E_L far from 0 and its sign (the 2x2 test's split form)

  // Per edge: its lane traverses x0 + Xmax (E_R), not x0 (E_L).
  logic [2:0] c_right;
  for (genvar k = 0; k < 3; k++) begin : g_right
    assign c_right[k] = trirast_pkg::lane_reads_right(c_a_q[k*CB +: CB], c_b_q[k*CB +: CB]);
  end

  assign c_free = !c_full_q || c_move;
  assign c_move = c_full_q && c_ready && l_free;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) c_full_q <= 1'b0;
    else if (b_take) c_full_q <= 1'b1;
    else if (c_move) c_full_q <= 1'b0;
  end
  // C's register. With the digit-serial unit (its multiplicands registered at the first start)
  // the fields below are read only when C's values are ready or at the corner unit's second
  // start, both at least two cycles after the take (run 1 starts in the take cycle and has at
  // least one digit; CRamReadLate_A): there (CRam) they are held in block RAM
  // (trirast_improved2_stage_ram), the rest in flip-flops.
  localparam bit UseCRam = CRam && CornerForm != 0;
  // C's x0, y0: read by the products (CornerForm 0) and copied to L without the job ring only.
  localparam bit CXY = CornerForm == 0 || !JobRing;
  localparam int CW = TB + (CXY ? 2 * PB : 0) + 2 * BB + 6 * CB + 3 * (CB + 1);
  logic [CW-1:0] c_d, c_q;
  logic [BB-1:0] b_xmax, b_ymax;
  // The box's last pixels clipped to the viewport (a box that is not empty has 0 <= t, and
  // first <= the clipped last), then Xmax, Ymax: at the take, from B's registers.
  logic [PB-1:0] b_lx, b_ly;
  assign b_lx = (b_tx_q > HB'(cfg_vp_xmax_i)) ? cfg_vp_xmax_i : PB'(b_tx_q);
  assign b_ly = (b_ty_q > HB'(cfg_vp_ymax_i)) ? cfg_vp_ymax_i : PB'(b_ty_q);
  assign b_xmax = BB'(b_lx - b_fx_q);
  assign b_ymax = BB'(b_ly - b_fy_q);
  if (CXY) begin : g_cxy
    assign c_d = {b_tag_q, b_fx_q, b_fy_q, b_xmax, b_ymax, b_a, b_b, b_p};
    assign {c_tag_q, c_x0_q, c_y0_q, c_xmax_q, c_ymax_q, c_a_q, c_b_q, c_p_q} = c_q;
  end else begin : g_cnoxy
    assign c_d = {b_tag_q, b_xmax, b_ymax, b_a, b_b, b_p};
    assign {c_tag_q, c_xmax_q, c_ymax_q, c_a_q, c_b_q, c_p_q} = c_q;
    assign {c_x0_q, c_y0_q} = '0;   // not read
  end
  if (UseCRam) begin : g_cram
    trirast_improved2_stage_ram #(.Bits (CW)) u_cram (
      .clk_i (clk_i), .rst_ni (rst_ni), .we_i (b_take), .d_i (c_d), .q_o (c_q));
  end else begin : g_creg
    always_ff @(posedge clk_i) begin
      if (b_take) c_q <= c_d;
    end
  end
  // The tiny flag in a flip-flop of its own, formed at the take (the move decisions read it, and
  // C's block-RAM fields come late in the cycle).
  logic c_tiny_q;
  assign c_tiny = c_tiny_q;
  always_ff @(posedge clk_i) begin
    if (b_take) begin
      c_tiny_q <= (b_xmax <= BB'(1)) && (b_ymax <= BB'(1));
      c_vx_q   <= b_vx_q;
      c_vy_q   <= b_vy_q;
      c_bias_q <= b_bias;
    end
  end

  if (CornerForm == 0) begin : g_mul
    // The values in one (combinational) step from the products: E_L for a tiny box (the 2x2
    // test), else each edge's at the column its lane reads (E_R at x0 + Xmax when c_right).
    trirast_improved2_corner_products u_corner (
      .vx_i (c_vx_q), .vy_i (c_vy_q), .a_i (c_a_q), .b_i (c_b_q), .bias_i (c_bias_q),
      .x0_i (c_x0_q), .x1_i (c_x0_q + PB'(c_xmax_q)), .x1sel_i (c_tiny ? 3'b000 : c_right),
      .y0_i (c_y0_q), .el_o (el));
    assign e_lane = el;
    for (genvar k = 0; k < 3; k++) begin : g_far
      logic [EB-F-CB-3:0] top;   // E's bits F + CB + 2 and up: far means |E| >= 2^(F+CB+2)
      assign top = el[k*EB + F + CB + 2 +: EB - F - CB - 2];
      assign e_far[k]  = !((&top) || !(|top));
      assign e_fneg[k] = el[k*EB + EB - 1];
    end
    assign c_ready = 1'b1;
  end else begin : g_msb
    // Digit-serial: run 1 forms E_L at x0; it starts in the cycle the triangle moves from B to C
    // (its operands cx0 - vx, cy0 - vy from B's box and vertices, its multiplicands from A, B
    // formed from B's vertices), and C's bias enters its output. A box for the
    // lanes then runs again at x1 = x0 + Xmax (its x operands from run 1's, held in the unit, and
    // C's Xmax), for the edges whose lane reads E_R only (c_right): the others' accumulators hold
    // E_L, so the lanes load the accumulators.
    logic start2_q, run_q, second_q, busy, start, done;
    logic [3*EB-1:0] acc;
    assign start = b_take || start2_q;   // exclusive: C holds a triangle during run 2
    // A, B are read at the first start only, from B (the unit keeps A + B and A - B).
    trirast_corner_serial #(.DigitBits (4)) u_corner (
      .clk_i (clk_i), .rst_ni (rst_ni), .start_i (start), .second_i (start2_q),
      .run_i (start2_q ? c_right : 3'b111),
      .vx_i (b_vx_q), .vy_i (b_vy_q), .a_i (b_a), .b_i (b_b), .p_i (b_p), .bias_i (c_bias_q),
      .x0_i (b_fx_q), .y0_i (b_fy_q), .xmax_i (c_xmax_q), .busy_o (busy), .el_o (acc),
      .far_o (e_far), .fneg_o (e_fneg));
    assign done = run_q && !start2_q && !busy;   // the current run's result is in acc
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        start2_q <= 1'b0;  run_q <= 1'b0;  second_q <= 1'b0;
      end else begin
        start2_q <= 1'b0;
        if (b_take) begin
          run_q <= 1'b1;  second_q <= 1'b0;
        end else if (done && !second_q && !c_tiny) begin
          start2_q <= 1'b1;  second_q <= 1'b1;
        end else if (c_move) begin
          run_q <= 1'b0;
        end
      end
    end
    // The 2x2 test's result is used only for a tiny box, which moves after run 1 (E_L in every
    // accumulator); the lanes load after run 2.
    assign el     = acc;
    assign e_lane = acc;
    // C's block-RAM fields are read two cycles after the take at the earliest (trirast_improved2_stage_ram).
    `ASSERT_IMPLIES(CRamReadLate_A, UseCRam && $past(b_take), !(c_full_q && c_ready) && !start2_q,
            clk_i, !rst_ni)
    assign c_ready = done && (second_q || c_tiny);
    // Cover points (docs/coverage.md): run 1 (E_L at x0) and run 2 (a lane job's E_R) under way.
    `COVER(CornerRun1_C, run_q && busy && !second_q, clk_i, !rst_ni)
    `COVER(CornerRun2_C, run_q && (busy || start2_q) && second_q, clk_i, !rst_ni)
  end

  // The direct 2x2 test (box-relative: x0 = y0 = 0). TestHi: E_L + A*u (u = 2^F) >= 0 exactly
  // when floor(E_L / u) + A >= 0, so the test runs on E_L's bits above F and on A, B.
  localparam int TW = TestHi ? EB - F : EB;
  logic [3*TW-1:0] t_el, a_step, b_step, ab_step;
  for (genvar k = 0; k < 3; k++) begin : g_step
    if (TestHi) begin : g_hi
      assign t_el[k*TW +: TW]   = el[k*EB + F +: TW];
      assign a_step[k*TW +: TW] = TW'($signed(c_a_q[k*CB +: CB]));
      assign b_step[k*TW +: TW] = TW'($signed(c_b_q[k*CB +: CB]));
      assign ab_step[k*TW +: TW] = TW'($signed(c_p_q[k*(CB+1) +: CB+1]));
      logic unused_lo;
      assign unused_lo = ^el[k*EB +: F];   // below the test's sign (floor)
    end else begin : g_full
      assign t_el[k*TW +: TW]   = el[k*EB +: EB];
      assign a_step[k*TW +: TW] = EB'($signed(c_a_q[k*CB +: CB])) <<< F;
      assign b_step[k*TW +: TW] = EB'($signed(c_b_q[k*CB +: CB])) <<< F;
      assign ab_step[k*TW +: TW] = EB'($signed(c_p_q[k*(CB+1) +: CB+1])) <<< F;
    end
  end
  logic [1:0] t_valid;
  logic [2*PB-1:0] t_xb;
  logic [2*(PB+1)-1:0] t_xe;
  /* verilator lint_off PINCONNECTEMPTY */
  trirast_improved2_direct_test_2x2 #(.W (TW), .SW (TestHi ? CB : CB + F)) u_box2x2 (
    .el_i (t_el), .a_i (a_step), .b_i (b_step), .ab_i (ab_step), .far_i (e_far),
    .fneg_i (e_fneg), .xmax_i (c_xmax_q[0]), .ymax_i (c_ymax_q[0]),
    .x0_i (PB'(0)), .y0_i (PB'(0)), .valid_o (t_valid), .y_o (), .xb_o (t_xb), .xe_o (t_xe));
  /* verilator lint_on PINCONNECTEMPTY */

  // ---------------------------------------------------------------- L: job register, lanes
  logic l_full_q, l_tiny_q;
  logic [TB-1:0] l_tag_q;
  logic [BB-1:0] l_xmax_q, l_ymax_q;
  logic [1:0] l_tvalid_q, l_tbegin_q, l_tend1_q;
  logic lane_load, hand_valid, hand_ready;
  logic [2:0] lane_done;

  assign l_free    = !l_full_q || (hand_valid && hand_ready);
  assign lane_load = c_move && !c_tiny;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) l_full_q <= 1'b0;
    else if (c_move) l_full_q <= 1'b1;
    else if (hand_valid && hand_ready) l_full_q <= 1'b0;
  end
  always_ff @(posedge clk_i) begin
    if (c_move) begin
      l_tag_q    <= c_tag_q;
      l_xmax_q   <= c_xmax_q;
      l_ymax_q   <= c_ymax_q;
      l_tiny_q   <= c_tiny;
      l_tvalid_q <= t_valid;
      l_tbegin_q <= {t_xb[PB], t_xb[0]};
      l_tend1_q  <= {t_xe[PB+2], t_xe[1]};   // x_end is 1 or 2: bit 1 says 2
    end
  end

  `TRIRAST_IMPROVED_HANDOFF_EDGES_SIGNALS(hand_)
  logic [3*RB-1:0] hand_entry_e;
  logic [3*(BB+1)-1:0] hand_entry_b;
  // The three redesigned lanes, side by side on C's corner values; their box: the lanes read
  // Xmax, Ymax from the cycle after the load on, and the job register L holds them (in the load
  // cycle L may still hold the job being handed off, whose entry X' reads its own Xmax); the
  // iteration count m = bits(Xmax) + 1 (adaptive) is registered at the load from C.
  localparam int IterBits = $clog2(QB + 1);
  function automatic logic [IterBits-1:0] bits_plus_one(input logic [BB-1:0] v);
    logic [IterBits-1:0] nb;
    nb = IterBits'(1);
    for (int i = 0; i < BB; i++) begin
      if (v[i]) nb = IterBits'(i + 1);
    end
    bits_plus_one = nb + 1'b1;
  endfunction
  logic [IterBits-1:0] m_q;
  always_ff @(posedge clk_i) begin
    if (lane_load) m_q <= bits_plus_one(c_xmax_q);
  end
  for (genvar k = 0; k < 3; k++) begin : g_edge
    /* verilator lint_off PINCONNECTEMPTY */
    trirast_improved2_edge_lane #(.FixedM (LaneFixedM), .PreIter (LanePreIter)) u_lane (
      .clk_i (clk_i), .rst_ni (rst_ni), .m_i (m_q), .load_i (lane_load),
      .a_i (c_a_q[k*CB +: CB]), .b_i (c_b_q[k*CB +: CB]), .e_i (e_lane[k*EB +: EB]),
      .xmax_i (l_xmax_q), .ymax_i (l_ymax_q),
      .busy_o (lane_busy_o[k]), .done_o (lane_done[k]),
      .div_o (lane_div_o[k]), .step_o (lane_step_o[k]),
      .horiz_o (), .mirror_o (hand_mirror[k]), .dir_down_o (hand_dir_down[k]),
      .d_o (hand_d[k*SB +: SB]), .qs_o (hand_qs[k*QB +: QB]), .rs_o (hand_rs[k*RB +: RB]),
      .ssat_o (hand_ssat[k]), .enters_o (hand_enters[k]), .j_entry_o (hand_j_entry[k*WB +: WB]),
      .entry_state_o (hand_entry_state[2*k +: 2]), .entry_x_o (hand_entry_x[k*XB +: XB]),
      .entry_b_o (hand_entry_b[k*(BB+1) +: BB+1]),
      .entry_e_o (hand_entry_e[k*RB +: RB]));
    /* verilator lint_on PINCONNECTEMPTY */
  end

  assign hand_valid = l_full_q && (l_tiny_q || (&lane_done));

  // ---------------------------------------------------------------- W: walk stage, FIFO
  // The walk stage's tag and box: JobRing, read from a ring of the jobs' fields written at C's
  // take (every job taken into C reaches the walk stage, in order; C, L and W hold at most three
  // of them, so four words), from the cycle after the hand-off (the walk stage reads them from
  // then on: HandHeld); else copied from L at the hand-off, with L's x0, y0 copied from C.
  localparam int JW = TB + 2 * PB + 2 * BB;
  logic [JW-1:0] w_job;
  if (JobRing) begin : g_ring
    trirast_improved2_job_ring #(.Bits (JW), .Words (4)) u_ring (
      .clk_i (clk_i), .rst_ni (rst_ni), .we_i (b_take),
      .d_i ({b_tag_q, b_fx_q, b_fy_q, b_xmax, b_ymax}), .next_i (hand_valid && hand_ready),
      .q_o (w_job));
    // The ring shows the job just handed off: the tag and box L held.
    `ASSERT_IMPLIES(JobRingInOrder_A, $past(hand_valid && hand_ready),
                   {w_job[JW-1 -: TB], w_job[2*BB-1:0]} == $past({l_tag_q, l_xmax_q, l_ymax_q}),
                   clk_i, !rst_ni)
  end else begin : g_lcopy
    logic [PB-1:0] l_x0_q, l_y0_q;
    always_ff @(posedge clk_i) begin
      if (c_move) begin
        l_x0_q <= c_x0_q;
        l_y0_q <= c_y0_q;
      end
    end
    assign w_job = {l_tag_q, l_x0_q, l_y0_q, l_xmax_q, l_ymax_q};
  end
  logic walk_busy;
  logic [TB+3*PB:0] span;
  trirast_improved2_walk_stage #(
    .FifoDepth (FifoDepth), .FifoRam (FifoRam), .WalkerCs (WalkerCs), .HandHeld (JobRing),
    .NumEndpoints (NumEndpoints)
  ) u_walk (
    .clk_i (clk_i), .rst_ni (rst_ni),
    .hand_valid_i (hand_valid), .hand_ready_o (hand_ready),
    .hand_tag_i (w_job[JW-1 -: TB]), .hand_x0_i (w_job[2*PB+2*BB-1 -: PB]),
    .hand_y0_i (w_job[PB+2*BB-1 -: PB]), .hand_xmax_i (w_job[2*BB-1 -: BB]),
    .hand_ymax_i (w_job[BB-1:0]),
    `TRIRAST_CONNECT_IMPROVED_HANDOFF_EDGES(_i),
    .hand_entry_b_i (hand_entry_b),
    .hand_entry_e_i (hand_entry_e),
    .hand_tiny_i (l_tiny_q), .hand_tiny_valid_i (l_tvalid_q),
    .hand_tiny_begin_i (l_tbegin_q), .hand_tiny_end1_i (l_tend1_q),
    .cfg_fifo_depth_i (cfg_fifo_depth_i), .cfg_endpoints_i (cfg_endpoints_i),
    .span_ready_i (span_ready_i), .span_valid_o (span_valid_o), .span_o (span),
    .busy_o (walk_busy), .walk_o (walk_busy_o), .stall_o (walk_stall_o), .last_o (walk_last_o),
    .retire_o (walk_retire_o), .tag_o (walk_tag_o), .fifo_count_o (fifo_count_o));

  assign {span_tag_o, span_y_o, span_x_begin_o, span_x_end_o} = span;
  assign busy_o = b_full_q || c_full_q || l_full_q || walk_busy || span_valid_o;

  // Observation outputs.
  assign box_valid_o    = b_full_q;
  assign box_stall_o    = b_full_q && !b_retire && !b_take;
  assign box_tag_o      = b_tag_q;
  assign corner_valid_o = c_full_q;
  assign corner_stall_o = c_full_q && c_ready && !l_free;
  assign {job_valid_o, job_ready_o, job_tag_o} = {l_full_q, hand_valid, l_tag_q};
  `TRIRAST_ASSIGN_HANDOFF_OBSERVATION(l_xmax_q, l_ymax_q)

  // Protocol assumptions and invariants.
  `ASSERT(CfgFifoDepthInRange_A, cfg_fifo_depth_i >= CountBits'(1) &&
          32'(cfg_fifo_depth_i) <= FifoDepth, clk_i, !rst_ni)
  // N > 1: 1 <= n <= N and n <= DEPTH (a larger n would overflow the walk stage or the FIFO).
  `ASSERT(CfgEndpointsInRange_A, NumEndpoints == 1 || (cfg_endpoints_i >= 3'd1 &&
          32'(cfg_endpoints_i) <= NumEndpoints && 32'(cfg_fifo_depth_i) >= 32'(cfg_endpoints_i)),
          clk_i, !rst_ni)
  `ASSERT_INIT(NumEndpointsInRange_A, NumEndpoints >= 1 && NumEndpoints <= 4)
  `ASSERT_STABLE(TriDataStable_A, tri_valid_i && !tri_ready_o,
                 {tri_tag_i, tri_vx_i, tri_vy_i, tri_a_i, tri_b_i, tri_c_i, tri_bias_i},
                 clk_i, !rst_ni)
  `ASSERT_NEXT(TriValidHeld_A, tri_valid_i && !tri_ready_o, tri_valid_i, clk_i, !rst_ni)
  // A job is handed off only when every lane it loaded is done; a tiny job loads none.
  `ASSERT_IMPLIES(HandoffLanesDone_A, handoff_o && !l_tiny_q, &lane_done, clk_i, !rst_ni)
  `ASSERT_IMPLIES(LaneLoadIdle_A, lane_load, &lane_done, clk_i, !rst_ni)
  `ASSERT_KNOWN(HandshakesKnown_A, {tri_ready_o, box_retire_o, handoff_o, busy_o}, clk_i, !rst_ni)

  logic unused;
  assign unused = ^{tri_c_i, tri_a_i, tri_b_i, c_vx_q, c_vy_q, c_x0_q, c_y0_q};  // asserts, form 0

  // The triangle port's preconditions (docs/port.md, "Preconditions"; C is not read here, so
  // not checked), simulation only.
`ifndef SYNTHESIS  // simulation only: neither synthesis nor the formal flow (Yosys)
`ifndef FORMAL
  `TRIRAST_TRIANGLE_PORT_CHECK(1'b1, 1'b0, 1'b1, tri_a_i, tri_b_i, tri_c_i, tri_bias_i)
`endif  // FORMAL
`endif  // SYNTHESIS
  // Cover points (docs/coverage.md). The triangle port: waiting, taking a triangle, taking one in
  // two cycles in a row (the box stage passes or retires its triangle in the cycle it takes the
  // next). The box stage (B): an empty box retired, a box waiting for the corner stage. The
  // corner stage (C): a tiny box (at most 2 x 2) moving to L
  // with its 2x2 direct test, a lane job moving to L, a finished triangle waiting for L. The job
  // stage (L): a lane job waiting for its lanes, a job waiting for the walk stage. (The serial
  // corner form's runs: in g_msb.)
  `COVER(TriAccept_C, tri_valid_i && tri_ready_o, clk_i, !rst_ni)
  `COVER(TriPortStall_C, tri_valid_i && !tri_ready_o, clk_i, !rst_ni)
  `COVER(TriAcceptBackToBack_C, tri_valid_i && tri_ready_o && $past(tri_valid_i && tri_ready_o),
         clk_i, !rst_ni)
  `COVER(BoxEmptyRetired_C, b_retire, clk_i, !rst_ni)
  `COVER(BoxWaitsForCorner_C, box_stall_o, clk_i, !rst_ni)
  `COVER(CornerTinyToJob_C, c_move && c_tiny, clk_i, !rst_ni)
  `COVER(CornerLaneJobToJob_C, c_move && !c_tiny, clk_i, !rst_ni)
  `COVER(CornerWaitsForJob_C, c_full_q && c_ready && !l_free, clk_i, !rst_ni)
  `COVER(JobWaitsForLanes_C, l_full_q && !hand_valid, clk_i, !rst_ni)
  `COVER(JobWaitsForWalk_C, hand_valid && !hand_ready, clk_i, !rst_ni)
  // The span port (its FIFO is the walk stage's): a span waiting (valid, not ready), and ready
  // low for two cycles or more in a row.
  `COVER(SpanPortStall_C, span_valid_o && !span_ready_i, clk_i, !rst_ni)
  `COVER(SpanReadyLow2_C, !span_ready_i && !$past(span_ready_i), clk_i, !rst_ni)

endmodule
