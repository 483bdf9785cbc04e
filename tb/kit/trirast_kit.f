// The testbench kit (docs/port.md, "Testbench kit"): its modules, the bench top last. One path
// per line, relative to this list's folder (Verilator's -F rule). Give it together with the
// unit's rtl/UNIT/trirast_UNIT.f, the include dir rtl/common and the unit's define (TRIRAST_KIT_IMPROVED,
// TRIRAST_KIT_IMPROVED2, TRIRAST_KIT_TRAD or TRIRAST_KIT_HALFSPACE; tb/kit/run.sh gives them to
// Verilator --binary --timing and Icarus -g2012 alike).
trirast_kit_driver.sv
trirast_kit_downstream.sv
trirast_kit_monitor.sv
trirast_kit_scoreboard.sv
trirast_kit_bench.sv
