// What many tests build their scenes and configurations from: a triangle from six coordinates,
// the golden's sorted spans, configurations of a given precision, viewport and widths, random
// triangles with far-away vertices, and the half-space unit's stamp / tile / walk shapes. Header
// only: the model-only test programs (tests/CMakeLists.txt) include it without linking
// trirast_test_support.
#pragma once
#include <string>
#include <vector>

#include "common/config.hpp"
#include "common/reference_raster.hpp"
#include "common/setup.hpp"
#include "golden/golden.hpp"

namespace trirast::test {

// The triangle (x0, y0), (x1, y1), (x2, y2), in pixels.
inline InputTriangle tri(double x0, double y0, double x1, double y1, double x2, double y2) {
  InputTriangle t{};
  t.x[0] = x0, t.y[0] = y0, t.x[1] = x1, t.y[1] = y1, t.x[2] = x2, t.y[2] = y2;
  return t;
}

// The golden's spans of every set-up triangle, sorted: what the engines are held against.
inline SpanList golden_spans(const SetupResult& setup, const RasterConfig& cfg) {
  SpanList spans;
  for (const TriangleSetup& t : setup.tris) golden_triangle(t, cfg, spans);
  sort_spans(spans);
  return spans;
}

// The default configuration with `subpixel_bits` of precision and a width x height viewport.
inline RasterConfig config_at(int subpixel_bits, int width, int height) {
  RasterConfig cfg;
  cfg.subpixel_bits = subpixel_bits;
  cfg.width = width;
  cfg.height = height;
  return cfg;
}

// config_at with the coordinate range's and the box's widths too, validated (throws
// std::invalid_argument on a combination the configuration refuses).
inline RasterConfig config_with_widths(int subpixel_bits, int coord_int_bits, int box_bits,
                                       int width, int height) {
  RasterConfig cfg = config_at(subpixel_bits, width, height);
  cfg.coord_int_bits = coord_int_bits;
  cfg.box_bits = box_bits;
  cfg.validate();
  return cfg;
}

// `count` triangles with one vertex near the viewport (in [-50, near_x) x [-50, near_y) pixels)
// and two far away near the +-32768 limit, all on the 1/256 grid.
inline std::vector<InputTriangle> far_vertex_triangles(TestRng& rng, int count, int near_x,
                                                       int near_y) {
  std::vector<InputTriangle> tris;
  for (int n = 0; n < count; ++n) {
    InputTriangle t{};
    t.x[0] = double(rng.range(-256 * 50, 256 * near_x)) / 256;
    t.y[0] = double(rng.range(-256 * 50, 256 * near_y)) / 256;
    for (int i = 1; i < 3; ++i) {
      t.x[i] = double(rng.range(-32768 * 256, 32767 * 256)) / 256;
      t.y[i] = double(rng.range(-32768 * 256, 32767 * 256)) / 256;
    }
    tris.push_back(t);
  }
  return tris;
}

// One shape of the half-space unit: stamp size, tile size (0: no tiles), walk order and the
// set-up's corner form (0 products, 1 radix 16).
struct HalfspaceShape {
  int stamp, tile;
  HalfspaceWalk walk;
  int corner_form = 0;
};

// Every shape the unit supports: stamps 1, 2, 4 x tiles none, 8, 16 x row, zig-zag and forward
// walks.
inline std::vector<HalfspaceShape> every_halfspace_shape() {
  std::vector<HalfspaceShape> shapes;
  for (int stamp : {1, 2, 4})
    for (int tile : {0, 8, 16})
      for (HalfspaceWalk walk : {HalfspaceWalk::Row, HalfspaceWalk::Zigzag, HalfspaceWalk::Forward})
        shapes.push_back({stamp, tile, walk});
  return shapes;
}

// "stamp S tile T walk [radix16]", for failure messages.
inline std::string halfspace_shape_name(const HalfspaceShape& shape) {
  return "stamp " + std::to_string(shape.stamp) + " tile " + std::to_string(shape.tile) + " " +
         halfspace_walk_name(shape.walk) + (shape.corner_form ? " radix16" : "");
}

// `cfg` with the half-space unit set to `shape`.
inline RasterConfig with_halfspace_shape(RasterConfig cfg, const HalfspaceShape& shape) {
  cfg.halfspace.stamp = shape.stamp;
  cfg.halfspace.tile = shape.tile;
  cfg.halfspace.walk = shape.walk;
  cfg.halfspace.corner_form = shape.corner_form;
  return cfg;
}

}  // namespace trirast::test
