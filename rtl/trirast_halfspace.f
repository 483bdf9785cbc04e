// The half-space tile unit (top: trirast_hs_top), in dependency order: the package first.
// One path per line, relative to rtl/; read as rtl/trirast_improved.f is. Include dir: rtl/.
trirast_pkg.sv
trirast_interface.sv
trirast_span_fifo.sv
trirast_span_port.sv
trirast_hs_setup_stage.sv
trirast_hs_stamp_tester.sv
trirast_hs_tile_walker.sv
trirast_hs_span_emitter.sv
trirast_hs_top.sv
