// The list of engines, as the unit descriptors (units.cpp) register them: names are
// <unit>-<view>, the reference engines golden and float-scanline besides.
#include "engines.hpp"

#include "units.hpp"

namespace trirast {

const std::vector<EngineInfo>& engine_registry() {
  static const std::vector<EngineInfo> engines = [] {
    std::vector<EngineInfo> out;
    for (const EngineDescriptor& d : engine_descriptors()) out.push_back(d.info);
    return out;
  }();
  return engines;
}

const EngineInfo* find_engine(const std::string& name) {
  for (const EngineInfo& e : engine_registry())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace trirast
