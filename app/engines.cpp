// The list of engines. Adding an engine: include its factory's header and add one line below.
// Names are <unit>-<view>: the improved-Bresenham unit as a bit-accurate datapath (-datapath), a
// SystemC model (-sc) and Verilated RTL (-rtl); the traditional unit as -sc and -rtl.
#include "engines.hpp"

#include <cstdio>
#include <set>

#include "golden/golden.hpp"
#include "improved/improved_sc.hpp"
#include "improved2/improved2_sc.hpp"
#include "trad/trad_sc.hpp"
#include "halfspace/halfspace_sc.hpp"
#include "halfspace/halfspace_unit.hpp"
#include "improved2/improved2_unit.hpp"
#include "improved/improved_unit.hpp"
#include "improved/improved_rtl_engine.hpp"
#include "halfspace/halfspace_rtl_engine.hpp"
#include "improved2/improved2_rtl_engine.hpp"
#include "trad/trad_rtl_engine.hpp"

namespace trirast {

const std::vector<EngineInfo>& engine_registry() {
  static const std::vector<EngineInfo> engines = {
      {"golden", "half-space rasterizer, the coverage rule of docs/coverage-rule.md (the truth)",
       true, [] { return make_golden_engine(); }},
      {"improved-datapath",
       "improved-Bresenham unit, bit-accurate datapath model, untimed (docs/unit.md)", true,
       make_improved_datapath_engine},
      {"improved-sc",
       "improved-Bresenham unit, SystemC model: the datapath's spans plus cycles (docs/timing.md)",
       true, make_improved_sc_engine, /*timed=*/true},
      {"improved-rtl", "improved-Bresenham unit, Verilated RTL (rtl/improved/trirast_improved.f)", true,
       make_improved_rtl_engine, /*timed=*/true},
      {"improved2-datapath",
       "second-generation improved unit, bit-accurate datapath, untimed "
       "(docs/improved2.md)",
       true, make_improved2_datapath_engine},
      {"improved2-sc",
       "second-generation improved unit, SystemC model: its spans plus cycles, N = 1, 2, 4 "
       "(docs/improved2.md)",
       true, make_improved2_sc_engine, /*timed=*/true},
      {"improved2-rtl",
       "second-generation improved unit, Verilated RTL (rtl/improved2/trirast_improved2.f): improved2-sc's "
       "spans and cycles",
       true, make_improved2_rtl_engine, /*timed=*/true},
      {"trad-sc",
       "traditional Bresenham unit (GR3-style edge walking), SystemC model with cycles; its own "
       "coverage, not the rule",
       false, make_trad_sc_engine, /*timed=*/true},
      {"trad-rtl",
       "traditional Bresenham unit, Verilated RTL (rtl/trad/trirast_trad.f): trad-sc's spans and cycles",
       false, make_trad_rtl_engine, /*timed=*/true},
      {"halfspace-datapath",
       "half-space (edge-function) tile unit, bit-accurate datapath, untimed (docs/unit.md)", true,
       make_halfspace_datapath_engine},
      {"halfspace-sc",
       "half-space tile unit, SystemC model: the datapath's spans plus cycles (docs/timing.md)",
       true, make_halfspace_sc_engine, /*timed=*/true},
      {"halfspace-rtl",
       "half-space tile unit, Verilated RTL (rtl/halfspace/trirast_halfspace.f): halfspace-sc's spans and "
       "cycles",
       true, make_halfspace_rtl_engine, /*timed=*/true},
      {"float-scanline",
       "float scanline with the top-left rule as ceil(x - 0.5): a CPU baseline, not exact", false,
       make_float_scanline_engine},
  };
  return engines;
}

std::string engine_alias(const std::string& name) {
  // Old names, kept for one release: the next release drops this list.
  static const std::pair<const char*, const char*> kOldNames[] = {
      {"unit", "improved-datapath"}, {"model", "improved-sc"}, {"rtl", "improved-rtl"},
      {"trad", "trad-sc"},           {"rtl-trad", "trad-rtl"},
  };
  for (const auto& [old_name, new_name] : kOldNames)
    if (name == old_name) return new_name;
  return {};
}

std::string current_engine_name(const std::string& name) {
  const std::string alias = engine_alias(name);
  if (alias.empty()) return name;
  static std::set<std::string> noted;
  if (noted.insert(name).second)
    std::fprintf(stderr, "trirast: engine '%s' is now '%s' (the old name works for this release)\n",
                 name.c_str(), alias.c_str());
  return alias;
}

const EngineInfo* find_engine(const std::string& name) {
  const std::string alias = engine_alias(name);
  const std::string& wanted = alias.empty() ? name : alias;
  for (const EngineInfo& e : engine_registry())
    if (e.name == wanted) return &e;
  return nullptr;
}

}  // namespace trirast
