// The engines this build holds: the list the CLI, the sweep and the tests look names up in. It sits
// above every engine library (model/, model/, tb/), so none of them reaches up to it.
#pragma once
#include <string>
#include <vector>

#include "common/engine.hpp"

namespace trirast {

// All engines compiled into this build, in the order --help lists them.
const std::vector<EngineInfo>& engine_registry();
// Looks an engine up by its name or by an old name (see engine_alias); nullptr when unknown.
const EngineInfo* find_engine(const std::string& name);
// The current name for an old engine name kept for one release (e.g. "model" -> "improved-sc");
// empty when `name` is not an old name.
std::string engine_alias(const std::string& name);
// A name the user typed (--engine, --engines, ...), as the current name: an old name prints one
// note on stderr (once per name and process) and comes back as its new name; any other name
// comes back as given (unknown ones are for the caller to refuse).
std::string current_engine_name(const std::string& name);

}  // namespace trirast
