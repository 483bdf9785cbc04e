// The schedule of trirast fuzz: which engines run a scene, and on how much of it, so that each
// engine spends about the same CPU time per scene however slow it is.
//
// A scene's cost to an engine is estimated before it runs, from the set-up triangles' boxes:
// triangles, box rows, box columns and the half-space unit's unit tests and stamps, each times a
// per-engine constant (kFuzzCosts in fuzz_schedule.cpp, measured by `trirast fuzz --calibrate`).
// An engine whose estimate is above its cap (share / min_fraction) gets the scene cut down: the
// viewport cropped to its top-left corner (halved, the larger side first, down to 16 pixels),
// then a window of consecutive triangles (halved); the triangles themselves are never changed,
// so every class the generator draws reaches every engine with its exact vertices. The engine
// then runs the scene when scene % 10 is its slot (so every engine sees at least one scene in
// ten) or when a draw from (seed, scene, engine) falls below share / estimate. Everything depends
// only on the seed, the scene and the constants: a seed reproduces its run.
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "common/config.hpp"
#include "common/setup.hpp"

namespace trirast {

// What a scene (or a cut of it) costs an engine, in the quantities the constants multiply.
struct FuzzCostFeatures {
  double tris = 0;    // accepted triangles
  double rows = 0;    // box rows (sum of box heights)
  double cols = 0;    // box columns (sum of box widths)
  double stamps = 0;  // the half-space walker's unit tests plus the stamps of partial tiles
};

// Nanoseconds of CPU time per run, triangle, row, column and stamp.
struct FuzzEngineCost {
  const char* engine;
  double run_ns, tri_ns, row_ns, col_ns, stamp_ns;
};

// The table (an unknown engine gets the dearest row's constants).
const std::vector<FuzzEngineCost>& fuzz_cost_table();
const FuzzEngineCost& fuzz_engine_cost(const std::string& engine);

// The features of the accepted triangles with scene index in [tri_begin, tri_end), boxes clipped
// to a width x height viewport at the origin (cfg's half-space stamp and tile).
FuzzCostFeatures fuzz_cost_features(const SetupResult& setup, const RasterConfig& cfg, int width,
                                    int height, uint32_t tri_begin, uint32_t tri_end);
double fuzz_estimate_ns(const FuzzEngineCost& cost, const FuzzCostFeatures& f);

// One engine's part of one scene.
struct FuzzAssignment {
  bool runs = false;
  bool cut = false;              // the viewport or the triangles were cut down
  int width = 0, height = 0;     // the viewport it runs (the scene's, or a crop at the origin)
  uint32_t tri_begin = 0, tri_end = 0;  // the scene's triangles it runs
  double estimate_ns = 0;        // of what it runs
};

struct FuzzSchedulePolicy {
  double share_ns = 1.0e6;    // CPU time per scene each engine should spend on average
  int slot_period = 10;       // an engine runs every scene whose index % period is its slot
};

// The assignment of every engine in `engines` (the golden included: it always runs the whole
// scene) for scene `scene` of `seed`; `n_tris` the scene's triangles, `setup` set up at `cfg`.
std::vector<FuzzAssignment> fuzz_schedule_scene(uint64_t seed, uint64_t scene,
                                                const SetupResult& setup, uint32_t n_tris,
                                                const RasterConfig& cfg,
                                                const std::vector<std::string>& engines,
                                                const FuzzSchedulePolicy& policy = {});

// `trirast fuzz --calibrate`: runs every engine in `engines` on four fixed scenes, fits the
// constants to their CPU times and prints them as kFuzzCosts rows on `out`.
void fuzz_calibrate(const std::vector<std::string>& engines, std::FILE* out);

}  // namespace trirast
