// The improved unit, second generation (top: trirast_improved2_top), in dependency order: the
// package first. One path per line, relative to this list's folder (Verilator's -F rule); read by rtl/CMakeLists.txt (Verilator, lint,
// Yosys, Icarus), the Verilated builds (cmake/trirast_rtl_builds.cmake) and scripts/synth.sh.
// Include dir: rtl/common/ (trirast_assert.svh, trirast_ports.svh).
../common/trirast_pkg.sv
../common/trirast_port_pkg.sv
../common/trirast_triangle_port_check.sv
trirast_improved2_corner_products.sv
../common/trirast_corner_serial.sv
trirast_improved2_direct_test_2x2.sv
trirast_improved2_edge_lane.sv
trirast_improved2_edge_walker.sv
trirast_improved2_span_generator.sv
../common/trirast_span_fifo.sv
../common/trirast_span_fifo_ram.sv
trirast_improved2_stage_ram.sv
trirast_improved2_job_ring.sv
trirast_improved2_walk_stage.sv
trirast_improved2_top.sv
