// The traditional-Bresenham unit (top: trirast_trad_top), in dependency order: the package
// first. One path per line, relative to rtl/; read by every flow as rtl/trirast_improved.f is.
trirast_pkg.sv
trirast_span_fifo.sv
trirast_span_port.sv
trirast_trad_quantizer.sv
trirast_trad_line_setup.sv
trirast_trad_setup_stage.sv
trirast_trad_walker.sv
trirast_trad_span_filler.sv
trirast_trad_walk_stage.sv
trirast_trad_top.sv
