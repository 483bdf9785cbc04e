// The traditional-Bresenham unit (top: trirast_trad_top), in dependency order: the package
// first. One path per line, relative to this list's folder (Verilator's -F rule); read by every flow as rtl/improved/trirast_improved.f is.
../common/trirast_pkg.sv
../common/trirast_port_pkg.sv
../common/trirast_triangle_port_check.sv
../common/trirast_span_fifo.sv
../common/trirast_span_port.sv
trirast_trad_quantizer.sv
trirast_trad_line_setup.sv
trirast_trad_setup_stage.sv
trirast_trad_walker.sv
trirast_trad_span_filler.sv
trirast_trad_walk_stage.sv
trirast_trad_top.sv
