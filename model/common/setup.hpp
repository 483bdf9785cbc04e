// Triangle setup: done once, in one place, for every engine (architecture.md).
// Snap to fixed point, orient, cull, build edge functions with the top-left bias, and compute the
// pixel bounding box clipped to the viewport. Engines never re-derive any of this.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/config.hpp"

namespace trirast {

// A scene triangle as read: floating-point pixel coordinates, y down, origin top-left.
struct InputTriangle {
  double x[3];
  double y[3];
  int line = 0;  // source line for text input, 0 otherwise
};

struct Vec2i {
  int64_t x;
  int64_t y;
};

// Edge function E(p) = A*p.x + B*p.y + C in frac_bits() units; a pixel centre c is inside the
// edge iff E(c) + bias >= 0.
struct EdgeSetup {
  int64_t A;
  int64_t B;
  int64_t C;
  int bias;  // 0 for a top-left edge, -1 otherwise

  int64_t eval(int64_t x, int64_t y) const { return A * x + B * y + C; }
};

// Pixel bounding box, inclusive on both ends. Empty when x0 > x1 or y0 > y1.
struct PixelBox {
  int32_t x0, y0, x1, y1;
  bool empty() const { return x0 > x1 || y0 > y1; }
  int64_t width() const { return empty() ? 0 : int64_t(x1) - x0 + 1; }
  int64_t height() const { return empty() ? 0 : int64_t(y1) - y0 + 1; }
};

struct TriangleSetup {
  uint32_t index;     // scene index of the triangle
  Vec2i v[3];         // snapped vertices in frac_bits() units, ordered so that area2 > 0
  EdgeSetup edge[3];  // edge i runs from v[i] to v[(i+1)%3]
  int64_t area2;      // twice the signed area, > 0
  bool swapped;       // v1 and v2 were swapped to make area2 > 0 (the input ran counter-clockwise
                      // as seen on screen: a front face)
  PixelBox box;       // pixels whose centres lie within the snapped vertex extent, clipped to viewport
};

struct SetupCounts {
  uint64_t read = 0;             // triangles handed to setup (a mesh's after near-plane clipping)
  uint64_t degenerate = 0;       // area2 == 0 after snapping
  uint64_t culled = 0;           // removed by --cull
  uint64_t offscreen = 0;        // accepted, and the snapped vertex extent misses the viewport
  uint64_t no_pixel_centre = 0;  // accepted, and no pixel centre inside the clipped bounding box
                                 // (tiny triangles on screen and every off-screen one)
  uint64_t accepted = 0;         // handed to the engines (offscreen ones included)
};

struct SetupResult {
  std::vector<TriangleSetup> tris;  // accepted triangles, in scene order
  SetupCounts counts;
};

// Raised for input that the configuration cannot represent (non-finite, out of range).
class SetupError : public std::runtime_error {
 public:
  SetupError(const std::string& msg, uint32_t tri, int line)
      : std::runtime_error(msg), tri(tri), line(line) {}
  uint32_t tri;
  int line;
};

// Round-to-nearest-even snap of one coordinate to S fractional bits. Throws SetupError when the
// value is NaN, infinite, or outside [-2^(coord_int_bits-1), 2^(coord_int_bits-1)) pixels.
int64_t snap_coordinate(double value, const RasterConfig& cfg, uint32_t tri, int line);

// Sets up one triangle. Returns false (and fills `why` with "degenerate" or "culled") when it
// produces no pixels by area or facing; the box may still be empty for an accepted triangle.
bool setup_triangle(const InputTriangle& in, uint32_t index, const RasterConfig& cfg,
                    TriangleSetup& out, const char** why);

SetupResult setup_scene(const std::vector<InputTriangle>& tris, const RasterConfig& cfg);

// Pixel-centre x (or y) of pixel index p in frac_bits() units.
inline int64_t pixel_centre(int64_t p, const RasterConfig& cfg) {
  return p * cfg.unit() + cfg.half();
}

}  // namespace trirast
