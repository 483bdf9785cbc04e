// Speed against error (docs/speed-vs-error.md): engines x configurations x scenes.
// Every point is measured against one reference per scene: the golden at S = 8 with the default
// coordinate width, on the same float input. This file holds the measurement of one point on
// one scene and the aggregation over scenes; app/cli/cmd_sweep.cpp runs them (in parallel) and
// writes the outputs.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "common/config.hpp"
#include "common/setup.hpp"
#include "common/span.hpp"
#include "io/json.hpp"
#include "sweep/sweep_area.hpp"
#include "scene/scene.hpp"

namespace trirast {

// A scene of the sweep: the --scene argument, its culling, and whether it is a closed mesh (then
// cracks and double hits are counted).
struct SweepScene {
  std::string spec;   // builtin:NAME[:k=v,...], a .tri file, or a mesh file
  std::string label;  // short name for tables and plots
  CullMode cull = CullMode::None;
  bool closed = false;
  CameraOptions camera;  // mesh scenes: the camera (trirast fit --yaw, ...; sweeps use the default)
};

// Parses "SPEC[@back|@front|@none][@closed]" (the --scenes items).
SweepScene parse_sweep_scene(const std::string& text);

// One configuration of one engine.
struct SweepPoint {
  std::string engine;   // model | trad | float-scanline | golden | unit | rtl
  std::string group;    // the sweep axis the point belongs to ("S x N x K", "box bits", ...)
  RasterConfig cfg;     // cull is taken from the scene
  UnitKind kind() const;
  // Whether the RTL implements the configuration (buildable hardware, so synthesizable): the
  // traditional unit, and the improved unit without quotient truncation (K) and with the default
  // FIFO depth. An improved configuration with K is a C++-model-only what-if: no RTL, its area
  // stays an estimate, and it is never on a hardware front. The second-generation unit
  // (improved2-*) is buildable at the default FIFO depth (rtl/improved2/trirast_improved2.f, both corner
  // forms, any widths).
  bool rtl() const;
  // "S8 c16 b14 K- N1" plus "fixed" / "divide" when not the default; the second-generation unit
  // "S8 c16 b14 N1 gen2 radix16" (its corner form; the untimed improved2-datapath, whose spans
  // the corner form does not change, "S8 c16 b14 N1 gen2").
  std::string config_name() const;
  std::string label() const { return engine + " " + config_name(); }
};

// The points of the full sweep, or of --quick. `engines` restricts the engine names
// (empty = model, trad, float-scanline and the golden baseline).
std::vector<SweepPoint> sweep_points(bool quick, const std::vector<std::string>& engines);
// The scenes of the full sweep, or of --quick.
std::vector<SweepScene> sweep_scenes(bool quick);

// A scene loaded once with the default configuration (its float triangles are the input of every
// point) and its reference: the golden at S = 8, default coordinate width.
struct SweepSceneData {
  SweepScene spec;
  Scene scene;
  SpanList reference;  // sorted
  int64_t reference_pixels = 0;
  uint64_t reference_triangles = 0;  // accepted by the reference setup
  double golden_seconds = 0;         // the reference golden run's wall time
  // Closed meshes: the reference's own cracks and double hits (0 and 0 for a clean mesh).
  int64_t reference_cracks = -1, reference_doubles = -1;
};

SweepSceneData load_sweep_scene(const SweepScene& s, const RasterConfig& base);

// The measurement of one point on one scene.
struct PointResult {
  uint64_t read = 0;            // triangles in the scene
  uint64_t offered = 0;         // triangles the engine rasterized (accepted and not rejected)
  uint64_t degenerate = 0;      // zero area after snapping at this S
  uint64_t culled = 0;
  uint64_t rejected_range = 0;  // a vertex outside the coordinate range (--coord-bits)
  uint64_t rejected_width = 0;  // the engine's widths cannot hold it (box > 2^box_bits, ...)
  uint64_t spans = 0;
  int64_t pixels = 0;
  int64_t missing = 0;          // reference pixels the point does not cover
  int64_t extra = 0;            // pixels the point covers and the reference does not
  int64_t cracks = -1;          // closed meshes: uncovered pixels inside the surface (-1: n/a)
  int64_t doubles = -1;         // closed meshes: pixels covered more than once (-1: n/a)
  uint64_t total_cycles = 0;    // timed engines; 0 otherwise
  uint64_t divider_iterations = 0;
  double wall_seconds = 0;      // the engine's run (noisy: compare as ratios within one run)
  std::string error;            // non-empty when the point failed as a whole
};

// Sets up the scene's float triangles at the point's configuration, one triangle at a time (a
// triangle outside the coordinate range is rejected, not fatal), runs the engine (a triangle the
// engine's widths cannot hold is rejected, not fatal) and measures it against the reference.
PointResult run_sweep_point(const SweepPoint& p, const SweepSceneData& scene);

// A point aggregated over the scenes.
struct PointSummary {
  double error_ppm = 0;        // mean over scenes of (missing + extra) / reference pixels
  double missing_ppm = 0, extra_ppm = 0;
  double max_error_ppm = 0;    // the worst scene
  int64_t missing = 0, extra = 0, reference_pixels = 0;
  int64_t cracks = -1, doubles = -1;  // summed over the closed meshes
  uint64_t offered = 0, rejected = 0, total_cycles = 0;
  int64_t pixels = 0;
  uint64_t scene_triangles = 0;    // triangles the reference accepted, all scenes
  double cycles_per_triangle = 0;  // total cycles / scene_triangles (a rejected triangle counts)
  double cycles_per_pixel = 0;     // total cycles / covered pixels, all scenes
  double wall_seconds = 0;
  double wall_ratio = 0;           // wall seconds / the reference golden's, all scenes
  bool exact = false;              // no missing or extra pixel on any scene
  bool timed = false;
  int failures = 0;                // scenes where the point failed
  Area area;
  bool rtl = false;                // SweepPoint::rtl(): buildable hardware
  // The hardware fronts: among the buildable (rtl) timed points without failures.
  bool pareto_cycles = false;      // on the front of (error, cycles per triangle)
  bool pareto_area = false;        // on the front of (error, LUTs)
  // Model-only what-ifs (not rtl): the point would be on the front of (error, cycles) / (error,
  // LUTs) taken over every point, buildable or not. Never set for a buildable point.
  bool whatif_cycles = false;
  bool whatif_area = false;
};

PointSummary summarize(const SweepPoint& p, const std::vector<SweepSceneData>& scenes,
                       const std::vector<PointResult>& results, const AreaModel& area);
// Marks the Pareto fronts (minimize both coordinates) of buildable hardware (rtl) among the points
// without failures (cycles: timed points; area: points with an area), and the model-only
// what-if points (whatif_*: not rtl, undominated when every point competes).
void mark_pareto(std::vector<PointSummary>& summaries);

// Rows of the per-scene CSV / the per-configuration CSV, header first.
std::string sweep_csv(const std::vector<SweepPoint>& points,
                      const std::vector<SweepSceneData>& scenes,
                      const std::vector<std::vector<PointResult>>& results,
                      const std::vector<PointSummary>& summaries);
std::string sweep_configs_csv(const std::vector<SweepPoint>& points,
                              const std::vector<PointSummary>& summaries);
Json sweep_point_json(const SweepPoint& p);
Json point_result_json(const PointResult& r);
Json point_summary_json(const PointSummary& s);

}  // namespace trirast
