// The SystemC models as engines (docs/sc-model.md). Each unit's model registers itself here
// (its UNIT_sc.cpp); every registered unit is elaborated once per process, the first time any of
// them runs, and every run then goes through the same modules from the current SystemC time on
// (cycle numbers are relative to the run's start). The factories are each unit's own:
// make_UNIT_sc_engine() in model/UNIT/UNIT_sc.hpp.
#pragma once
#include <functional>
#include <memory>
#include <string>

#include "common/config.hpp"
#include "common/engine.hpp"

namespace trirast::sc {

class UnitScIf;

// A unit's SystemC model as the engine runs it.
struct ScUnit {
  std::string name;                                        // module name and trace scope
  std::function<std::unique_ptr<UnitScIf>()> elaborate;    // builds the unit's modules
  std::function<void(const RasterConfig&)> check_widths;   // throws WidthError; may be empty
};

// Registers a unit (at static initialization, once per unit); returns its handle for
// make_sc_engine.
int register_sc_unit(ScUnit unit);

// The engine that runs registered unit `unit`.
std::unique_ptr<Engine> make_sc_engine(int unit);

}  // namespace trirast::sc
