// One built-in per case of docs/hard-cases.md (#1 .. #18), plus hard-all.
//
// Single-triangle cases add every base triangle in all 6 vertex orders at the same place
// (triangles 6k .. 6k+5 must cover the same pixels). Closed configurations (fans, grids,
// whole-screen pairs) are added 6 times, once per vertex order, each copy in its own cell
// (add_config_all_orders), except whole-screen pairs, which necessarily overlap.
// Cells start at whole pixels, so moving a shape into a cell keeps every tie it was built on.
#include <algorithm>
#include <cmath>

#include "scene/builtin.hpp"
#include "scene/camera.hpp"
#include "scene/mesh_builders.hpp"
#include "scene/rng.hpp"

namespace trirast {

namespace {

constexpr double kPi = 3.14159265358979323846;

Scene scene_of(TriList tris) {
  Scene scene;
  scene.tris = std::move(tris);
  return scene;
}

// One subpixel step of cfg (1/256 px by default).
double subpixel(const RasterConfig& cfg) { return std::ldexp(1.0, -cfg.subpixel_bits); }

// Largest |coordinate| the hard cases use: the range minus a 1 px margin.
double coord_margin_limit(const RasterConfig& cfg) { return double(cfg.coord_limit_px()) - 1.0; }

// Adds each base triangle (cell-local) in all orders, one cell per base triangle.
void add_bases_in_cells(TriList& out, const TriList& bases, CellLayout& cells) {
  for (const InputTriangle& base : bases) {
    const auto [ox, oy] = cells.next();
    add_all_orders(out, translated(base, ox, oy));
  }
}

// #1: quads on either diagonal, rotated quad grids, fans of 3-8, strips (64 px cells).
Scene hard_shared_edges(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  TriList out;
  CellLayout cells(cfg, 64, 64);
  const TriList quad = {make_tri(3.3, 5.1, 58.7, 2.2, 61.1, 60.9), make_tri(3.3, 5.1, 61.1, 60.9,
                                                                            6.6, 59.2)};
  const TriList quad_anti = {make_tri(3.3, 5.1, 58.7, 2.2, 6.6, 59.2),
                             make_tri(58.7, 2.2, 61.1, 60.9, 6.6, 59.2)};
  add_config_all_orders(out, quad, cells);
  add_config_all_orders(out, quad_anti, cells);
  const double angles[] = {0.0, 10.0, 22.5, 30.0, 45.0, 60.0, 77.7, 90.0};
  for (double angle : angles) {
    // Grid nodes on pixel corners for "main", on pixel centres for "anti" (at angle 0).
    add_config_all_orders(out, make_quad_grid(32.0, 32.0, 4, 4, 10.0, angle, "main"), cells);
    add_config_all_orders(out, make_quad_grid(32.5, 32.5, 4, 4, 10.0, angle, "anti"), cells);
  }
  for (int n = 3; n <= 8; ++n) {
    add_config_all_orders(out, make_fan(32.5, 32.5, n, 28.0, 0.0), cells);
    add_config_all_orders(out, make_fan(32.3137, 32.2718, n, 28.0, 13.0), cells);
  }
  add_config_all_orders(out, make_strip(3.0, 61.0, 32.0, 12, 16.0, 10.0, 1.0), cells);
  add_config_all_orders(out, make_strip(2.5, 60.5, 32.5, 10, 16.0, 0.0, 0.0), cells);
  return scene_of(out);
}

// #2: axis-aligned edges on pixel-centre lines and 45-degree (and 2:1) edges through centres.
Scene hard_centre_edges(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  const TriList bases = {
      make_tri(4.5, 4.5, 24.5, 4.5, 4.5, 24.5),     make_tri(24.5, 4.5, 24.5, 24.5, 4.5, 4.5),
      make_tri(24.5, 24.5, 4.5, 24.5, 24.5, 4.5),   make_tri(4.5, 24.5, 4.5, 4.5, 24.5, 24.5),
      make_tri(4.0, 4.0, 24.0, 4.0, 4.0, 24.0),     // axis edges on pixel borders, for contrast
      make_tri(4.5, 4.5, 24.5, 24.5, 4.5, 24.5),    // 45 degrees through centres
      make_tri(24.5, 4.5, 4.5, 24.5, 24.5, 24.5),   // -45 degrees
      make_tri(4.5, 4.5, 14.5, 24.5, 4.5, 24.5),    // 2:1, centres every other row
      make_tri(4.5, 4.5, 24.5, 14.5, 4.5, 14.5),    // 1:2
      make_tri(14.5, 2.5, 26.5, 14.5, 2.5, 14.5),   // diamond half, two 45-degree edges
  };
  TriList out;
  CellLayout cells(cfg, 32, 32);
  add_bases_in_cells(out, bases, cells);
  return scene_of(out);
}

// #3: a vertex exactly on a pixel centre as top, bottom, left-middle and right-middle vertex.
Scene hard_vertex_on_centre(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  const double c = 16.5;
  const TriList bases = {
      make_tri(c, c - 10, c - 7.3, c + 1.1, c + 9.2, c + 10.4),  // c - 10: also on a centre
      make_tri(c, c, c - 7.3, c + 11.1, c + 9.2, c + 10.4),      // top vertex
      make_tri(c, c, c - 7.3, c - 11.1, c + 9.2, c - 10.4),      // bottom vertex
      make_tri(c, c, c + 10.0, c - 9.3, c + 12.2, c + 8.9),      // left-middle vertex
      make_tri(c, c, c - 10.0, c - 9.3, c - 12.2, c + 8.9),      // right-middle vertex
      make_tri(c, c, c - 8.0, c + 10.3, c + 8.0, c + 10.3),      // top vertex over a flat bottom
      make_tri(4.5, 4.5, 24.5, 8.5, 10.5, 26.5),                 // all three on centres
  };
  TriList out;
  CellLayout cells(cfg, 32, 32);
  add_bases_in_cells(out, bases, cells);
  return scene_of(out);
}

// #4: flat tops and bottoms on a centre row (and off it), a diamond split on a centre row.
Scene hard_horizontal_edges(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  const TriList bases = {
      make_tri(4.3, 8.5, 27.6, 8.5, 15.2, 26.1),    // flat top on a centre row (included)
      make_tri(4.3, 24.5, 27.6, 24.5, 15.2, 5.1),   // flat bottom on a centre row (excluded)
      make_tri(4.3, 8.0, 27.6, 8.0, 15.2, 26.1),    // flat top on a pixel border
      make_tri(4.3, 24.0, 27.6, 24.0, 15.2, 5.1),   // flat bottom on a pixel border
      make_tri(16.2, 3.1, 28.3, 16.5, 4.1, 16.5),   // diamond: upper half, edge on a centre row
      make_tri(4.1, 16.5, 28.3, 16.5, 16.2, 29.8),  // diamond: lower half
      make_tri(4.5, 8.5, 27.5, 8.5, 16.0, 9.5),     // one row tall: top and bottom on centres
  };
  TriList out;
  CellLayout cells(cfg, 32, 32);
  add_bases_in_cells(out, bases, cells);
  return scene_of(out);
}

// #5: the middle vertex on a centre row, level with the top or bottom vertex, or one step off.
Scene hard_middle_vertex_row(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  const double u = subpixel(cfg);
  const TriList bases = {
      make_tri(10.3, 3.2, 26.7, 14.5, 5.9, 28.8),       // right middle vertex on a centre row
      make_tri(20.3, 3.2, 4.1, 14.5, 25.9, 28.8),       // left middle vertex on a centre row
      make_tri(10.3, 3.2, 26.7, 14.5 + u, 5.9, 28.8),   // one step below the row
      make_tri(10.3, 3.2, 26.7, 14.5 - u, 5.9, 28.8),   // one step above the row
      make_tri(5.2, 4.3, 26.8, 4.3, 12.1, 27.7),        // level with the top vertex
      make_tri(5.2, 4.3, 26.8, 4.3 + u, 12.1, 27.7),    // one step below the top vertex
      make_tri(5.2, 27.7, 26.8, 27.7, 12.1, 4.3),       // level with the bottom vertex
      make_tri(5.2, 27.7, 26.8, 27.7 - u, 12.1, 4.3),   // one step above the bottom vertex
      make_tri(5.2, 4.5, 26.8, 4.5, 12.1, 27.5),        // level with the top, on centre rows
  };
  TriList out;
  CellLayout cells(cfg, 32, 32);
  add_bases_in_cells(out, bases, cells);
  return scene_of(out);
}

// #6: vertical edges (dx = 0) and near-vertical ones (dx = +-1..3 steps) over thousands of rows.
Scene hard_vertical(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  const double u = subpixel(cfg);
  // Edges run from `extra` px above the viewport to `extra` px below it.
  const double extra = std::max(0.0, std::min(4000.0, coord_margin_limit(cfg) - cfg.height));
  const double top = -extra, bottom = cfg.height + extra, mid = 0.5 * cfg.height;
  const double dxs[] = {0.0, u, -u, 3 * u};
  TriList out;
  double x = 8.5;
  auto next_column = [&]() { x = x + 16.0 < cfg.width ? x + 16.0 : 8.5; };
  for (double dx : dxs)
    for (double offset : {0.0, -0.5, 0.3}) {  // on centres, on pixel borders, anywhere
      const double x0 = x + offset;
      add_all_orders(out, make_tri(x0, top, x0 + dx, bottom, x0 + 6.3, mid));        // left edge
      add_all_orders(out, make_tri(x0 + 9.0, top, x0 + 9.0 + dx, bottom, x0 + 2.7, mid + 0.4));
      add_all_orders(out, make_tri(x0, 0.5, x0 + dx, cfg.height - 0.5, x0 + 4.1, mid));
      next_column();
    }
  return scene_of(out);
}

// #7: near-horizontal edges: dy of 1-3 subpixel steps, dx up to the whole coordinate range.
Scene hard_near_horizontal(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  const double u = subpixel(cfg), far = coord_margin_limit(cfg) - 1.0;
  TriList out;
  double y = 10.5;
  for (int steps = 1; steps <= 3; ++steps)
    for (double sign : {1.0, -1.0})
      for (double y_offset : {0.0, 0.5 * u, 0.37}) {  // on a centre row, a half step, anywhere
        const double y0 = y + y_offset, y1 = y0 + sign * steps * u;
        // Whole range wide, third vertex below or above.
        add_all_orders(out, make_tri(-far, y0, far, y1, 0.5 * cfg.width + 7.3, y0 + 9.7));
        add_all_orders(out, make_tri(-far, y0, far, y1, 0.5 * cfg.width - 5.1, y0 - 4.9));
        // Viewport wide.
        add_all_orders(out, make_tri(0.3, y0, cfg.width - 0.3, y1, 0.25 * cfg.width, y0 + 3.3));
        y = y + 14.0 < cfg.height ? y + 14.0 : 10.5;
      }
  return scene_of(out);
}

// #8: slivers: third vertex within 0.02 px of the opposite edge; 1 px wide and 1000+ px long.
Scene hard_slivers(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  const double w = cfg.width, h = cfg.height;
  TriList out;
  const double distances[] = {0.02, 0.01, 0.005, -0.02, 1.0 / 512};
  int k = 0;
  for (double angle : {3.0, 31.0, 58.0, 90.0, 123.0}) {
    // Edge a-b of length ~0.6 of the smaller side; c just off its midpoint along the normal.
    const double len = 0.3 * std::min(w, h), rad = angle * kPi / 180.0;
    const double dx = std::cos(rad) * len, dy = std::sin(rad) * len;
    const double cx = 0.5 * w + 0.173 * k, cy = 0.5 * h + 0.311 * k;
    for (double d : distances) {
      add_all_orders(out, make_tri(cx - dx, cy - dy, cx + dx, cy + dy, cx - dy / len * d,
                                   cy + dx / len * d));
      ++k;
    }
  }
  // 1 px wide, 1050+ px tall (off-screen ends), 1 px tall, 1200 px wide, and a long diagonal.
  for (double x : {10.13, 100.5, 0.25 * w + 0.37}) {
    add_all_orders(out, make_tri(x, -150.0, x + 1.0, -150.0, x + 0.5, h + 300.0));
    add_all_orders(out, make_tri(-100.0, x, w + 100.0, x + 0.7, -100.0, x + 1.2));
  }
  add_all_orders(out, make_tri(0.2, 0.3, w - 0.4, h - 0.1, w - 1.3, h - 0.2));
  return scene_of(out);
}

// #9: degenerate after snapping: collinear, repeated or equal vertices; float-valid triangles
// that collapse or flip winding at the subpixel grid.
Scene hard_degenerate(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  const double u = subpixel(cfg);
  const TriList bases = {
      make_tri(4.25, 4.5, 14.25, 14.5, 24.25, 24.5),         // exactly collinear
      make_tri(4.1, 4.2, 14.1, 14.2, 24.1, 24.2),            // collinear in decimal only
      make_tri(4.5, 4.5, 4.5, 4.5, 20.3, 17.9),              // repeated vertex
      make_tri(10.3, 10.3, 10.3, 10.3, 10.3, 10.3),          // all three equal
      make_tri(4.0, 4.0, 20.0, 4.0 + 0.25 * u, 12.0, 4.0 - 0.25 * u),  // collapses to a line
      make_tri(4.0, 4.0, 14.0, 4.0 + 0.49 * u, 24.0, 4.0 + 0.51 * u),  // flips winding
      make_tri(4.0, 4.0, 24.0, 4.0, 14.0, 4.0 + u),          // smallest non-zero area
      make_tri(4.0, 4.0, 4.0 + 0.3 * u, 4.0 + 0.2 * u, 4.0 - 0.1 * u, 4.0 + 0.4 * u),  // a point
  };
  TriList out;
  CellLayout cells(cfg, 32, 32);
  add_bases_in_cells(out, bases, cells);
  return scene_of(out);
}

// #10: tiny triangles holding 0, 1 or 2 centres, between centres, or touching one; plus random
// tiny ones on the subpixel grid.
Scene hard_tiny(const BuiltinParams& p, const RasterConfig& cfg, const CameraOptions&) {
  const int64_t count = p.integer("count", 0, 1000000);
  const TriList bases = {
      make_tri(2.2, 2.3, 2.8, 2.25, 2.55, 2.8),    // one centre
      make_tri(1.4, 2.45, 3.6, 2.5, 1.4, 2.6),     // two centres
      make_tri(1.6, 1.6, 1.9, 1.7, 1.7, 1.95),     // between centres
      make_tri(1.3, 1.9, 3.7, 3.3, 3.7, 3.15),     // box holds 4 centres, triangle none
      make_tri(2.2, 2.5, 2.8, 2.5, 2.5, 2.9),      // centre on a top edge (in)
      make_tri(2.2, 2.5, 2.5, 2.1, 2.8, 2.5),      // centre on a bottom edge (out)
      make_tri(2.5, 2.5, 2.9, 2.6, 2.6, 2.9),      // vertex on the centre
      make_tri(2.5, 2.5, 2.1, 2.6, 2.4, 2.9),      // vertex on the centre, other side
  };
  TriList out;
  CellLayout cells(cfg, 8, 8);
  add_bases_in_cells(out, bases, cells);
  SceneRng rng(p.seed());
  const double u = subpixel(cfg);
  for (int64_t i = 0; i < count; ++i) {
    // Vertices within 1 px of a random point of the 4x4 cell, on the subpixel grid.
    const double cx = 2.0 + rng.uniform(0.0, 4.0), cy = 2.0 + rng.uniform(0.0, 4.0);
    double v[6];
    for (int k = 0; k < 6; ++k)
      v[k] = std::nearbyint(((k % 2) ? cy : cx) / u + rng.uniform(-0.7, 0.7) / u) * u;
    const auto [ox, oy] = cells.next();
    add_all_orders(out, translated(make_tri(v[0], v[1], v[2], v[3], v[4], v[5]), ox, oy));
  }
  return scene_of(out);
}

// #11: vertices near the ends of the coordinate range with small visible parts.
Scene hard_large_coords(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  const double L = coord_margin_limit(cfg), w = cfg.width, h = cfg.height;
  TriList out;
  add_all_orders(out, make_tri(-L, -L, L, -L + 0.37, -L + 0.61, L));  // covers everything
  // Only a small corner near (0, 0) is visible: region x + y < 15.3.
  add_all_orders(out, make_tri(L - 3.1, 15.3 - L + 3.1, 15.3 - L + 2.2, L - 2.2, -L, -L));
  // Only a small corner near (w, h) is visible: region x + y > w + h - 15.7.
  const double s = w + h - 15.7;
  add_all_orders(out, make_tri(s - L + 3.1, L - 3.1, L - 2.2, s - L + 2.2, L, L));
  // Diagonal edges from one end of the range to the other across the viewport: |dx| + |dy| near
  // its largest, each placed so that it enters 8- and 16-pixel tiles near a corner, where a tile
  // it crosses holds pixels up to 14 (30) pixel sums inside it: there a tile unit's
  // tile-relative stamp values span their widest (docs/unit.md). Beyond x + y = d1 (pixel centre
  // sums 16k + 2 and up), and beyond y - x = d2 (differences 16k - 7 and up).
  const double d1 = 16.0 * std::floor((w + h) / 32.0) + 1.3;
  const double d2 = 16.0 * std::floor((h - w) / 32.0) - 7.7;
  add_all_orders(out, make_tri(L, d1 - L, d1 - L, L, L, L));
  const double x1 = -L + std::max(0.0, -d2), x2 = L - std::max(0.0, d2);
  add_all_orders(out, make_tri(x1, x1 + d2, x2, x2 + d2, -L, L));
  // Thin bands across the viewport with far-away vertices.
  add_all_orders(out, make_tri(-L, 100.25, L, 130.75, -L, 101.5));
  add_all_orders(out, make_tri(200.5, -L, 231.25, L, 203.75, -L));
  // Entirely off-screen, at the corners of the range.
  add_all_orders(out, make_tri(L - 10.0, L - 10.0, L, L - 5.0, L - 3.0, L));
  add_all_orders(out, make_tri(-L, -L, -L + 10.5, -L + 0.5, -L + 0.5, -L + 7.5));
  return scene_of(out);
}

// #12: negative coordinates, straddling x = 0, y = 0 and the corner.
Scene hard_negative(const BuiltinParams&, const RasterConfig&, const CameraOptions&) {
  const TriList bases = {
      make_tri(-5.3, 10.2, 12.7, 4.4, -2.1, 30.9),   // straddles x = 0
      make_tri(10.2, -5.3, 30.9, -2.1, 4.4, 12.7),   // straddles y = 0
      make_tri(-7.7, -3.3, 9.1, -6.6, -4.2, 11.8),   // straddles the corner
      make_tri(-0.5, 3.5, 6.5, -0.5, -0.5, -0.5),    // vertices on centres of pixel -1
      make_tri(-20.3, -10.1, -3.7, -15.2, -9.9, -2.2),  // wholly negative
      make_tri(-3.3, 5.7, 7.2, -2.6, 2.9, 9.9),      // negative fractions: floor vs truncate
      make_tri(-1000.7, -3.2, 20.4, 0.6, -300.1, 25.3),  // long negative reach
  };
  TriList out;
  for (const InputTriangle& t : bases) add_all_orders(out, t);
  return scene_of(out);
}

// #13: vertices exactly halfway between two subpixel steps, positive, negative and around 0.
Scene hard_snap_ties(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  const double h = 0.5 * subpixel(cfg);  // odd multiples of h are ties
  const TriList bases = {
      make_tri(10 + h, 10 + 3 * h, 30 + 5 * h, 10 + 7 * h, 12 + 9 * h, 28 + 11 * h),
      make_tri(10 - h, 10 - 3 * h, 30 - 5 * h, 10 - 7 * h, 12 - 9 * h, 28 - 11 * h),
      make_tri(-5 - h, 8 + h, 20 + 3 * h, -4 - 3 * h, 6 - 5 * h, 22 - 7 * h),
      make_tri(h, -h, 25 - h, h, -h, 20 + h),         // ties around zero, both signs
      make_tri(-h, -h, -25 - h, -3 * h, -5 * h, -20 - h),  // wholly negative ties
      make_tri(5.5 + h, 5.5 - h, 15.5 - h, 5.5 + h, 5.5 - h, 15.5 + h),  // ties at centres
      make_tri(4 + h, 4 + h, 24 + 3 * h, 4 + 5 * h, 14 + 7 * h, 4 + 9 * h),  // thin, all ties
  };
  TriList out;
  for (const InputTriangle& t : bases) {
    add_all_orders(out, t);
    add_all_orders(out, translated(t, 64.0, 32.0));  // the same ties with other integer parts
  }
  return scene_of(out);
}

// #14: spans starting or ending at x = 0, W-1, on multiples of 8/16/32/64; 4x4-block triangles.
Scene hard_viewport_edges(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  const double w = cfg.width, h = cfg.height;
  TriList out;
  for (double x : {0.0, 0.5, -0.5}) {  // left border: on it, on centre 0, on centre -1
    add_all_orders(out, make_tri(x, 10.3, x, 50.7, x + 20.2, 30.1));
    add_all_orders(out, make_tri(w - x, 10.3, w - x, 50.7, w - x - 20.2, 30.1));
    add_all_orders(out, make_tri(10.3, x, 50.7, x, 30.1, x + 20.2));
    add_all_orders(out, make_tri(10.3, h - x, 50.7, h - x, 30.1, h - x - 20.2));
  }
  // Spans that start and end on tile boundaries (on the border, or on the centre beside it).
  double y = 60.5;
  for (double tile : {8.0, 16.0, 32.0, 64.0})
    for (double x : {3 * tile, 3 * tile - 0.5, 3 * tile + 0.5}) {
      add_all_orders(out, make_tri(x, y, x + 12.3, y + 8.2, x, y + 16.0));           // starts
      add_all_orders(out, make_tri(x + tile, y, x + tile, y + 16.0, x + 3.1, y + 8.7));  // ends
      y = y + 20.0 < h - 20.0 ? y + 20.0 : 60.5;
    }
  // Inside one 4x4 block: at the first, last and a middle block of the viewport.
  const double last_bx = std::floor((w - 4.0) / 4.0) * 4.0, last_by = std::floor((h - 4.0) / 4.0) * 4.0;
  for (auto [bx, by] : {std::pair<double, double>{0.0, 0.0}, {last_bx, last_by},
                        {std::floor(w / 8.0) * 4.0, std::floor(h / 8.0) * 4.0}}) {
    add_all_orders(out, make_tri(bx + 0.6, by + 0.7, bx + 3.4, by + 1.2, bx + 1.9, by + 3.3));
    add_all_orders(out, make_tri(bx, by, bx + 4.0, by, bx, by + 4.0));
  }
  // Corners that stick out of the viewport.
  add_all_orders(out, make_tri(w - 5.3, h - 7.1, w + 6.2, h - 2.2, w - 1.1, h + 4.4));
  add_all_orders(out, make_tri(-6.2, -2.2, 5.3, 7.1, 1.1, -4.4));
  return scene_of(out);
}

// #15: pairs covering the viewport: both diagonals, rotated larger squares, partly off-screen.
// Each pair is added in all 6 vertex orders; the pairs are consecutive and overlap each other.
Scene hard_whole_screen(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  const double w = cfg.width, h = cfg.height;
  auto add_pair_all_orders = [](TriList& out, const InputTriangle& a, const InputTriangle& b) {
    for (int reversed = 0; reversed < 2; ++reversed)
      for (int rotation = 0; rotation < 3; ++rotation) {
        out.push_back(vertex_order(a, rotation, reversed != 0));
        out.push_back(vertex_order(b, rotation, reversed != 0));
      }
  };
  auto add_rect = [&](TriList& out, const double x[4], const double y[4]) {
    add_pair_all_orders(out, make_tri(x[0], y[0], x[1], y[1], x[2], y[2]),
                        make_tri(x[0], y[0], x[2], y[2], x[3], y[3]));
    add_pair_all_orders(out, make_tri(x[0], y[0], x[1], y[1], x[3], y[3]),
                        make_tri(x[1], y[1], x[2], y[2], x[3], y[3]));
  };
  TriList out;
  const double sx[4] = {0, w, w, 0}, sy[4] = {0, 0, h, h};
  add_rect(out, sx, sy);
  // Squares about the centre, large enough to cover the viewport, small enough for the range.
  const double half = std::min(0.75 * (w + h),
                               (coord_margin_limit(cfg) - 0.5 * std::max(w, h)) / std::sqrt(2.0));
  for (double angle : {10.0, 30.0, 45.0, 73.0}) {
    const double c = std::cos(angle * kPi / 180.0), s = std::sin(angle * kPi / 180.0);
    const double u[4] = {-half, half, half, -half}, v[4] = {-half, -half, half, half};
    double x[4], y[4];
    for (int i = 0; i < 4; ++i) x[i] = 0.5 * w + c * u[i] - s * v[i], y[i] = 0.5 * h + s * u[i] + c * v[i];
    add_rect(out, x, y);
  }
  const double ox = std::floor(w / 3), oy = -std::floor(h / 4);  // partly off-screen
  const double px[4] = {ox, w + ox, w + ox, ox}, py[4] = {oy, oy, h + oy, h + oy};
  add_rect(out, px, py);
  return scene_of(out);
}

// #16: closed fans whose common vertex is a pixel centre (exactly one triangle owns it).
Scene hard_one_vertex(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  TriList out;
  CellLayout cells(cfg, 64, 64);
  for (int n : {3, 4, 5, 6, 8, 12, 16})
    for (double rotation : {0.0, 45.0, 17.3}) add_config_all_orders(
        out, make_fan(32.5, 32.5, n, 24.0, rotation), cells);
  return scene_of(out);
}

// #17: T-junctions: a vertex of some triangles on another triangle's edge.
Scene hard_t_junctions(const BuiltinParams&, const RasterConfig& cfg, const CameraOptions&) {
  // Square a b c d split along b-d; the half b c d is split again at e on b-d.
  auto t_config = [](double ax, double ay, double bx, double by, double cx, double cy, double dx,
                     double dy, double t) {
    const double ex = bx + (dx - bx) * t, ey = by + (dy - by) * t;
    return TriList{make_tri(ax, ay, bx, by, dx, dy), make_tri(bx, by, cx, cy, ex, ey),
                   make_tri(ex, ey, cx, cy, dx, dy)};
  };
  TriList out;
  CellLayout cells(cfg, 64, 64);
  add_config_all_orders(out, t_config(4, 4, 60, 4, 60, 60, 4, 60, 0.5), cells);
  add_config_all_orders(out, t_config(4, 4, 60, 4, 60, 60, 4, 60, 1.0 / 3.0), cells);
  add_config_all_orders(out, t_config(4.5, 4.5, 60.5, 4.5, 60.5, 60.5, 4.5, 60.5, 0.5), cells);
  add_config_all_orders(out, t_config(20.1, 2.3, 61.2, 20.7, 43.9, 61.8, 2.8, 43.4, 0.37), cells);
  // A horizontal edge on a centre row with two triangles below meeting at its middle.
  add_config_all_orders(out, TriList{make_tri(4, 40.5, 32, 8, 60, 40.5),
                                     make_tri(4, 40.5, 32, 40.5, 18, 60),
                                     make_tri(32, 40.5, 60, 40.5, 46, 60)},
                        cells);
  return scene_of(out);
}

// #18: a terrain with objects seen from a camera standing on it: ground triangles behind the
// camera are dropped, those beside it are cut by the near plane, and shared vertices must stay
// bit-identical between neighbours.
Scene hard_projected(const BuiltinParams& p, const RasterConfig& cfg, const CameraOptions& cam) {
  const int res = int(p.integer("res", 2, 1000));
  const int views = int(p.integer("views", 1, 64));
  SceneRng rng(p.seed());
  Mesh world = make_height_field(res, "waves", 0.3, 10.0, glm::dvec3(0.0));
  world.append(make_uv_sphere(16, 32, 0.35, glm::dvec3(0.45, 0.6, -0.2)));  // cut by the near plane
  world.append(make_torus(48, 24, 1.5, 0.4, glm::dvec3(0.0, 0.8, -5.0)));
  world.append(make_box(glm::dvec3(0.5), glm::dvec3(-2.0, 0.5, -3.0)));
  Scene scene;
  for (int v = 0; v < views; ++v) {
    CameraView view;
    view.fov_deg = cam.fov_deg;
    const double yaw = rng.uniform(-0.3, 0.3);  // radians around the looking direction -z
    view.eye = glm::dvec3(0.0, 0.6, 0.0);
    view.target = view.eye + glm::dvec3(std::sin(yaw), -0.1, -std::cos(yaw));
    view.near_plane = cam.near_plane > 0.0 ? cam.near_plane : 0.25;
    project_mesh(world, view, cfg, scene);
  }
  return scene;
}

const std::vector<BuiltinEntry>& single_hard_entries() {
  static const std::vector<BuiltinEntry> entries = {
      {"hard-shared-edges", "#1 quads on both diagonals, rotated quad grids, fans 3-8, strips",
       {}, hard_shared_edges},
      {"hard-centre-edges", "#2 axis and 45-degree edges through pixel centres", {},
       hard_centre_edges},
      {"hard-vertex-on-centre", "#3 a vertex on a pixel centre (top/bottom/left/right)", {},
       hard_vertex_on_centre},
      {"hard-horizontal-edges", "#4 flat tops/bottoms and a horizontal middle edge on centre rows",
       {}, hard_horizontal_edges},
      {"hard-middle-vertex-row", "#5 middle vertex on a centre row or level with top/bottom", {},
       hard_middle_vertex_row},
      {"hard-vertical", "#6 vertical and near-vertical edges over thousands of rows", {},
       hard_vertical},
      {"hard-near-horizontal", "#7 edges with dy of 1-3 subpixels and dx up to the full range",
       {}, hard_near_horizontal},
      {"hard-slivers", "#8 slivers: apex within 0.02 px of the base; 1 px x 1000+ px", {},
       hard_slivers},
      {"hard-degenerate", "#9 collinear, repeated, equal, collapsing or flipping at the snap", {},
       hard_degenerate},
      {"hard-tiny", "#10 sub-pixel triangles holding 0, 1 or 2 centres, plus random tiny ones",
       {{"count", "200", ""}, {"seed", "1", ""}}, hard_tiny},
      {"hard-large-coords", "#11 vertices near the ends of the coordinate range", {},
       hard_large_coords},
      {"hard-negative", "#12 negative coordinates, straddling x = 0 and y = 0", {},
       hard_negative},
      {"hard-snap-ties", "#13 vertices exactly halfway between subpixel steps, both signs", {},
       hard_snap_ties},
      {"hard-viewport-edges", "#14 spans at x = 0, W-1, tile multiples; 4x4-block triangles", {},
       hard_viewport_edges},
      {"hard-whole-screen", "#15 triangle pairs covering the viewport, rotated, off-screen", {},
       hard_whole_screen},
      {"hard-one-vertex", "#16 closed fans of 3-16 meeting at a pixel centre", {},
       hard_one_vertex},
      {"hard-t-junctions", "#17 T-junctions: a vertex on another triangle's edge", {},
       hard_t_junctions},
      {"hard-projected", "#18 terrain and objects, camera on the ground, near-plane cuts",
       {{"res", "40", ""}, {"views", "3", ""}, {"seed", "1", ""}}, hard_projected},
  };
  return entries;
}

// hard-all: every hard case with its defaults, one after the other (seed passed on).
Scene hard_all(const BuiltinParams& p, const RasterConfig& cfg, const CameraOptions& cam) {
  const std::string seed = std::to_string(p.seed());
  Scene all;
  for (const BuiltinEntry& e : single_hard_entries()) {
    std::vector<std::pair<std::string, std::string>> given;
    for (const KeySpec& k : e.keys)
      if (std::string(k.key) == "seed") given.emplace_back("seed", seed);
    const Scene part = e.make(BuiltinParams(e.name, e.keys, given), cfg, cam);
    all.tris.insert(all.tris.end(), part.tris.begin(), part.tris.end());
    all.near_clipped += part.near_clipped;
    all.near_dropped += part.near_dropped;
    all.range_dropped += part.range_dropped;
    all.mesh_faces += part.mesh_faces;
    all.mesh_pieces += part.mesh_pieces;
  }
  return all;
}

}  // namespace

const std::vector<BuiltinEntry>& hard_case_entries() {
  static const std::vector<BuiltinEntry> entries = [] {
    std::vector<BuiltinEntry> list = single_hard_entries();
    list.push_back({"hard-all", "every hard-* scene above, concatenated", {{"seed", "1", ""}},
                    hard_all});
    return list;
  }();
  return entries;
}

}  // namespace trirast
