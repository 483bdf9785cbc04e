// Watertightness check for closed configurations (fans, grids, whole-screen covers): every pixel
// centre inside the union of the triangles is covered exactly once.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/setup.hpp"
#include "core/span.hpp"

namespace trirast::test {

struct WatertightResult {
  int64_t covered = 0;  // pixels covered at least once
  int64_t doubled = 0;  // pixels covered more than once
  int64_t holes = 0;    // uncovered pixels whose centre is inside the union, off its outer boundary
  std::string first_problem;
};

// `spans` are any engine's spans of the scene set up in `setup`. A pixel centre that lies on an
// edge or vertex of some triangle and is uncovered is a hole unless it lies on an outer boundary
// edge (an edge used by exactly one triangle). Pixels strictly inside a triangle are holes too.
WatertightResult check_watertight(const SetupResult& setup, const SpanList& spans,
                                  const RasterConfig& cfg);

}  // namespace trirast::test
