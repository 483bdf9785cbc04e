// The SystemC models as engines (docs/sc-model.md): the CLI's user of the units' components
// (sc_raster_unit.hpp). Each unit registers itself here (its UNIT_sc.cpp); the first run of any
// of them elaborates a platform of one instance of every registered unit, each with a producer
// (a TLM-2.0 initiator that sends the run's triangles) and a downstream channel (the run's
// --sink-stall), and every run then restarts its unit's stream at the current SystemC time and
// calls sc_start. A program with a platform of its own instantiates the components instead. The
// factories are each unit's own: make_UNIT_sc_engine() in model/UNIT/UNIT_sc.hpp.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <systemc>

#include "common/config.hpp"
#include "common/engine.hpp"

namespace trirast::sc {

class RasterUnitSc;

// A unit's SystemC model as the engine runs it.
struct ScUnit {
  std::string name;  // module name and trace scope
  // Builds the unit's component (name, configuration, clock period).
  std::function<std::unique_ptr<RasterUnitSc>(const char*, const RasterConfig&,
                                              const sc_core::sc_time&)>
      elaborate;
  std::function<void(const RasterConfig&)> check_widths;  // throws WidthError; may be empty
};

// Registers a unit (at static initialization, once per unit); returns its handle for
// make_sc_engine.
int register_sc_unit(ScUnit unit);

// The engine that runs registered unit `unit`.
std::unique_ptr<Engine> make_sc_engine(int unit);

// A new component of the registered unit called `unit` ("improved", "improved2", "trad",
// "halfspace"); null when there is none.
std::unique_ptr<RasterUnitSc> make_raster_unit_sc(const std::string& unit, const char* name,
                                                  const RasterConfig& cfg,
                                                  const sc_core::sc_time& period);

}  // namespace trirast::sc
