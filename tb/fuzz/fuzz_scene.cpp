#include "fuzz/fuzz_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "common/span_diff.hpp"
#include "golden/golden.hpp"

namespace trirast {

namespace {

double process_cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

}  // namespace

// ---- draws --------------------------------------------------------------------------------------

uint64_t FuzzDraws::below(uint64_t n) {
  if (n <= 1) return 0;
  int need = 1;
  while (need < 64 && (uint64_t(1) << need) < n) ++need;
  // Eight extra bits keep the modulo bias small without costing the byte decoder much.
  const int take = std::min(64, need + 8);
  return bits(take) % n;
}

int64_t FuzzDraws::range(int64_t lo, int64_t hi) {
  return lo + int64_t(below(uint64_t(hi - lo) + 1));
}

uint64_t ByteDraws::bits(int n) {
  uint64_t v = 0;
  const int bytes = (n + 7) / 8;
  for (int i = 0; i < bytes; ++i) {
    const uint64_t b = pos_ < size_ ? data_[pos_] : 0;
    ++pos_;
    v |= b << (8 * i);
  }
  return n >= 64 ? v : v & ((uint64_t(1) << n) - 1);
}

const char* fuzz_class_name(FuzzClass c) {
  static const char* const names[] = {"lattice",      "near-centre",  "axis-diagonal", "near-vertical",
                                      "near-horizontal", "sliver",     "degenerate",    "tiny",
                                      "extreme",      "straddle",     "snap-tie",      "viewport-edge",
                                      "cover",        "random"};
  const int i = int(c);
  return i >= 0 && i < int(FuzzClass::kCount) ? names[i] : "?";
}

// ---- configuration ------------------------------------------------------------------------------

namespace {

int draw_extent(FuzzDraws& d) {
  const uint64_t pick = d.below(100);
  if (pick < 8) return int(d.range(1, 8));
  if (pick < 55) return int(d.range(9, 1024));
  if (pick < 85) {
    static const int common[] = {64, 256, 320, 480, 640, 768, 1024};
    return common[d.below(7)];
  }
  if (pick < 98) return int(d.range(1025, 4096));
  return kMaxViewport;
}

int bits_for(int64_t n) {  // smallest b with 2^b >= n
  int b = 0;
  while ((int64_t(1) << b) < n) ++b;
  return b;
}

}  // namespace

RasterConfig draw_fuzz_config(FuzzDraws& d, const std::vector<FuzzWidths>& widths) {
  RasterConfig cfg;
  cfg.width = draw_extent(d);
  cfg.height = d.chance(30) ? cfg.width : draw_extent(d);
  if (!widths.empty()) {
    const FuzzWidths& w = widths[d.below(widths.size())];
    cfg.subpixel_bits = w.subpixel_bits;
    cfg.coord_int_bits = w.coord_int_bits;
    cfg.box_bits = w.box_bits;
    // The range must hold the viewport (2^(N-1) >= extent), and the box bits its extent.
    const int cap = std::min(1 << (w.coord_int_bits - 1), 1 << w.box_bits);
    cfg.width = std::min(cfg.width, cap);
    cfg.height = std::min(cfg.height, cap);
  } else {
    // Two configurations in five keep the default widths (16.8, 14-bit boxes); the rest vary
    // every width.
    const bool default_widths = d.chance(40);
    cfg.subpixel_bits = default_widths || d.chance(30) ? 8 : int(d.range(0, 7));
    const int extent = std::max(cfg.width, cfg.height);
    // The range must hold the viewport (2^(N-1) >= extent) and keep edge values within 63 bits.
    const int min_bits = std::max(2, bits_for(extent) + 1);
    const int max_bits = std::min(24, 30 - cfg.frac_bits());
    cfg.coord_int_bits = ((default_widths || d.chance(30)) && 16 >= min_bits && 16 <= max_bits)
                             ? 16
                             : int(d.range(min_bits, max_bits));
    // The box is clipped to the viewport, so a box_bits that holds the viewport holds every box.
    const int min_box = std::max(1, bits_for(extent));
    cfg.box_bits = default_widths || d.chance(30) ? 14 : int(d.range(min_box, 14));
  }
  cfg.boundary = d.chance(50) ? BoundaryMode::Step : BoundaryMode::Divide;
  const uint64_t cull = d.below(10);
  cfg.cull = cull < 7 ? CullMode::None : cull < 9 ? CullMode::Back : CullMode::Front;
  static const int endpoints[] = {1, 2, 4};
  cfg.endpoints = endpoints[d.below(3)];
  cfg.fifo_depth = d.chance(10) ? 1024 : int(d.range(cfg.endpoints, cfg.endpoints + 12));
  const uint64_t sink = d.below(10);
  if (sink < 6) {
    cfg.sink_stall = "none";
  } else if (sink < 8) {
    cfg.sink_stall = "periodic:" + std::to_string(d.range(1, 5)) + ":" + std::to_string(d.range(0, 5));
  } else if (kFuzzDrawsQueueDownstreams && sink == 9) {
    // A downstream that reacts to what it took: RATE pixels per cycle, CAPACITY pixels. A queue
    // makes a run's cycles grow with its pixels (pixels / RATE) where the patterns' grow with its
    // spans, so RATE is drawn from 8 up: the generator's screen-sized triangles stay affordable.
    const int64_t rate = d.range(8, 128);
    cfg.sink_stall = "queue:" + std::to_string(rate) + ":" + std::to_string(d.range(1, 512));
  } else {
    cfg.sink_stall = "random:" + std::to_string(d.below(1000)) + ":" + std::to_string(d.range(0, 90));
  }
  // The divider's iterations: adaptive (bits the box needs) or fixed (Q = box_bits + 1 on every
  // division: the longest, which adaptive reaches only on boxes of 2^(Q-2) pixels or more; the
  // RTL's cover point DivLenQ_C, docs/coverage.md).
  cfg.divider = d.chance(30) ? DividerMode::Fixed : DividerMode::Adaptive;
  cfg.validate();
  return cfg;
}

// ---- triangles ----------------------------------------------------------------------------------

namespace {

// Coordinates are drawn as integers on a grid one bit finer than the subpixel grid ("fine"
// units, 1/2^(S+1) pixel): even values are representable vertices, odd ones are snapping ties.
struct Grid {
  int64_t px;     // fine units per pixel (2^(S+1))
  int64_t sub;    // fine units per subpixel (2)
  int64_t lo, hi; // the representable range in fine units, both inclusive; odd values inside it
                  // still snap into the range (ties go to the even neighbour, never past hi)
  int shift;      // S + 1
  int64_t w, h;   // viewport in pixels
};

Grid grid_of(const RasterConfig& cfg) {
  Grid g;
  g.shift = cfg.subpixel_bits + 1;
  g.px = int64_t(1) << g.shift;
  g.sub = 2;
  g.lo = -cfg.coord_limit_px() * g.px;
  g.hi = cfg.coord_limit_px() * g.px - 2;
  g.w = cfg.width;
  g.h = cfg.height;
  return g;
}

struct P {
  int64_t x, y;  // fine units
};

int64_t clamp(int64_t v, const Grid& g) { return std::min(std::max(v, g.lo), g.hi); }

// A pixel index around the viewport: mostly inside, sometimes in a margin around it.
int64_t pick_pixel(FuzzDraws& d, int64_t extent) {
  if (d.chance(85)) return d.range(0, extent - 1);
  const int64_t margin = std::max<int64_t>(4, extent / 4);
  return d.range(-margin, extent + margin);
}

// A size in pixels: small, medium, large, or the viewport's.
int64_t pick_size(FuzzDraws& d, const Grid& g) {
  const uint64_t k = d.below(10);
  if (k < 3) return d.range(1, 4);
  if (k < 6) return d.range(2, 32);
  if (k < 9) return d.range(8, 256);
  return std::max<int64_t>(2, std::max(g.w, g.h));
}

P centre(int64_t px, int64_t py, const Grid& g) { return {px * g.px + g.px / 2, py * g.px + g.px / 2}; }

P lattice_point(FuzzDraws& d, P anchor, int64_t size, const Grid& g) {
  const int64_t px = anchor.x / g.px + d.range(-size, size);
  const int64_t py = anchor.y / g.px + d.range(-size, size);
  // Per axis a centre or a corner: pixel centres, pixel corners, middles of pixel sides.
  const int64_t ox = d.chance(65) ? g.px / 2 : 0;
  const int64_t oy = d.chance(65) ? g.px / 2 : 0;
  return {px * g.px + ox, py * g.px + oy};
}

P anchor_point(FuzzDraws& d, const Grid& g) { return centre(pick_pixel(d, g.w), pick_pixel(d, g.h), g); }

int64_t subpixel_offset(FuzzDraws& d, const Grid& g, int max_sub) {
  return d.range(-max_sub, max_sub) * g.sub;
}

// A fine coordinate near one end of the range (or exactly at it).
int64_t near_limit(FuzzDraws& d, const Grid& g) {
  const uint64_t k = d.below(4);
  if (k == 0) return g.lo;
  if (k == 1) return g.hi;
  const int64_t reach = g.px * d.range(0, 300) + g.sub * d.range(0, g.px / g.sub - 1);
  return d.chance(50) ? g.lo + reach : g.hi - reach;
}

void draw_class(FuzzDraws& d, const Grid& g, FuzzClass c, P v[3]) {
  const P a = anchor_point(d, g);
  const int64_t size = pick_size(d, g);
  switch (c) {
    case FuzzClass::Lattice:
      for (int i = 0; i < 3; ++i) v[i] = lattice_point(d, a, size, g);
      break;
    case FuzzClass::NearCentre:
      for (int i = 0; i < 3; ++i) {
        v[i] = lattice_point(d, a, size, g);
        v[i].x += subpixel_offset(d, g, 2);
        v[i].y += subpixel_offset(d, g, 2);
      }
      break;
    case FuzzClass::AxisAndDiagonal: {
      const int64_t len = d.range(1, size + 1) * g.px;
      v[0] = a;
      const uint64_t kind = d.below(4);
      if (kind == 0) v[1] = {a.x, a.y + (d.chance(50) ? len : -len)};  // vertical at x = k + 0.5
      else if (kind == 1) v[1] = {a.x + (d.chance(50) ? len : -len), a.y};  // horizontal
      else if (kind == 2) v[1] = {a.x + len, a.y + (d.chance(50) ? len : -len)};  // 45 degrees
      else v[1] = {a.x - len, a.y + (d.chance(50) ? len : -len)};
      v[2] = d.chance(50) ? lattice_point(d, a, size, g)
                          : P{a.x + (d.chance(50) ? len : -len), a.y};  // right angle on centres
      break;
    }
    case FuzzClass::NearVertical: {
      const int64_t len = d.range(1, std::max<int64_t>(2, d.chance(50) ? g.h * 2 : 64)) * g.px;
      v[0] = d.chance(50) ? a : P{a.x + subpixel_offset(d, g, 3), a.y + subpixel_offset(d, g, 3)};
      v[1] = {v[0].x + subpixel_offset(d, g, 3), v[0].y + (d.chance(50) ? len : -len)};
      v[2] = d.chance(30) ? P{v[0].x + subpixel_offset(d, g, 6), v[0].y + d.range(-len, len)}
                          : lattice_point(d, a, size, g);
      break;
    }
    case FuzzClass::NearHorizontal: {
      const int64_t len = d.range(1, std::max<int64_t>(2, d.chance(50) ? g.w * 2 : 64)) * g.px;
      v[0] = d.chance(50) ? a : P{a.x + subpixel_offset(d, g, 3), a.y + subpixel_offset(d, g, 3)};
      v[1] = {v[0].x + (d.chance(50) ? len : -len), v[0].y + subpixel_offset(d, g, 3)};
      v[2] = d.chance(30) ? P{v[0].x + d.range(-len, len), v[0].y + subpixel_offset(d, g, 6)}
                          : lattice_point(d, a, size, g);
      break;
    }
    case FuzzClass::Sliver: {
      const int64_t reach = std::max<int64_t>(2, d.chance(50) ? size : 1500) * g.px;
      v[0] = d.chance(50) ? a : P{a.x + d.range(-g.px, g.px), a.y + d.range(-g.px, g.px)};
      v[1] = {v[0].x + d.range(-reach, reach), v[0].y + d.range(-reach, reach)};
      const int64_t t = d.range(0, 1024);
      const int64_t off = d.chance(50) ? 2 : d.chance(50) ? 5 : 40;  // subpixels (5 = 0.02 px at S=8)
      v[2] = {v[0].x + (v[1].x - v[0].x) * t / 1024 + subpixel_offset(d, g, int(off)),
              v[0].y + (v[1].y - v[0].y) * t / 1024 + subpixel_offset(d, g, int(off))};
      break;
    }
    case FuzzClass::Degenerate: {
      v[0] = lattice_point(d, a, size, g);
      v[1] = d.chance(20) ? v[0] : lattice_point(d, a, size, g);
      const uint64_t kind = d.below(3);
      if (kind == 0) v[2] = v[d.below(2)];  // repeated vertex
      else if (kind == 1) {                 // collinear, beyond or between
        const int64_t m = d.range(-3, 3);
        v[2] = {v[0].x + (v[1].x - v[0].x) * m, v[0].y + (v[1].y - v[0].y) * m};
      } else {  // collinear within a subpixel or two after snapping (may flip or collapse)
        v[2] = {(v[0].x + v[1].x) / 2 + d.range(-1, 1), (v[0].y + v[1].y) / 2 + d.range(-1, 1)};
      }
      break;
    }
    case FuzzClass::Tiny:
      for (int i = 0; i < 3; ++i)
        v[i] = {a.x + d.range(-3 * g.px, 3 * g.px) / 2 * 2, a.y + d.range(-3 * g.px, 3 * g.px) / 2 * 2};
      break;
    case FuzzClass::Extreme:
      for (int i = 0; i < 3; ++i) {
        const bool far_x = d.chance(70), far_y = d.chance(70);
        v[i] = lattice_point(d, a, size, g);
        if (far_x) v[i].x = near_limit(d, g);
        if (far_y) v[i].y = near_limit(d, g);
      }
      break;
    case FuzzClass::Straddle:
      for (int i = 0; i < 3; ++i) {
        const int64_t r = std::max<int64_t>(2, size);
        v[i] = {d.range(-r * g.px, r * g.px) / 2 * 2, d.range(-r * g.px, r * g.px) / 2 * 2};
      }
      break;
    case FuzzClass::SnapTie:
      for (int i = 0; i < 3; ++i) {
        v[i] = lattice_point(d, a, size, g);
        v[i].x += subpixel_offset(d, g, 2);
        v[i].y += subpixel_offset(d, g, 2);
        if (d.chance(60)) v[i].x += d.chance(50) ? 1 : -1;  // exactly halfway between subpixels
        if (d.chance(60)) v[i].y += d.chance(50) ? 1 : -1;
      }
      break;
    case FuzzClass::ViewportEdge: {
      auto edge_coord = [&](int64_t extent) {
        const uint64_t k = d.below(5);
        int64_t px;
        if (k == 0) px = 0;
        else if (k == 1) px = extent;
        else if (k == 2) px = extent - 1;
        else {
          static const int64_t tiles[] = {4, 8, 16, 32, 64};
          const int64_t t = tiles[d.below(5)];
          px = t * d.range(0, std::max<int64_t>(1, extent / t));
        }
        return px * g.px + d.range(-2, 2) * (g.px / 4) / 2 * 2;
      };
      for (int i = 0; i < 3; ++i) {
        v[i] = lattice_point(d, a, size, g);
        if (d.chance(60)) v[i].x = edge_coord(g.w);
        if (d.chance(60)) v[i].y = edge_coord(g.h);
      }
      break;
    }
    case FuzzClass::Cover: {
      const int64_t ext = std::max(g.w, g.h) * g.px;
      const int64_t k = d.range(1, 6);
      v[0] = {-d.range(0, k * ext) / 2 * 2, -d.range(0, k * ext) / 2 * 2};
      v[1] = {g.w * g.px + d.range(0, 3 * k * ext) / 2 * 2, -d.range(0, k * ext) / 2 * 2};
      v[2] = {-d.range(0, k * ext) / 2 * 2, g.h * g.px + d.range(0, 3 * k * ext) / 2 * 2};
      if (d.chance(30)) {  // exactly the viewport's corners (one half of a two-triangle cover)
        v[0] = {0, 0};
        v[1] = {g.w * g.px, 0};
        v[2] = d.chance(50) ? P{0, g.h * g.px} : P{g.w * g.px, g.h * g.px};
      }
      break;
    }
    case FuzzClass::Random:
    default: {
      const int64_t r = size * g.px;
      for (int i = 0; i < 3; ++i)
        v[i] = {a.x + d.range(-r, r) / 2 * 2, a.y + d.range(-r, r) / 2 * 2};
      break;
    }
  }
}

InputTriangle to_input(const P v[3], const Grid& g) {
  InputTriangle t;
  for (int i = 0; i < 3; ++i) {
    t.x[i] = std::ldexp(double(clamp(v[i].x, g)), -g.shift);
    t.y[i] = std::ldexp(double(clamp(v[i].y, g)), -g.shift);
  }
  return t;
}

}  // namespace

InputTriangle draw_fuzz_triangle(FuzzDraws& d, const RasterConfig& cfg, FuzzClass c) {
  const Grid g = grid_of(cfg);
  P v[3];
  draw_class(d, g, c, v);
  // Every vertex rotation and both windings.
  const int rot = int(d.below(3));
  std::rotate(v, v + rot, v + 3);
  if (d.chance(50)) std::swap(v[1], v[2]);
  InputTriangle t = to_input(v, g);
  // Now and then a coordinate off every grid: setup's snapping is part of what is fuzzed.
  if (c == FuzzClass::Random && d.chance(20)) {
    const int i = int(d.below(3));
    const double jitter = double(d.range(-1000, 1000)) / 1e6;
    const double lim = double(cfg.coord_limit_px());
    t.x[i] = std::min(std::max(t.x[i] + jitter, -lim), lim - 1.0);
  }
  return t;
}

InputTriangle draw_fuzz_triangle(FuzzDraws& d, const RasterConfig& cfg) {
  return draw_fuzz_triangle(d, cfg, FuzzClass(d.below(uint64_t(FuzzClass::kCount))));
}

std::vector<InputTriangle> draw_fuzz_scene(FuzzDraws& d, const RasterConfig& cfg, int max_tris,
                                           std::vector<FuzzClass>* classes) {
  if (classes) classes->clear();
  max_tris = std::max(1, max_tris);
  const uint64_t size_pick = d.below(10);
  int n = size_pick < 2 ? 1 : size_pick < 6 ? int(d.range(2, 16)) : size_pick < 9 ? int(d.range(17, 64))
                                                                                  : int(d.range(65, 400));
  n = std::min(n, max_tris);
  std::vector<InputTriangle> tris;
  tris.reserve(size_t(n));
  const uint64_t mode = d.below(20);
  const Grid g = grid_of(cfg);
  if (mode < 3 && n >= 3) {
    // A closed fan around a pixel centre or a point a subpixel off one: shared edges and a shared
    // vertex, consecutive triangles with opposite windings.
    P c = anchor_point(d, g);
    if (d.chance(40)) c.x += subpixel_offset(d, g, 1);
    const int spokes = int(std::min<int64_t>(n, d.range(3, 16)));
    const double r = double(pick_size(d, g) * g.px);
    const double phase = double(d.below(360)) * M_PI / 180;
    P ring[17];
    for (int k = 0; k < spokes; ++k) {
      const double ang = phase + 2 * M_PI * k / spokes;
      ring[k] = {c.x + int64_t(std::llround(r * std::cos(ang))) / 2 * 2,
                 c.y + int64_t(std::llround(r * std::sin(ang))) / 2 * 2};
    }
    for (int k = 0; k < spokes; ++k) {
      P v[3] = {c, ring[k], ring[(k + 1) % spokes]};
      if (k % 2) std::swap(v[1], v[2]);
      tris.push_back(to_input(v, g));
      if (classes) classes->push_back(FuzzClass::kCount);  // a fan: no class of its own
    }
  }
  const FuzzClass run_class = FuzzClass(d.below(uint64_t(FuzzClass::kCount)));
  const bool one_class = mode >= 3 && mode < 8;
  while (int(tris.size()) < n) {
    // As draw_fuzz_triangle(d, cfg): the class drawn first, then the triangle.
    const FuzzClass c = one_class ? run_class : FuzzClass(d.below(uint64_t(FuzzClass::kCount)));
    tris.push_back(draw_fuzz_triangle(d, cfg, c));
    if (classes) classes->push_back(c);
  }
  return tris;
}

// ---- configuration as options -------------------------------------------------------------------

std::string config_options(const RasterConfig& cfg) {
  return "--width " + std::to_string(cfg.width) + " --height " + std::to_string(cfg.height) +
         " --subpixel-bits " + std::to_string(cfg.subpixel_bits) + " --coord-bits " +
         std::to_string(cfg.coord_int_bits) + " --box-bits " + std::to_string(cfg.box_bits) +
         " --boundary " + boundary_mode_name(cfg.boundary) + " --divider " +
         divider_mode_name(cfg.divider) + " --cull " + cull_mode_name(cfg.cull) +
         " --endpoints " + std::to_string(cfg.endpoints) + " --fifo-depth " +
         std::to_string(cfg.fifo_depth) + " --sink-stall " + cfg.sink_stall + hs_options(cfg);
}

std::string hs_options(const RasterConfig& cfg) {
  const RasterConfig d;
  const std::string form = cfg.halfspace.corner_form == d.halfspace.corner_form
                               ? ""
                               : std::string(" --hs-corner-form ") + corner_form_name(cfg.halfspace.corner_form);
  if (cfg.halfspace.stamp == d.halfspace.stamp && cfg.halfspace.tile == d.halfspace.tile && cfg.halfspace.walk == d.halfspace.walk)
    return form;
  return " --stamp " + std::to_string(cfg.halfspace.stamp) + " --tile " +
         (cfg.halfspace.tile ? std::to_string(cfg.halfspace.tile) : std::string("none")) + " --hs-walk " +
         halfspace_walk_name(cfg.halfspace.walk) + form;
}

void draw_fuzz_hs_config(FuzzDraws& d, RasterConfig& cfg, const std::vector<HalfspaceParams>& among) {
  if (!among.empty()) {
    const HalfspaceParams& c = among[d.below(among.size())];
    cfg.halfspace.stamp = c.stamp;
    cfg.halfspace.tile = c.tile;
    cfg.halfspace.walk = c.walk;
    cfg.halfspace.corner_form = c.corner_form;
  } else {
    static const int stamps[] = {1, 2, 4}, tiles[] = {0, 8, 16};
    cfg.halfspace.stamp = stamps[d.below(3)];
    cfg.halfspace.tile = tiles[d.below(3)];
    static const HalfspaceWalk walks[] = {HalfspaceWalk::Row, HalfspaceWalk::Zigzag,
                                          HalfspaceWalk::Forward};
    cfg.halfspace.walk = walks[d.below(3)];
  }
  cfg.validate();
}

RasterConfig parse_config_options(const std::string& options) {
  RasterConfig cfg;
  std::istringstream in(options);
  std::string key, value;
  auto to_int = [&](const std::string& k, const std::string& v) {
    size_t used = 0;
    int n = 0;
    try {
      n = std::stoi(v, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != v.size())
      throw std::invalid_argument(k + ": '" + v + "' is not an integer");
    return n;
  };
  while (in >> key) {
    if (!(in >> value)) throw std::invalid_argument(key + ": missing value");
    if (key == "--width") cfg.width = to_int(key, value);
    else if (key == "--height") cfg.height = to_int(key, value);
    else if (key == "--subpixel-bits") cfg.subpixel_bits = to_int(key, value);
    else if (key == "--coord-bits") cfg.coord_int_bits = to_int(key, value);
    else if (key == "--box-bits") cfg.box_bits = to_int(key, value);
    else if (key == "--boundary") cfg.boundary = parse_boundary_mode(value);
    else if (key == "--divider") cfg.divider = parse_divider_mode(value);
    else if (key == "--cull") cfg.cull = parse_cull_mode(value);
    else if (key == "--endpoints") cfg.endpoints = to_int(key, value);
    else if (key == "--fifo-depth") cfg.fifo_depth = to_int(key, value);
    else if (key == "--sink-stall") cfg.sink_stall = value;
    else if (key == "--stamp") cfg.halfspace.stamp = to_int(key, value);
    else if (key == "--tile") cfg.halfspace.tile = value == "none" ? 0 : to_int(key, value);
    else if (key == "--hs-walk") cfg.halfspace.walk = parse_halfspace_walk(value);
    else if (key == "--hs-corner-form") cfg.halfspace.corner_form = parse_corner_form(value, key);
    else throw std::invalid_argument("unknown option '" + key + "'");
  }
  cfg.validate();
  return cfg;
}

// ---- the checker --------------------------------------------------------------------------------

std::vector<FuzzDisagreement> check_engines(const std::vector<InputTriangle>& tris,
                                            const RasterConfig& cfg,
                                            const std::vector<const EngineInfo*>& engines,
                                            uint64_t* golden_pixels,
                                            std::vector<std::string>* skipped,
                                            std::vector<double>* cpu_seconds) {
  if (cpu_seconds) cpu_seconds->assign(engines.size(), 0.0);
  double t = cpu_seconds ? process_cpu_seconds() : 0.0;
  auto charge = [&](size_t i) {  // CPU time since the last charge goes to engines[i]
    if (!cpu_seconds) return;
    const double now = process_cpu_seconds();
    (*cpu_seconds)[i] += now - t;
    t = now;
  };
  const SetupResult setup = setup_scene(tris, cfg);
  EngineResult golden;
  make_golden_engine()->run(setup, cfg, golden);
  sort_spans(golden.spans);
  if (golden_pixels) *golden_pixels = uint64_t(count_pixels(golden.spans));
  for (size_t i = 0; i < engines.size(); ++i)
    if (engines[i]->name == "golden") {
      charge(i);
      break;
    }

  std::vector<FuzzDisagreement> found;
  for (size_t i = 0; i < engines.size(); ++i) {
    const EngineInfo* info = engines[i];
    if (info->name == "golden") continue;
    if (cpu_seconds) t = process_cpu_seconds();
    struct Charge {  // on every way out of this iteration
      std::function<void()> f;
      ~Charge() { f(); }
    } charged{[&, i] { charge(i); }};
    EngineResult r;
    try {
      info->make()->run(setup, cfg, r);
    } catch (const std::invalid_argument& e) {
      // A configuration this engine's build does not cover (checked before it runs).
      if (skipped) skipped->push_back(info->name);
      continue;
    } catch (const std::exception& e) {
      found.push_back({info->name, std::string("threw: ") + e.what(), {}});
      continue;
    }
    // Every span must be a non-empty run inside the viewport, of a triangle of the scene.
    bool sane = true;
    for (const Span& s : r.spans)
      if (s.y < 0 || s.y >= cfg.height || s.x_begin < 0 || s.x_end > cfg.width ||
          s.x_begin >= s.x_end || s.tri >= tris.size()) {
        found.push_back({info->name,
                         "bad span (tri " + std::to_string(s.tri) + ", y " + std::to_string(s.y) +
                             ", x " + std::to_string(s.x_begin) + ".." + std::to_string(s.x_end) +
                             ") in a " + std::to_string(cfg.width) + "x" +
                             std::to_string(cfg.height) + " viewport",
                         {s.tri}});
        sane = false;
        break;
      }
    if (!sane) continue;
    sort_spans(r.spans);
    const SpanDiff diff = diff_spans(golden.spans, r.spans);
    if (diff.exact()) continue;
    std::set<uint32_t> involved;
    for (const Span& s : diff.missing) involved.insert(s.tri);
    for (const Span& s : diff.extra) involved.insert(s.tri);
    found.push_back({info->name,
                     "missing " + std::to_string(diff.missing_pixels) + ", extra " +
                         std::to_string(diff.extra_pixels) + " pixels",
                     std::vector<uint32_t>(involved.begin(), involved.end())});
  }
  return found;
}

std::vector<InputTriangle> reduce_scene(const std::vector<InputTriangle>& tris,
                                        const RasterConfig& cfg, const EngineInfo& engine,
                                        const FuzzDisagreement& found) {
  const std::vector<const EngineInfo*> one = {&engine};
  auto still_fails = [&](const std::vector<InputTriangle>& subset) {
    try {
      return !check_engines(subset, cfg, one).empty();
    } catch (const std::exception&) {
      return false;
    }
  };
  if (!found.tris.empty() && found.tris.size() < tris.size()) {
    std::vector<InputTriangle> subset;
    for (uint32_t i : found.tris)
      if (i < tris.size()) subset.push_back(tris[i]);
    if (still_fails(subset)) return subset;
  }
  std::vector<InputTriangle> alone;
  for (size_t i = 0; i < tris.size() && alone.size() < 16; ++i)
    if (still_fails({tris[i]})) alone.push_back(tris[i]);
  if (!alone.empty()) return alone;
  return tris;  // the disagreement needs the sequence (state carried between triangles)
}

// ---- reproducers --------------------------------------------------------------------------------

std::string replay_command(const RasterConfig& cfg, const std::vector<std::string>& engines,
                           const std::string& scene_path, const std::vector<std::string>& unread) {
  std::string list;
  for (const std::string& e : engines) list += (list.empty() ? "" : ",") + e;
  // config_options() writes "--option value" pairs.
  std::istringstream in(config_options(cfg));
  std::string options, key, value;
  while (in >> key >> value)
    if (std::find(unread.begin(), unread.end(), key) == unread.end())
      options += (options.empty() ? "" : " ") + key + " " + value;
  return "trirast compare --scene " + scene_path + " --engines " + list + " " + options;
}

std::string format_reproducer(const std::vector<InputTriangle>& tris, const RasterConfig& cfg,
                              const std::vector<std::string>& engines, const std::string& note,
                              const std::string& scene_path, const std::vector<std::string>& unread) {
  std::string list;
  for (const std::string& e : engines) list += (list.empty() ? "" : ",") + e;
  std::string text = "# trirast fuzz reproducer\n# engines: " + list + "\n";
  std::istringstream notes(note);
  std::string line;
  while (std::getline(notes, line)) text += "# " + line + "\n";
  text += "# config: " + config_options(cfg) + "\n";
  text += "# replay: " + replay_command(cfg, engines, scene_path, unread) + "\n";
  char buf[256];
  for (const InputTriangle& t : tris) {
    // %.17g reads back bit for bit; grid values print short and exact (k / 2^(S+1)).
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g %.17g %.17g %.17g\n", t.x[0], t.y[0], t.x[1],
                  t.y[1], t.x[2], t.y[2]);
    text += buf;
  }
  return text;
}

RasterConfig parse_reproducer_config(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  const std::string tag = "# config:";
  while (std::getline(in, line))
    if (line.rfind(tag, 0) == 0) return parse_config_options(line.substr(tag.size()));
  return RasterConfig{};
}

}  // namespace trirast
