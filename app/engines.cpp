// The list of engines. Adding an engine: include its factory's header and add one line below.
// Names are <unit>-<view>: the improved-Bresenham unit and the traditional one, each as a
// bit-accurate datapath, a SystemC model (sc) and Verilated RTL (rtl).
#include "engines.hpp"

#include "golden/golden.hpp"
#include "sc/sc_engine.hpp"
#include "unit/halfspace_unit.hpp"
#include "unit/improved_unit.hpp"
#include "verilator/rtl_engine.hpp"
#include "verilator/rtl_hs_engine.hpp"
#include "verilator/rtl_trad_engine.hpp"

namespace trirast {

const std::vector<EngineInfo>& engine_registry() {
  static const std::vector<EngineInfo> engines = {
      {"golden", "half-space rasterizer, the coverage rule of docs/coverage-rule.md (the truth)",
       true, [] { return make_golden_engine(); }},
      {"unit",
       "improved-Bresenham unit, bit-accurate datapath model, untimed (docs/unit.md)", true,
       make_unit_engine},
      {"model",
       "improved-Bresenham unit, SystemC model: the datapath's spans plus cycles (docs/timing.md)",
       true, make_model_engine},
      {"rtl", "improved-Bresenham unit, Verilated RTL (rtl/trirast_improved.f)", true,
       make_rtl_engine},
      {"trad",
       "traditional Bresenham unit (GR3-style edge walking), SystemC model with cycles; its own "
       "coverage, not the rule",
       false, make_trad_model_engine},
      {"rtl-trad",
       "traditional Bresenham unit, Verilated RTL (rtl/trirast_trad.f): trad-sc's spans and cycles",
       false, make_rtl_trad_engine},
      {"halfspace-datapath",
       "half-space (edge-function) tile unit, bit-accurate datapath, untimed (docs/unit.md)", true,
       make_halfspace_engine},
      {"halfspace-sc",
       "half-space tile unit, SystemC model: the datapath's spans plus cycles (docs/timing.md)",
       true, make_halfspace_model_engine},
      {"halfspace-rtl",
       "half-space tile unit, Verilated RTL (rtl/trirast_halfspace.f): halfspace-sc's spans and "
       "cycles",
       true, make_rtl_halfspace_engine},
      {"float-scanline",
       "float scanline with the top-left rule as ceil(x - 0.5): a CPU baseline, not exact", false,
       make_float_scanline_engine},
  };
  return engines;
}

std::string engine_alias(const std::string& name) {
  static const std::pair<const char*, const char*> kOldNames[] = {{"", ""}};
  for (const auto& [old_name, new_name] : kOldNames)
    if (name == old_name) return new_name;
  return {};
}

const EngineInfo* find_engine(const std::string& name) {
  const std::string alias = engine_alias(name);
  const std::string& wanted = alias.empty() ? name : alias;
  for (const EngineInfo& e : engine_registry())
    if (e.name == wanted) return &e;
  return nullptr;
}

}  // namespace trirast
