// Testbench kit (docs/port.md, "Testbench kit"): the triangle driver. It reads the stimulus
// (+kit_dir=DIR: DIR/tris.hex, one triangle port value per line, written by trirast raster
// --vectors) and offers the triangles in order on a valid/ready port: triangle p is on the port
// (tri_valid high, tri_data = line p) from the cycle after triangle p - 1's handshake, or, with
// +gap=N, N cycles later. A handshake is a rising edge with tri_valid and tri_ready high.
// Plain modules, tasks and $readmemh: Icarus 11 and Verilator 5 read it alike.
module trirast_kit_driver #(
  parameter int TriBits = 1,   // one triangle port value (tris.hex's width)
  parameter int MaxTris = 1    // tris.hex lines it holds
) (
  input  logic               clk,
  input  logic               rst_n,
  input  logic               tri_ready,
  output logic               tri_valid,
  output logic [TriBits-1:0] tri_data,
  output logic [31:0]        next_tri,   // the triangle on the port (ntris once all went in)
  output logic               all_sent    // every triangle was accepted
);
  logic [TriBits-1:0] tris [MaxTris];
  int ntris, gap;
  logic [31:0] wait_q;  // idle cycles left before the next triangle is offered
  string dir;

  initial begin
    if (!$value$plusargs("kit_dir=%s", dir)) $fatal(1, "kit driver: +kit_dir=DIR missing");
    if (!$value$plusargs("ntris=%d", ntris)) $fatal(1, "kit driver: +ntris missing");
    if (!$value$plusargs("gap=%d", gap)) gap = 0;
    if (ntris < 0 || ntris > MaxTris)
      $fatal(1, "kit driver: +ntris=%0d exceeds the bench's MaxTris %0d", ntris, MaxTris);
    if (ntris > 0) $readmemh({dir, "/tris.hex"}, tris, 0, ntris - 1);
  end

  assign all_sent = next_tri >= 32'(ntris);
  assign tri_valid = !all_sent && wait_q == 0;
  assign tri_data = tri_valid ? tris[next_tri] : '0;

  always @(posedge clk or negedge rst_n) begin
    if (!rst_n) begin
      next_tri <= 0;
      wait_q <= 0;
    end else if (tri_valid && tri_ready) begin
      next_tri <= next_tri + 1;
      wait_q <= 32'(gap);
    end else if (wait_q != 0) begin
      wait_q <= wait_q - 1;
    end
  end
endmodule
