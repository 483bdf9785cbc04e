// One line of text for every statistic of a --report JSON (the habit of gem5's stats.txt): the
// report gets a "descriptions" object mapping each dotted statistic name ("triangles.read",
// "engines[].work.divider_iterations", "timing.modules.setup.busy") to its description. The
// values keep their places: scripts that read the report do not change.
#pragma once
#include <string>

#include "io/json.hpp"

namespace trirast {

// The description of one statistic name; empty when none is known.
std::string describe_statistic(const std::string& name);

// Adds "descriptions" to `report` for every statistic in it (a missing one reads
// "(no description)", which the test suite refuses).
void add_descriptions(Json& report);

}  // namespace trirast
