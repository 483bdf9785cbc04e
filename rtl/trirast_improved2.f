// The improved unit, second generation (top: trirast_improved2_top), in dependency order: the
// package first. One path per line, relative to rtl/; read by rtl/CMakeLists.txt (Verilator, lint,
// Yosys, Icarus), the Verilated builds (cmake/trirast_rtl_builds.cmake) and scripts/synth.sh.
// Include dir: rtl/ (trirast_assert.svh).
trirast_pkg.sv
trirast_corner_products.sv
trirast_corner_serial.sv
trirast_direct_test_2x2.sv
trirast_edge_lane2.sv
trirast_edge_walker2.sv
trirast_span_generator2.sv
trirast_span_fifo.sv
trirast_span_fifo_ram.sv
trirast_stage_ram.sv
trirast_job_ring.sv
trirast_walk_stage2.sv
trirast_improved2_top.sv
