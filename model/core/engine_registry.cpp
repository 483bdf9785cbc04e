// The list of engines. Adding an engine: declare its factory here and add one line below.
#include "core/engine.hpp"

namespace trirast {

std::unique_ptr<Engine> make_golden_engine();
std::unique_ptr<Engine> make_unit_engine();
std::unique_ptr<Engine> make_rtl_engine();
std::unique_ptr<Engine> make_rtl_trad_engine();
std::unique_ptr<Engine> make_trad_engine();
std::unique_ptr<Engine> make_float_scanline_engine();
std::unique_ptr<Engine> make_model_engine();
std::unique_ptr<Engine> make_trad_model_engine();

const std::vector<EngineInfo>& engine_registry() {
  static const std::vector<EngineInfo> engines = {
      {"golden", "half-space rasterizer, the rule of raster-rules.md (the truth)", true,
       make_golden_engine},
      {"unit", "improved-Bresenham unit, bit-accurate datapath model (docs/unit.md)", true,
       make_unit_engine},
      {"rtl", "Verilated RTL of the improved unit (rtl/)", true, make_rtl_engine},
      {"model", "SystemC model of the improved unit: the unit's spans plus cycles (docs/timing.md)",
       true, make_model_engine},
      {"trad", "traditional Bresenham unit (GR3, seed 001 sec. 2.1), SystemC model with cycles; "
               "its own coverage, not the rule",
       false, make_trad_model_engine},
      {"rtl-trad", "Verilated RTL of the traditional unit (rtl/trirast_trad_*.sv): trad's spans "
                   "and cycles",
       false, make_rtl_trad_engine},
      {"float-scanline", "float scanline of seed 002, top-left via ceil(x - 0.5): a CPU baseline, "
                         "not exact",
       false, make_float_scanline_engine},
  };
  return engines;
}

const EngineInfo* find_engine(const std::string& name) {
  for (const EngineInfo& e : engine_registry())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace trirast
