// The engines this build holds: the list the CLI, the sweep and the tests look names up in. It sits
// above every engine library (model/, model/, tb/), so none of them reaches up to it.
// The list is made from the unit descriptors (units.hpp).
#pragma once
#include <string>
#include <vector>

#include "common/engine.hpp"

namespace trirast {

// All engines compiled into this build, in the order --help lists them.
const std::vector<EngineInfo>& engine_registry();
// Looks an engine up by its name; nullptr when unknown.
const EngineInfo* find_engine(const std::string& name);

}  // namespace trirast
