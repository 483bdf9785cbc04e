// The improved-Bresenham unit (top: trirast_improved_top), in dependency order: the package first.
// One path per line, relative to this list's folder (Verilator's -F rule); read by rtl/CMakeLists.txt (Verilator, lint, Yosys),
// the Icarus testbench, the libFuzzer build and scripts/synth.sh. Include dir: rtl/common/
// (trirast_assert.svh, trirast_ports.svh).
../common/trirast_pkg.sv
../common/trirast_port_pkg.sv
../common/trirast_triangle_port_check.sv
trirast_improved_adder_divider.sv
trirast_improved_edge_lane.sv
trirast_improved_edge_normalizer.sv
../common/trirast_box_stage.sv
trirast_improved_edge_walker.sv
trirast_improved_span_generator.sv
../common/trirast_span_fifo.sv
../common/trirast_span_port.sv
trirast_improved_setup_stage.sv
trirast_improved_walk_stage.sv
trirast_improved_top.sv
