// Internals of the built-in scenes: the key=value parameters, the registry entries, and the
// 2D building blocks (vertex orders, cell layout, fans, grids, strips) shared by builtin.cpp and
// hard_cases.cpp.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.hpp"

namespace trirast {

// One key a built-in accepts: its default (parsed like a given value) and, for choices, the
// allowed values ("" otherwise). The defaults here are the only ones: builtin_scenes() prints them.
struct KeySpec {
  const char* key;
  const char* default_value;
  const char* choices;  // "a|b|c" or ""
};

// The key=value list of one built-in, checked against its KeySpecs.
class BuiltinParams {
 public:
  // Throws SceneError for a key the built-in does not have or a key given twice.
  BuiltinParams(const std::string& name, const std::vector<KeySpec>& keys,
                const std::vector<std::pair<std::string, std::string>>& given);

  int64_t integer(const char* key, int64_t lo, int64_t hi) const;
  double real(const char* key, double lo, double hi) const;
  std::string choice(const char* key) const;  // one of the KeySpec's choices
  uint64_t seed() const { return uint64_t(integer("seed", 0, INT64_MAX)); }
  const std::string& name() const { return name_; }

 private:
  std::string text(const char* key) const;  // the given value, else the default
  [[noreturn]] void bad_value(const char* key, const std::string& expected) const;

  std::string name_;
  const std::vector<KeySpec>& keys_;
  std::vector<std::pair<std::string, std::string>> given_;
};

using BuiltinMaker = Scene (*)(const BuiltinParams&, const RasterConfig&, const CameraOptions&);

struct BuiltinEntry {
  const char* name;
  const char* summary;  // one line, without the keys (they are appended from `keys`)
  std::vector<KeySpec> keys;
  BuiltinMaker make;
};

// The hard-case built-ins (hard_cases.cpp), in docs/hard-cases.md order.
const std::vector<BuiltinEntry>& hard_case_entries();

// ---- 2D building blocks (pixels, y down) ----

using TriList = std::vector<InputTriangle>;

InputTriangle make_tri(double x0, double y0, double x1, double y1, double x2, double y2);
// The same triangle with its vertex list rotated by `rotation` (0..2) and, when `reversed`,
// its winding flipped (v1 and v2 exchanged after the rotation).
InputTriangle vertex_order(const InputTriangle& tri, int rotation, bool reversed);
InputTriangle translated(const InputTriangle& tri, double dx, double dy);

// Appends `tri` in all 6 vertex orders (3 rotations x 2 windings), at the same place:
// triangles 6k .. 6k+5 of a hard-case scene built this way must cover the same pixels.
void add_all_orders(TriList& out, const InputTriangle& tri);

// Hands out cells of cell_w x cell_h pixels in row-major order over the viewport, wrapping to
// the top-left when the viewport is full (cells then overlap earlier ones). Origins are whole
// pixels, so translating a shape into a cell keeps its position relative to pixel centres.
class CellLayout {
 public:
  CellLayout(const RasterConfig& cfg, int cell_w, int cell_h);
  // Origin (top-left) of the next cell.
  std::pair<double, double> next();

 private:
  int cols_, rows_, cell_w_, cell_h_, used_ = 0;
};

// Appends a closed configuration (its triangles drawn around the origin, fitting in one cell)
// 6 times, each copy in its own cell, with every triangle's vertices in order (rotation r,
// winding w) for the 6 combinations. Within one copy the triangles are consecutive.
void add_config_all_orders(TriList& out, const TriList& config, CellLayout& cells);

// Fan of n triangles around (cx, cy) with rim points on a circle of `radius`, the first at
// `rotation_deg` (clockwise on screen). Each rim point is computed once and shared.
TriList make_fan(double cx, double cy, int n, double radius, double rotation_deg);
// cols x rows quads of side `cell` rotated by angle_deg about (cx, cy), each split in two:
// diag "main" (top-left to bottom-right), "anti", or "alternate" (checkerboard).
TriList make_quad_grid(double cx, double cy, int cols, int rows, double cell, double angle_deg,
                       const std::string& diag);
// Triangle strip of n triangles along x from x0 to x1, thickness `width`, centre line
// y = cy + amplitude * sin(2 pi waves t). Consecutive triangles share an edge.
TriList make_strip(double x0, double x1, double cy, int n, double width, double amplitude,
                   double waves);

}  // namespace trirast
