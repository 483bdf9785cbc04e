// The scenes of docs/cycles-improved-vs-trad.md (tools/cycles_table.cpp) and
// docs/which-unit-wins.md (tools/unit_compare.cpp): the five benchmark scenes after Mileff, Nehez &
// Dudra, the built-in meshes and the test mesh cube.obj (under the source folder `source`).
#pragma once
#include <string>
#include <vector>

namespace trirast {

struct BenchmarkScene {
  std::string label, spec;
};

inline std::vector<BenchmarkScene> benchmark_scenes(const std::string& source) {
  return {
      {"1 low-poly far", "builtin:lowpoly-far"},
      {"2 low-poly near", "builtin:lowpoly-near"},
      {"3 high-poly far", "builtin:highpoly-far"},
      {"4 high-poly near", "builtin:highpoly-near"},
      {"5 mixed", "builtin:mixed"},
      {"mesh: sphere", "builtin:sphere"},
      {"mesh: torus", "builtin:torus"},
      {"mesh: surface", "builtin:surface"},
      {"mesh: cube.obj", source + "/tests/data/cube.obj"},
  };
}

}  // namespace trirast
