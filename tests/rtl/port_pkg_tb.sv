// The testbench of rtl/common/trirast_port_pkg.sv (ctest rtl_port_pkg_*, tests/rtl/port_pkg_check.sh):
// reads the triangles and the CLI setup's results that trirast_port_pkg_vectors wrote
// (tests/rtl/port_pkg_vectors.cpp; +vectors=FILE), forms each triangle with
// trirast_port_pkg::form_port_triangle, and compares every field: the degenerate flag; for a
// triangle setup accepts, the swap, the ordered vertices, A, B, C and the bias of every edge.
// Ends with "port_pkg_tb: PASS ..." or "port_pkg_tb: FAIL ..." (and $fatal). The same source runs
// under Icarus 11 and Verilator 5.006.
module port_pkg_tb;
  // Icarus 11 parses a package's task called as a statement only when imported (a package's
  // function it takes qualified, trirast_port_pkg::edge_a(...), in an expression).
  import trirast_port_pkg::form_port_triangle;
  localparam int P = trirast_pkg::VertexBits;
  localparam int CB = trirast_pkg::CoefBits;
  localparam int EB = trirast_pkg::EdgeBits;

  initial begin
    string path;
    int fd, n, p_file, cb_file, eb_file, s_file, count, degenerates, swaps, errors, got;
    logic [P-1:0] sx[3], sy[3], ex[3], ey[3];
    logic [CB-1:0] ea[3], eb[3];
    logic [EB-1:0] ec[3];
    logic [2:0] ebias;
    logic edeg, eswap;
    logic [3*P-1:0] px, py, vx, vy;
    logic [3*CB-1:0] a, b;
    logic [3*EB-1:0] c;
    logic [2:0] bias;
    logic deg, swap;
    if (!$value$plusargs("vectors=%s", path)) $fatal(1, "port_pkg_tb: no +vectors=FILE");
    fd = $fopen(path, "r");
    if (fd == 0) $fatal(1, "port_pkg_tb: %s: cannot read", path);
    got = $fscanf(fd, "%d %d %d %d %d\n", p_file, cb_file, eb_file, s_file, count);
    if (got != 5 || p_file != P || cb_file != CB || eb_file != EB ||
        s_file != trirast_pkg::SubpixelBits)
      $fatal(1, "port_pkg_tb: %s: line 1: widths %0d %0d %0d S %0d, the package's %0d %0d %0d S %0d",
             path, p_file, cb_file, eb_file, s_file, P, CB, EB, trirast_pkg::SubpixelBits);
    errors = 0;
    degenerates = 0;
    swaps = 0;
    for (n = 0; n < count; n++) begin
      got = $fscanf(fd, "%h %h %h %h %h %h %h %h", sx[0], sx[1], sx[2], sy[0], sy[1], sy[2],
                    edeg, eswap);
      got = got + $fscanf(fd, "%h %h %h %h %h %h", ex[0], ex[1], ex[2], ey[0], ey[1], ey[2]);
      got = got + $fscanf(fd, "%h %h %h %h %h %h", ea[0], ea[1], ea[2], eb[0], eb[1], eb[2]);
      got = got + $fscanf(fd, "%h %h %h %h\n", ec[0], ec[1], ec[2], ebias);
      if (got != 24) $fatal(1, "port_pkg_tb: %s: line %0d: %0d fields, not 24", path, n + 2, got);
      px = {sx[2], sx[1], sx[0]};
      py = {sy[2], sy[1], sy[0]};
      form_port_triangle(px, py, deg, swap, vx, vy, a, b, c, bias);
      degenerates += int'(edeg);
      swaps += int'(eswap);
      if (deg !== edeg) begin
        errors++;
        if (errors <= 10) $display("port_pkg_tb: triangle %0d: degenerate %b, setup %b", n, deg, edeg);
      end else if (!edeg) begin
        if (swap !== eswap || vx !== {ex[2], ex[1], ex[0]} || vy !== {ey[2], ey[1], ey[0]} ||
            a !== {ea[2], ea[1], ea[0]} || b !== {eb[2], eb[1], eb[0]} ||
            c !== {ec[2], ec[1], ec[0]} || bias !== ebias) begin
          errors++;
          if (errors <= 10)
            $display("port_pkg_tb: triangle %0d: swapped %b/%b vx %h/%h vy %h/%h a %h/%h b %h/%h c %h/%h bias %b/%b (package/setup)",
                     n, swap, eswap, vx, {ex[2], ex[1], ex[0]}, vy, {ey[2], ey[1], ey[0]},
                     a, {ea[2], ea[1], ea[0]}, b, {eb[2], eb[1], eb[0]}, c, {ec[2], ec[1], ec[0]},
                     bias, ebias);
        end
      end
    end
    $fclose(fd);
    if (errors != 0 || degenerates == 0 || swaps == 0 || swaps == count - degenerates)
      $fatal(1, "port_pkg_tb: FAIL %0d of %0d triangles differ from setup (%0d degenerate, %0d swapped)",
             errors, count, degenerates, swaps);
    $display("port_pkg_tb: PASS %0d triangles equal setup's (%0d degenerate, %0d swapped)", count,
             degenerates, swaps);
    $finish;
  end
endmodule
