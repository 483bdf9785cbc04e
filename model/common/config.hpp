// Configuration shared by setup and every engine: viewport, subpixel precision, coordinate range,
// culling, and the unit's hardware parameters.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace trirast {

class SpanDownstream;

enum class CullMode { None, Back, Front };

// How the unit's walkers find the first row where an edge enters the bounding box:
// Step = the paper's boundary traversal, one row per step down the box's side column;
// Divide = one division on the adder divider (same result, fewer steps on tall boxes).
enum class BoundaryMode { Step, Divide };
BoundaryMode parse_boundary_mode(const std::string& text);
const char* boundary_mode_name(BoundaryMode mode);

// How many iterations the unit's adder divider runs per division (docs/unit.md, section 3):
// Fixed = Q = box_bits + 1 always (m from the configured range);
// Adaptive = as many quotient bits as this triangle's box needs (m from the box size).
enum class DividerMode { Fixed, Adaptive };
DividerMode parse_divider_mode(const std::string& text);
const char* divider_mode_name(DividerMode mode);

// How the half-space unit walks the box's tiles (docs/timing.md, "The half-space unit"):
// Row = every tile of every band, left to right; Zigzag = bands alternate direction and a band
// ends at the first tile rejected after a tile that was not (the rest of the band is empty);
// Forward = every band left to right, with the zig-zag walk's early band end (the default: no
// right-to-left band, so the set-up forms no value at the band row's far end).
// The values are the RTL walker's WalkMode parameter.
enum class HalfspaceWalk { Row = 0, Zigzag = 1, Forward = 2 };
HalfspaceWalk parse_halfspace_walk(const std::string& text);
const char* halfspace_walk_name(HalfspaceWalk walk);

// The corner form of the improved2 and half-space units: "dsp" (0) | "radix16" (1); throws
// std::invalid_argument naming the option otherwise.
int parse_corner_form(const std::string& text, const std::string& option = "--corner-form");
const char* corner_form_name(int form);

// Parses "none" | "back" | "front"; throws std::invalid_argument otherwise.
CullMode parse_cull_mode(const std::string& text);
const char* cull_mode_name(CullMode mode);

constexpr int kMaxViewport = 16384;  // largest --width / --height

// The half-space unit's hardware parameters (docs/unit.md, "The half-space unit").
struct HalfspaceConfig {
  int stamp = 2;                                // S: the stamp tester tests S x S pixels per cycle (1, 2, 4)
  int tile = 8;                                 // T: tile edge for hierarchical rejection (8, 16; 0 = none)
  HalfspaceWalk walk = HalfspaceWalk::Forward;  // tile order
  // How the set-up forms the edge values at the box corner: 0 = products in one cycle (the xc7
  // form, the default), 1 = the digit-serial corner unit, radix 16 (no multipliers: the iCE40 HX
  // form; cycles only, the values are the same).
  int corner_form = 0;
};

// The second-generation improved unit's build choice: how its corner stage forms the corner
// values: 0 = DSP products in one cycle (the xc7 form), 1 = digit-serial, MSB first, radix 16
// (the iCE40 HX form, the default).
struct Improved2Config {
  int corner_form = 1;
};

struct RasterConfig {
  int width = 1024;          // viewport width in pixels, 1..kMaxViewport
  int height = 768;          // viewport height in pixels, 1..kMaxViewport
  int subpixel_bits = 8;     // S: vertices snap to 1/2^S pixel, 0..8
  int coord_int_bits = 16;   // signed integer bits of a coordinate: range [-2^15, 2^15) pixels
  CullMode cull = CullMode::None;

  // ---- the improved-Bresenham unit's hardware parameters ----
  int box_bits = 14;         // unsigned bits of a box-relative pixel coordinate (box <= 2^box_bits)
  BoundaryMode boundary = BoundaryMode::Step;
  DividerMode divider = DividerMode::Adaptive;
  // Quotient truncation (the sweep's "divider width", docs/speed-vs-error.md): 0 = automatic (the
  // exact default: Q, or the bits the box needs); K > 0 caps every division at K quotient bits,
  // so a quotient >= 2^K saturates (read as "beyond the box") and the unit is no longer exact.
  int divider_quotient_bits = 0;

  // ---- the half-space unit's hardware parameters (docs/unit.md, "The half-space unit") ----
  HalfspaceConfig halfspace;

  // ---- the second-generation improved unit's build choice (improved2-*) ----
  Improved2Config improved2;

  // ---- timing (docs/timing.md): used by the cycle-level engines (model, rtl, trad) ----
  int endpoints = 1;                // N: rows the walk stage processes per cycle (1, 2, 4)
  int fifo_depth = 8;               // span FIFO entries (>= endpoints)
  std::string sink_stall = "none";  // the downstream's ready (common/span_downstream.hpp)
  // A program's own downstream (docs/embedding.md): when set, every run of a cycle-level engine
  // gets a fresh one from it in place of the one sink_stall names.
  std::function<std::unique_ptr<SpanDownstream>()> downstream;

  // ---- traces of the cycle-level engines ----
  std::string trace_path;           // empty: no trace
  int64_t trace_first = 0;          // record only triangles trace_first..trace_last (scene
  int64_t trace_last = -1;          // indices); trace_last < 0: to the end

  // ---- the RTL engines' Verilated builds (docs/rtl.md, "Speed and checked builds") ----
  // Run the checked builds (assertions, cover points, trace support) where a speed build would
  // cover the run; a trace or --coverage run takes them anyway.
  bool rtl_checked = false;

  // Fractional bits used for the arithmetic: S, or 1 when S == 0 so that pixel centres
  // (px + 0.5) stay integers (docs/coverage-rule.md, "S = 0").
  int frac_bits() const { return subpixel_bits > 0 ? subpixel_bits : 1; }
  // Multiplier from snapped S-bit vertex values to frac_bits() values (1, or 2 when S == 0).
  int64_t snap_scale() const { return subpixel_bits > 0 ? 1 : 2; }
  // One pixel in frac_bits() units.
  int64_t unit() const { return int64_t(1) << frac_bits(); }
  // Half a pixel in frac_bits() units (the offset of a pixel centre).
  int64_t half() const { return int64_t(1) << (frac_bits() - 1); }
  // Exclusive bound of |coordinate| in pixels: coordinates lie in [-limit, limit).
  int64_t coord_limit_px() const { return int64_t(1) << (coord_int_bits - 1); }
  // Signed bits of a vertex coordinate in frac_bits() units (p in docs/coverage-rule.md).
  int vertex_bits() const { return coord_int_bits + frac_bits(); }

  // Throws std::invalid_argument with a message naming the option when out of range.
  void validate() const;
};

}  // namespace trirast
