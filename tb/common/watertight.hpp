// The closed-mesh check, one for the tests and the sweep: on a closed configuration (a mesh, a
// fan, a grid, a whole-screen cover) every pixel centre inside the union of the triangles is
// covered exactly once. Its words: a crack is an uncovered pixel whose centre lies inside or on a
// set-up triangle and not on the outline (the edges used by exactly one triangle, where the
// coverage rule leaves one side uncovered); a double hit is a pixel covered more than once.
#pragma once
#include <cstdint>
#include <string>

#include "common/config.hpp"
#include "common/setup.hpp"
#include "common/span.hpp"

namespace trirast {

struct WatertightResult {
  int64_t covered = 0;  // pixels covered at least once
  int64_t doubles = 0;  // pixels covered more than once
  int64_t cracks = 0;   // uncovered centres inside or on a triangle, off the outline; each once
  std::string first_problem;  // the first double hit or crack, in words; empty when none
};

// `spans` are any engine's spans of the scene set up in `setup`; spans outside the viewport of
// `cfg` are not counted.
WatertightResult check_watertight(const SetupResult& setup, const SpanList& spans,
                                  const RasterConfig& cfg);

}  // namespace trirast
