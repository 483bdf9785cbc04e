// Built-in scenes: the registry, spec parsing, and the general (non hard-case) generators.
#include <algorithm>
#include <cmath>

#include "scene/builtin.hpp"
#include "scene/camera.hpp"
#include "scene/mesh_builders.hpp"
#include "scene/rng.hpp"

namespace trirast {

namespace {

constexpr double kPi = 3.14159265358979323846;

// ---- random ----

struct AreaRange {
  double lo, hi;  // px^2
};

AreaRange area_range(const std::string& size_class, const RasterConfig& cfg) {
  const double screen = double(cfg.width) * cfg.height;
  if (size_class == "tiny") return {0.02, 1.0};
  if (size_class == "small") return {3.0, 30.0};
  if (size_class == "medium") return {100.0, 1000.0};
  if (size_class == "large") return {1e4, 1e5};
  return {std::min(1e5, 0.5 * screen), screen};  // huge
}

// Rounds a coordinate to the vertex grid asked for by `grid=`.
double snap_to_grid(double v, const std::string& grid, int subpixel_bits) {
  if (grid == "subpixel") return std::ldexp(std::nearbyint(std::ldexp(v, subpixel_bits)),
                                            -subpixel_bits);
  if (grid == "half") return std::nearbyint(v * 2.0) * 0.5;
  return v;
}

// One random triangle of the given area class, placed uniformly so that its bounding box lies
// inside [x0, x1] x [y0, y1] (scaled down first if it cannot fit).
InputTriangle random_triangle(SceneRng& rng, const AreaRange& range, double x0, double y0,
                              double x1, double y1) {
  double px[3], py[3], area = 0.0;
  // A shape from three points in the unit square, re-drawn while it is too thin: slivers have
  // their own hard case, here the size class should decide the area.
  for (int attempt = 0; attempt < 64 && area < 0.05; ++attempt) {
    for (int i = 0; i < 3; ++i) px[i] = rng.uniform(-1.0, 1.0), py[i] = rng.uniform(-1.0, 1.0);
    area = 0.5 * std::abs((px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0]));
  }
  // Log-uniform target area within the class.
  const double target = std::exp(rng.uniform(std::log(range.lo), std::log(range.hi)));
  double scale = std::sqrt(target / std::max(area, 1e-12));
  const double bw = (*std::max_element(px, px + 3) - *std::min_element(px, px + 3)) * scale;
  const double bh = (*std::max_element(py, py + 3) - *std::min_element(py, py + 3)) * scale;
  scale *= std::min({1.0, (x1 - x0) / bw, (y1 - y0) / bh});
  const double min_x = *std::min_element(px, px + 3) * scale,
               max_x = *std::max_element(px, px + 3) * scale;
  const double min_y = *std::min_element(py, py + 3) * scale,
               max_y = *std::max_element(py, py + 3) * scale;
  const double ox = rng.uniform(x0 - min_x, std::max(x0 - min_x, x1 - max_x));
  const double oy = rng.uniform(y0 - min_y, std::max(y0 - min_y, y1 - max_y));
  // Clamping only removes the last-bit rounding of ox + px * scale at the region's border.
  auto in_x = [&](double v) { return std::clamp(ox + v * scale, x0, x1); };
  auto in_y = [&](double v) { return std::clamp(oy + v * scale, y0, y1); };
  return make_tri(in_x(px[0]), in_y(py[0]), in_x(px[1]), in_y(py[1]), in_x(px[2]), in_y(py[2]));
}

Scene make_random(const BuiltinParams& p, const RasterConfig& cfg, const CameraOptions&) {
  const int64_t count = p.integer("count", 1, 5000000);
  const std::string size = p.choice("size");
  const std::string grid = p.choice("grid");
  // The margin may not push vertices out of the coordinate range.
  const double max_margin =
      std::max(0.0, double(cfg.coord_limit_px()) - std::max(cfg.width, cfg.height) - 1.0);
  const double margin = p.real("margin", 0.0, max_margin);
  static const char* const kClasses[] = {"tiny", "small", "medium", "large", "huge"};
  SceneRng rng(p.seed());
  Scene scene;
  scene.tris.reserve(size_t(count));
  for (int64_t i = 0; i < count; ++i) {
    const std::string size_class = size == "mixed" ? kClasses[rng.below(5)] : size;
    InputTriangle t = random_triangle(rng, area_range(size_class, cfg), -margin, -margin,
                                      cfg.width + margin, cfg.height + margin);
    for (int v = 0; v < 3; ++v) {
      t.x[v] = snap_to_grid(t.x[v], grid, cfg.subpixel_bits);
      t.y[v] = snap_to_grid(t.y[v], grid, cfg.subpixel_bits);
    }
    scene.tris.push_back(t);
  }
  return scene;
}

// ---- 2D configurations ----

Scene scene_of(TriList tris) {
  Scene scene;
  scene.tris = std::move(tris);
  return scene;
}

Scene make_fan_scene(const BuiltinParams& p, const RasterConfig& cfg, const CameraOptions&) {
  const int n = int(p.integer("n", 3, 64));
  const bool on_pixel = p.choice("centre") == "pixel";
  double radius = p.real("radius", 0.0, 30000.0);
  const double rotation = p.real("rotation", -360.0, 360.0);
  if (radius == 0.0) radius = 0.4 * std::min(cfg.width, cfg.height);
  // "pixel": exactly on the centre of the middle pixel; "free": an offset with no special ties.
  const double cx = on_pixel ? std::floor(cfg.width / 2) + 0.5 : cfg.width * 0.5 + 0.3137;
  const double cy = on_pixel ? std::floor(cfg.height / 2) + 0.5 : cfg.height * 0.5 + 0.2718;
  return scene_of(make_fan(cx, cy, n, radius, rotation));
}

Scene make_quad_grid_scene(const BuiltinParams& p, const RasterConfig& cfg, const CameraOptions&) {
  const int cols = int(p.integer("cols", 1, 2000)), rows = int(p.integer("rows", 1, 2000));
  const double angle = p.real("angle", 0.0, 90.0);
  const std::string diag = p.choice("diag");
  double cell = p.real("cell", 0.0, 10000.0);
  if (cell == 0.0) {  // largest cell for which the rotated grid fits in 95% of the viewport
    const double c = std::cos(angle * kPi / 180.0), s = std::sin(angle * kPi / 180.0);
    cell = std::min(0.95 * cfg.width / (c * cols + s * rows),
                    0.95 * cfg.height / (s * cols + c * rows));
  }
  return scene_of(make_quad_grid(cfg.width * 0.5, cfg.height * 0.5, cols, rows, cell, angle,
                                 diag));
}

Scene make_strip_scene(const BuiltinParams& p, const RasterConfig& cfg, const CameraOptions&) {
  const int n = int(p.integer("n", 1, 1000000));
  const double width = p.real("width", 0.0, 10000.0);
  const double waves = p.real("waves", 0.0, 1000.0);
  return scene_of(make_strip(0.05 * cfg.width, 0.95 * cfg.width, 0.5 * cfg.height, n, width,
                             0.3 * cfg.height, waves));
}

// ---- meshes through the camera ----

// Projects `mesh` with the orbit camera of `cam`, at `distance` radii when > 0.
Scene project_with_orbit(const Mesh& mesh, const RasterConfig& cfg, CameraOptions cam,
                         double distance = 0.0) {
  if (distance > 0.0) cam.distance = distance;
  Scene scene;
  project_mesh(mesh, orbit_camera(bounding_sphere(mesh), cfg, cam), cfg, scene);
  return scene;
}

Scene make_sphere_scene(const BuiltinParams& p, const RasterConfig& cfg, const CameraOptions& cam) {
  const int tess = int(p.integer("tess", 2, 1000));
  return project_with_orbit(make_uv_sphere(tess, 2 * tess, 1.0, glm::dvec3(0.0)), cfg, cam);
}

Scene make_torus_scene(const BuiltinParams& p, const RasterConfig& cfg, const CameraOptions& cam) {
  const int tess = int(p.integer("tess", 3, 2000));
  const double ratio = p.real("ratio", 0.01, 0.99);
  const Mesh torus = make_torus(tess, std::max(3, tess / 2), 1.0, ratio, glm::dvec3(0.0));
  return project_with_orbit(torus, cfg, cam);
}

Scene make_surface_scene(const BuiltinParams& p, const RasterConfig& cfg,
                         const CameraOptions& cam) {
  const int res = int(p.integer("res", 1, 1000));
  const std::string func = p.choice("func");
  const double height = p.real("height", 0.0, 100.0);
  return project_with_orbit(make_height_field(res, func, height, 1.0, glm::dvec3(0.0)), cfg, cam);
}

// The five scene types of Table 1 of Mileff, Nehéz & Dudra, "Accelerated half-space triangle
// rasterization": low/high poly, far/near, and a mixed scene.
Scene make_lowpoly(const BuiltinParams& p, const RasterConfig& cfg, const CameraOptions& cam) {
  const int tess = int(p.integer("tess", 2, 100));
  const double dist = p.real("dist", 1.01, 1000.0);
  return project_with_orbit(make_uv_sphere(tess, 2 * tess, 1.0, glm::dvec3(0.0)), cfg, cam, dist);
}

Scene make_highpoly(const BuiltinParams& p, const RasterConfig& cfg, const CameraOptions& cam) {
  const int tess = int(p.integer("tess", 2, 1000));
  const double dist = p.real("dist", 1.01, 1000.0);
  return project_with_orbit(make_uv_sphere(tess, 2 * tess, 1.0, glm::dvec3(0.0)), cfg, cam, dist);
}

Scene make_mixed(const BuiltinParams& p, const RasterConfig& cfg, const CameraOptions& cam) {
  const int objects = int(p.integer("objects", 0, 1000));
  const int tess = int(p.integer("tess", 3, 500));
  const double dist = p.real("dist", 0.05, 1000.0);
  SceneRng rng(p.seed());
  // A rippled ground of 20 x 20 units with spheres, tori and boxes of random size on it; the
  // camera stands at the edge of the bounding sphere, so objects range from near to far.
  Mesh world = make_height_field(std::max(4, tess), "ripple", 0.4, 10.0, glm::dvec3(0.0));
  for (int i = 0; i < objects; ++i) {
    const double size = rng.uniform(0.3, 1.5);
    const glm::dvec3 at(rng.uniform(-8.0, 8.0), size + 0.4, rng.uniform(-8.0, 8.0));
    switch (rng.below(3)) {
      case 0: world.append(make_uv_sphere(tess, 2 * tess, size, at)); break;
      case 1: world.append(make_torus(2 * tess, tess, size, 0.3 * size, at)); break;
      default: world.append(make_box(glm::dvec3(size), at)); break;
    }
  }
  return project_with_orbit(world, cfg, cam, dist);
}

// ---- registry ----

const std::vector<BuiltinEntry>& general_entries() {
  static const std::vector<BuiltinEntry> entries = {
      {"random",
       "random triangles of one size class (tiny <1px^2 .. huge = whole screen)",
       {{"count", "1000", ""},
        {"size", "mixed", "tiny|small|medium|large|huge|mixed"},
        {"grid", "float", "float|subpixel|half"},
        {"margin", "0", ""},
        {"seed", "1", ""}},
       make_random},
      {"fan",
       "closed fan of n triangles around the viewport centre (radius 0 = 40% of it)",
       {{"n", "6", ""},
        {"centre", "pixel", "pixel|free"},
        {"radius", "0", ""},
        {"rotation", "0", ""}},
       make_fan_scene},
      {"quad-grid",
       "grid of quads rotated by angle (deg), two triangles each (cell 0 = fit)",
       {{"cols", "16", ""},
        {"rows", "12", ""},
        {"angle", "30", ""},
        {"diag", "alternate", "main|anti|alternate"},
        {"cell", "0", ""}},
       make_quad_grid_scene},
      {"strip",
       "wavy triangle strip across the viewport",
       {{"n", "100", ""}, {"width", "40", ""}, {"waves", "1.5", ""}},
       make_strip_scene},
      {"sphere",
       "UV sphere (tess stacks x 2*tess slices) through the mesh camera",
       {{"tess", "32", ""}},
       make_sphere_scene},
      {"torus",
       "torus (tess rings x tess/2 sides, minor/major = ratio) through the mesh camera",
       {{"tess", "48", ""}, {"ratio", "0.35", ""}},
       make_torus_scene},
      {"surface",
       "height-field surface plot z=f(x,y) as in GR3, res x res quads",
       {{"res", "64", ""}, {"func", "waves", "waves|bump|ripple"}, {"height", "0.35", ""}},
       make_surface_scene},
      {"lowpoly-far",
       "Mileff et al. case 1: coarse sphere (few large triangles) far away",
       {{"tess", "6", ""}, {"dist", "10", ""}},
       make_lowpoly},
      {"lowpoly-near",
       "Mileff et al. case 2: coarse sphere filling and exceeding the screen",
       {{"tess", "6", ""}, {"dist", "1.2", ""}},
       make_lowpoly},
      {"highpoly-far",
       "Mileff et al. case 3: fine sphere (~100k small triangles) far away",
       {{"tess", "160", ""}, {"dist", "10", ""}},
       make_highpoly},
      {"highpoly-near",
       "Mileff et al. case 4: fine sphere covering the entire screen",
       {{"tess", "160", ""}, {"dist", "1.1", ""}},
       make_highpoly},
      {"mixed",
       "Mileff et al. case 5: ground and random objects at various distances",
       {{"objects", "8", ""}, {"tess", "24", ""}, {"dist", "1", ""}, {"seed", "1", ""}},
       make_mixed},
  };
  return entries;
}

const BuiltinEntry* find_entry(const std::string& name) {
  for (const auto* list : {&general_entries(), &hard_case_entries()})
    for (const BuiltinEntry& e : *list)
      if (name == e.name) return &e;
  return nullptr;
}

std::string describe(const BuiltinEntry& e) {
  std::string text = e.summary;
  if (e.keys.empty()) return text;
  text += " [";
  for (size_t i = 0; i < e.keys.size(); ++i) {
    if (i) text += ", ";
    text += std::string(e.keys[i].key) + "=" + e.keys[i].default_value;
    if (e.keys[i].choices[0] != '\0') text += std::string(" (") + e.keys[i].choices + ")";
  }
  return text + "]";
}

}  // namespace

const std::vector<BuiltinInfo>& builtin_scenes() {
  static const std::vector<BuiltinInfo> infos = [] {
    std::vector<BuiltinInfo> list;
    for (const auto* entries : {&general_entries(), &hard_case_entries()})
      for (const BuiltinEntry& e : *entries) list.push_back({e.name, describe(e)});
    return list;
  }();
  return infos;
}

Scene make_builtin(const std::string& spec, const RasterConfig& cfg, const CameraOptions& cam) {
  const size_t colon = spec.find(':');
  const std::string name = spec.substr(0, colon);
  const BuiltinEntry* entry = find_entry(name);
  if (!entry)
    throw SceneError("builtin:" + name + ": unknown built-in scene (see `trirast scenes`)");
  // "key=value,key=value" after the colon.
  std::vector<std::pair<std::string, std::string>> given;
  if (colon != std::string::npos) {
    const std::string list = spec.substr(colon + 1);
    size_t start = 0;
    while (start <= list.size()) {
      size_t comma = list.find(',', start);
      if (comma == std::string::npos) comma = list.size();
      const std::string item = list.substr(start, comma - start);
      const size_t eq = item.find('=');
      if (eq == std::string::npos || eq == 0)
        throw SceneError("builtin:" + name + ": expected key=value, got '" + item + "'");
      given.emplace_back(item.substr(0, eq), item.substr(eq + 1));
      start = comma + 1;
    }
  }
  const BuiltinParams params(name, entry->keys, given);
  Scene scene = entry->make(params, cfg, cam);
  scene.name = "builtin:" + spec;
  return scene;
}

}  // namespace trirast
