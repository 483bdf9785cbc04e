// The SystemC models as engines (docs/sc-model.md). Both units are elaborated once per process,
// the first time either engine runs; every run then goes through the same modules from the
// current SystemC time on (cycle numbers are relative to the run's start).
#pragma once
#include <memory>

#include "common/engine.hpp"

namespace trirast {

// The improved-Bresenham unit, timed (register as "improved-sc").
std::unique_ptr<Engine> make_improved_sc_engine();
// The second-generation improved unit, timed, N = 1 (register as "improved2-sc").
std::unique_ptr<Engine> make_improved2_sc_engine();
// The traditional-Bresenham unit, timed: the spans of make_trad_datapath_engine() plus cycles
// (register as "trad-sc").
std::unique_ptr<Engine> make_trad_sc_engine();
// The half-space tile unit, timed (register as "halfspace-sc"; docs/timing.md).
std::unique_ptr<Engine> make_halfspace_sc_engine();

}  // namespace trirast
