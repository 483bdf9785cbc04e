// Formal harness of the improved2 unit's two corner forms against each other (docs/formal.md, "The
// corner unit's two forms"): rtl/common/trirast_corner_serial.sv (CornerForm 1,
// digit-serial) against trirast_improved2_corner_products.sv (CornerForm 0, products), on the
// same triangle. Bounded model checking from reset (reset in the first cycle only). The serial
// unit is driven as trirast_improved2_top drives it: a first start (all three edges, the vertices,
// A, B, A + B, x0, y0) when it is not busy, then optionally a second start (x1 = x0 + Xmax for the
// edges of a free mask) when it is not busy and the last start was a first one. A, B and A + B
// are the vertices' (A_k = y_k - y_k+1, B_k = x_k+1 - x_k), as the serial form requires; the box
// fits the pixel range (x0 + Xmax < 2^PixBits); vertices, x0, y0, Xmax and the bias are free.
// The products unit is given the triangle of the last first start, and per edge x1 = x0 + Xmax
// when the edge's last run was a second run.
//   FormsAgree  when the serial unit is not busy after a start, its el_o equals the products'
//   (unlabelled, one per edge: a loop) far_o: |E| >= 2^(F+CoefBits) and fneg_o is E < 0; not far: |E| < 2^(F+CoefBits+3)
//               (the 2x2 test's split-form contract, E = el_o)
module formal_corner_forms (
  input logic clk_i
);
  localparam int P = trirast_pkg::VertexBits;
  localparam int F = trirast_pkg::FracBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;
  localparam int PB = trirast_pkg::PixBits;
  localparam int BB = trirast_pkg::BoxBits;

  (* anyseq *) logic rst_ni, start_i, second_i;
  (* anyseq *) logic [2:0] run_i, bias_i;
  (* anyseq *) logic [3*P-1:0] vx_i, vy_i;
  (* anyseq *) logic [PB-1:0] x0_i, y0_i;
  (* anyseq *) logic [BB-1:0] xmax_i;

  // A, B, A + B from the vertices (trirast_improved2_top's b_a, b_b, b_p)
  logic [3*CB-1:0] a, b;
  logic [3*(CB+1)-1:0] p;
  always @* begin
    for (int k = 0; k < 3; k++) begin
      a[k*CB +: CB] = CB'($signed(vy_i[k*P +: P])) - CB'($signed(vy_i[((k+1)%3)*P +: P]));
      b[k*CB +: CB] = CB'($signed(vx_i[((k+1)%3)*P +: P])) - CB'($signed(vx_i[k*P +: P]));
      p[k*(CB+1) +: CB+1] = (CB+1)'($signed(a[k*CB +: CB])) + (CB+1)'($signed(b[k*CB +: CB]));
    end
  end

  logic busy_o;
  logic [3*EB-1:0] el_o;
  logic [2:0] far_o, fneg_o;
  trirast_corner_serial #(.DigitBits (4)) dut (
    .clk_i (clk_i), .rst_ni (rst_ni), .start_i (start_i), .second_i (second_i), .run_i (run_i),
    .vx_i (vx_i), .vy_i (vy_i), .a_i (a), .b_i (b), .p_i (p), .bias_i (bias_i), .x0_i (x0_i),
    .y0_i (y0_i), .xmax_i (xmax_i), .busy_o (busy_o), .el_o (el_o), .far_o (far_o),
    .fneg_o (fneg_o));

  // ---- the environment: the triangle of the last first start, the edges of the last run ----
  logic f_first_q = 1'b1;
  logic f_started_q, f_last_first_q;
  logic [3*P-1:0] g_vx_q, g_vy_q;
  logic [3*CB-1:0] g_a_q, g_b_q;
  logic [PB-1:0] g_x0_q, g_y0_q;
  logic [BB-1:0] g_xmax_q;
  logic [2:0] g_sel_q;
  always @(posedge clk_i) begin
    f_first_q <= 1'b0;
    if (!rst_ni) begin
      f_started_q <= 1'b0;
      f_last_first_q <= 1'b0;
    end else if (start_i) begin
      f_started_q <= 1'b1;
      f_last_first_q <= !second_i;
      if (!second_i) begin
        {g_vx_q, g_vy_q, g_a_q, g_b_q, g_x0_q, g_y0_q} <= {vx_i, vy_i, a, b, x0_i, y0_i};
        g_sel_q <= 3'b000;
      end else begin
        g_xmax_q <= xmax_i;
        g_sel_q <= run_i;
      end
    end
  end
  always @* begin
    if (f_first_q) assume (!rst_ni);
    else assume (rst_ni);
    if (start_i) assume (!busy_o && (second_i ? f_last_first_q : run_i == 3'b111));
    if (start_i && second_i) assume (32'(g_x0_q) + 32'(xmax_i) < (32'(1) << PB));
  end

  logic [3*EB-1:0] f_el;
  trirast_improved2_corner_products u_ref (
    .vx_i (g_vx_q), .vy_i (g_vy_q), .a_i (g_a_q), .b_i (g_b_q), .bias_i (bias_i), .x0_i (g_x0_q),
    .x1_i (g_x0_q + PB'(g_xmax_q)), .x1sel_i (g_sel_q), .y0_i (g_y0_q), .el_o (f_el));

  // ---- the properties ----
  always @* begin
    if (rst_ni && f_started_q && !busy_o) begin
      FormsAgree: assert (el_o == f_el);
      for (int k = 0; k < 3; k++) begin
        logic signed [EB-1:0] e;
        logic [EB:0] mag;
        e = $signed(f_el[k*EB +: EB]);
        mag = e < 0 ? -((EB+1)'(e)) : (EB+1)'(e);   // -(W'(x)): Yosys 0.23 misreads -W'(x)
        if (far_o[k]) assert (mag >= ((EB+1)'(1) << (F + CB)) && fneg_o[k] == (e < 0));
        else assert (mag < ((EB+1)'(1) << (F + CB + 3)));
      end
    end
  end

  // ---- reachability (yosys-smtbmc -c): a first run's result, a second run's ----
  always @* begin
    if (rst_ni && f_started_q && !busy_o) begin
      CoverFirst: cover (f_last_first_q);
      CoverSecond: cover (!f_last_first_q && g_sel_q == 3'b101);
    end
  end
endmodule
