#include "io/report_descriptions.hpp"

#include <map>
#include <vector>

namespace trirast {

namespace {

// Statistics by name; a leading "engines[]." (compare) is removed before the look-up.
const std::map<std::string, std::string>& table() {
  static const std::map<std::string, std::string> t = {
      {"engine", "the engine that ran (trirast engines lists them)"},
      {"scene", "the --scene argument as given"},
      {"spans", "spans the engine emitted (one row of one triangle each)"},
      {"pixels", "pixels the engine covered (sum of span lengths)"},
      {"config.width", "viewport width in pixels (--width)"},
      {"config.height", "viewport height in pixels (--height)"},
      {"config.subpixel_bits", "vertex snapping: coordinates are multiples of 1/2^S pixel (--subpixel-bits)"},
      {"config.coord_bits", "signed integer bits of a coordinate (--coord-bits)"},
      {"config.cull", "face culling: none, back or front (--cull)"},
      {"config.rtl_checked", "the RTL engines run their checked Verilated builds (--rtl-checked, or implied by --coverage or --trace)"},
      {"config.box_bits", "bits of a box-relative coordinate in the unit (--box-bits)"},
      {"config.boundary", "the improved unit's boundary traversal: step or divide (--boundary)"},
      {"config.divider", "the improved unit's divider iterations: adaptive or fixed (--divider)"},
      {"config.stamp", "the half-space unit's stamp side in pixels (--stamp)"},
      {"config.tile", "the half-space unit's tile side in pixels, 0 for no tiles (--tile)"},
      {"config.hs_walk", "the half-space unit's tile order: row, zigzag or forward (--hs-walk)"},
      {"config.corner_form", "the second-generation unit's corner form: dsp or radix16 (--corner-form)"},
      {"config.hs_corner_form", "the half-space unit's corner form: dsp or radix16 (--hs-corner-form)"},
      {"config.traversal", "the golden's pixel traversal (--traversal)"},
      {"config.threads", "the golden's threads, 0 for all cores (--threads)"},
      {"config.endpoints", "rows walked per cycle by the timed units (--endpoints)"},
      {"config.fifo_depth", "span FIFO entries of the timed units (--fifo-depth)"},
      {"config.sink_stall", "ready pattern of the span sink (--sink-stall)"},
      {"triangles.read", "triangles in the scene file or built-in, before near-plane clipping and drops"},
      {"triangles.set_up", "triangles handed to setup: read, less near-plane and range drops, plus extra pieces of clipped ones"},
      {"triangles.accepted", "triangles handed to the engines after setup (off-screen ones included)"},
      {"triangles.culled", "triangles removed by --cull"},
      {"triangles.degenerate", "triangles of zero area after snapping"},
      {"triangles.offscreen", "accepted triangles whose snapped extent misses the viewport"},
      {"triangles.no_pixel_centre", "accepted triangles whose bounding box holds no pixel centre (tiny or off-screen)"},
      {"triangles.near_clipped", "mesh triangles cut by the near plane (their pieces kept)"},
      {"triangles.near_dropped", "mesh triangles wholly behind the near plane (not rasterized)"},
      {"triangles.range_dropped", "mesh triangles with a piece outside the coordinate range (piece dropped)"},
      {"wall_seconds.load", "wall-clock seconds reading or generating the scene"},
      {"wall_seconds.setup", "wall-clock seconds of triangle setup"},
      {"wall_seconds.engine", "wall-clock seconds of the engine run"},
      {"wall_seconds.total", "wall-clock seconds of the whole command"},
      {"timing.total_cycles", "clock cycles from the first triangle's accept to the last span"},
      {"timing.triangles_per_cycle", "accepted triangles per clock cycle"},
      {"timing.spans_per_cycle", "spans emitted per clock cycle"},
      {"timing.pixels_per_cycle", "pixels covered per clock cycle"},
      {"timing.sim_cycles_per_second", "simulated clock cycles per wall-clock second"},
      {"timing.sim_cycles_per_cpu_second", "simulated clock cycles per CPU second of the process"},
      {"work.triangles", "triangles the engine processed"},
      {"work.spans", "spans the engine emitted"},
      {"work.pixels", "pixels the engine covered"},
      {"work.boundary_steps", "edge-walker boundary steps (improved unit)"},
      {"work.divider_iterations", "adder-divider iterations (improved unit)"},
      {"work.divisions", "divisions started by the adder-dividers (improved unit)"},
      {"work.rows_stepped", "rows the edge walkers stepped through"},
      {"work.empty_boxes", "triangles whose clipped box was empty (retired in the box stage)"},
      {"work.tiny_boxes", "boxes the second-generation unit's direct 2x2 test covered"},
      {"work.lane_boxes", "boxes the three edge lanes set up (second-generation unit)"},
      {"work.hs_units_tested", "tiles (stamps without tiles) the half-space unit's walker tested"},
      {"work.hs_units_rejected", "tested units the half-space unit rejected from their corners"},
      {"work.hs_tiles_accepted", "tiles the half-space unit accepted whole from their corners"},
      {"work.hs_units_partial", "tested tiles the half-space unit walked stamp by stamp"},
      {"work.hs_stamps", "stamps the half-space unit's stamp tester tested"},
      {"work.hs_bands", "bands of tiles the half-space unit walked"},
      {"work.rows_visited", "rows of a bounding box the engine visited"},
      {"work.rtl_build_endpoints", "NumEndpoints of the Verilated RTL build the run used"},
      {"work.rtl_build_fifo_depth", "FifoDepth of the Verilated RTL build the run used"},
      {"work.rtl_build_checked", "1: the run used a checked Verilated build (assertions, cover points, trace support); 0: a speed build"},
      {"work.rtl_x_seed", "seed of the RTL's random initial values (Verilator --x-initial unique)"},
      {"work.rtl_x_zero_fill", "1: a traced run without TRIRAST_RTL_SEED filled the RTL's initial values with zeros (the trace shows no random numbers)"},
      {"work.sim_cycles_per_second", "simulated clock cycles per wall-clock second"},
      {"work.sim_cpu_microseconds", "CPU microseconds of the process during the simulation"},
      {"work.sim_cycles_per_cpu_second", "simulated clock cycles per CPU second of the process"},
      {"work.sim_wall_microseconds", "wall-clock microseconds of the simulation"},
      {"work.total_cycles", "clock cycles of the run"},
      {"work.trad_bresenham_steps", "Bresenham steps of the traditional unit's edge walkers"},
      {"work.trad_collinear", "triangles the traditional unit found collinear after sorting"},
      {"work.walk_stall_cycles", "cycles the walk stage waited for room in the span FIFO"},
      {"work.golden_threads", "threads the golden rasterizer used"},
      {"golden_pixels", "pixels the golden rasterizer covered (the reference)"},
      {"all_exact_agree", "every engine that claims exactness covers exactly the golden's pixels"},
      {"claims_exact", "the engine claims pixel-exact agreement with the golden rule"},
      {"missing_pixels", "golden pixels the engine did not cover"},
      {"extra_pixels", "pixels the engine covered that the golden does not"},
      {"agrees", "the engine covers exactly the golden's pixels"},
      {"seconds", "wall-clock seconds of the engine run"},
      {"fmax_mhz", "timed engines: the unit's iCE40 HX8K routed Fmax at these widths (docs/synth.csv), null when none was routed"},
      {"microseconds_at_fmax", "timed engines: total cycles at fmax_mhz, in microseconds (null without a routed Fmax)"},
      {"fmax_source", "timed engines: the docs/synth.csv row the Fmax came from, or why there is none"},
      {"diff_image", "the PNG of this engine against the golden (grey agreed, red missing, blue extra, ringed)"},
      {"differing_triangle_count", "triangles with a pixel that differs from the golden"},
      {"differing_triangles", "the first differing triangles (scene indices), at most 64"},
      {"differing_pixel_count", "pixels that differ from the golden (missing plus extra)"},
      {"differing_pixels", "the first differing pixels (at most 64): tri, x, y, kind"},
      {"differing_pixels[].tri", "triangle of a differing pixel (the first 64 listed)"},
      {"differing_pixels[].x", "column of a differing pixel"},
      {"differing_pixels[].y", "row of a differing pixel"},
      {"differing_pixels[].kind", "missing (golden covers it) or extra (only the engine covers it)"},
  };
  return t;
}

bool starts_with(const std::string& s, const std::string& p) { return s.rfind(p, 0) == 0; }
bool ends_with(const std::string& s, const std::string& p) {
  return s.size() >= p.size() && s.compare(s.size() - p.size(), p.size(), p) == 0;
}

}  // namespace

std::string describe_statistic(const std::string& full_name) {
  std::string name = full_name;
  if (starts_with(name, "engines[].")) name = name.substr(10);
  auto it = table().find(name);
  if (it != table().end()) return it->second;
  // timing.modules.NAME.busy / .stall: per-module cycle counters of a timed engine.
  if (starts_with(name, "timing.modules.") || starts_with(name, "work.busy_cycles.") ||
      starts_with(name, "work.stall_cycles.")) {
    const bool busy = ends_with(name, ".busy") || starts_with(name, "work.busy_cycles.");
    std::string module = name;
    if (starts_with(module, "timing.modules.")) {
      module = module.substr(15);
      module = module.substr(0, module.rfind('.'));
    } else {
      module = module.substr(module.find('.', 5) + 1);
    }
    return busy ? "cycles the " + module + " module was busy (docs/timing.md)"
                : "cycles the " + module + " module stalled: busy but unable to advance (docs/timing.md)";
  }
  return "";
}

void add_descriptions(Json& report) {
  std::vector<std::string> names;
  report.leaf_names(names);
  Json d = Json::object();
  for (const std::string& n : names) {
    if (n == "descriptions" || starts_with(n, "descriptions.")) continue;
    const std::string text = describe_statistic(n);
    d.set(n, text.empty() ? "(no description)" : text);
  }
  report.set("descriptions", d);
}

}  // namespace trirast
