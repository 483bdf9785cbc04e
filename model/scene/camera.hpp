// Indexed triangle meshes and the perspective camera that turns them into screen triangles.
// Shared by the mesh loader and the built-in 3D scenes, so both project the same way.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace trirast {

// An indexed triangle mesh in world space (y up). Faces keep the winding of the source.
struct Mesh {
  std::vector<glm::dvec3> positions;
  std::vector<std::array<uint32_t, 3>> faces;

  // Appends `other`, re-basing its indices.
  void append(const Mesh& other);
};

// Bounding sphere: centre of the axis-aligned box, radius to the farthest vertex.
struct BoundingSphere {
  glm::dvec3 centre{0.0};
  double radius = 1.0;
};
BoundingSphere bounding_sphere(const Mesh& mesh);

// A fully resolved camera: where it is, where it looks, and its frustum.
struct CameraView {
  glm::dvec3 eye{0.0, 0.0, 1.0};
  glm::dvec3 target{0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  double fov_deg = 45.0;   // vertical field of view
  double near_plane = 0.1; // distance of the near plane from the eye, > 0
};

// Camera looking at `sphere` from yaw/pitch. When opts.distance is 0 the distance is chosen so
// the sphere's silhouette fills 90% of the smaller viewport dimension; otherwise it is
// opts.distance radii. near_plane 0 = max(half the gap to the sphere, 5% of the radius).
CameraView orbit_camera(const BoundingSphere& sphere, const RasterConfig& cfg,
                        const CameraOptions& opts);

// Projects `mesh` through `view` into cfg's viewport (pixels, y down, origin top-left) and
// appends the triangles to `scene`, in face order.
//  * Each vertex is projected once (double precision) and its screen position reused by every
//    face, so neighbours get bit-identical shared vertices (hard case 18).
//  * Faces are clipped against the near plane (Sutherland-Hodgman, one plane: 1 or 2 pieces).
//    A new vertex on an edge is computed from the edge's endpoints in a canonical order, so both
//    faces sharing the edge get the same point. Counted in near_clipped / near_dropped.
//  * A piece with a vertex outside the representable range of cfg (the exact snap test of setup)
//    is dropped; each input face with a dropped piece counts once in range_dropped. No guard-band
//    clipping is done, so a dropped piece can leave a visible hole near the camera.
void project_mesh(const Mesh& mesh, const CameraView& view, const RasterConfig& cfg, Scene& scene);

// True when setup can snap `value` under cfg (finite, inside [-limit, limit) after rounding).
bool representable(double value, const RasterConfig& cfg);

}  // namespace trirast
