// The improved-Bresenham unit (top: trirast_top), in dependency order: the package first.
// One path per line, relative to rtl/; read by rtl/CMakeLists.txt (Verilator, lint, Yosys),
// the Icarus testbench, the libFuzzer build and scripts/synth.sh. Include dir: rtl/
// (trirast_assert.svh).
trirast_pkg.sv
trirast_adder_divider.sv
trirast_edge_lane.sv
trirast_edge_normalizer.sv
trirast_interface.sv
trirast_edge_walker.sv
trirast_span_generator.sv
trirast_span_fifo.sv
trirast_span_port.sv
trirast_setup_stage.sv
trirast_walk_stage.sv
trirast_top.sv
