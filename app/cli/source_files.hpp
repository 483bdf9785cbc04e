// Files of the source tree a command reads by default (docs/synth.csv, scripts/synth.sh), found
// from any working directory.
#pragma once
#include <string>

namespace trirast {

// `relative` (e.g. "docs/synth.csv") in the source tree this program was built from, else beside
// the executable's build folder (BUILD/..), else as given (the working directory). Returns the
// first that exists, or the source-tree path when none does.
std::string source_file(const std::string& relative);

}  // namespace trirast
