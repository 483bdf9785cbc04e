// The half-space tile unit (top: trirast_halfspace_top), in dependency order: the package first.
// One path per line, relative to this list's folder (Verilator's -F rule); read as rtl/improved/trirast_improved.f is. Include dir: rtl/common/.
../common/trirast_pkg.sv
../common/trirast_port_pkg.sv
../common/trirast_triangle_port_check.sv
../common/trirast_box_stage.sv
../common/trirast_corner_serial.sv
../common/trirast_span_fifo_ram.sv
trirast_halfspace_setup_stage.sv
trirast_halfspace_stamp_tester.sv
trirast_halfspace_walk_decide.sv
trirast_halfspace_tile_walker.sv
trirast_halfspace_late_select.sv
trirast_halfspace_span_emitter.sv
trirast_halfspace_top.sv
