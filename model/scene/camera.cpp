// Perspective projection of indexed meshes with near-plane clipping (see camera.hpp).
#include "scene/camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

namespace trirast {

void Mesh::append(const Mesh& other) {
  const uint32_t base = uint32_t(positions.size());
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  for (const auto& f : other.faces) faces.push_back({f[0] + base, f[1] + base, f[2] + base});
}

BoundingSphere bounding_sphere(const Mesh& mesh) {
  BoundingSphere s;
  if (mesh.positions.empty()) return s;
  glm::dvec3 lo = mesh.positions[0], hi = mesh.positions[0];
  for (const auto& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  s.centre = (lo + hi) * 0.5;
  double r2 = 0.0;
  for (const auto& p : mesh.positions) {
    const glm::dvec3 d = p - s.centre;
    r2 = std::max(r2, d.x * d.x + d.y * d.y + d.z * d.z);
  }
  // A single point still needs a non-zero radius for the camera to have somewhere to stand.
  s.radius = r2 > 0.0 ? std::sqrt(r2) : 1.0;
  return s;
}

CameraView orbit_camera(const BoundingSphere& sphere, const RasterConfig& cfg,
                        const CameraOptions& opts) {
  CameraView view;
  view.fov_deg = opts.fov_deg;
  const double r = sphere.radius;
  double distance = opts.distance * r;
  if (opts.distance <= 0.0) {
    // tan of the half field of view along the smaller viewport dimension.
    const double aspect = double(cfg.width) / double(cfg.height);
    const double tan_half = std::tan(glm::radians(opts.fov_deg) * 0.5) * std::min(1.0, aspect);
    // A sphere at distance d subtends a half-angle asin(r/d); make its tangent 90% of tan_half.
    distance = r / std::sin(std::atan(0.9 * tan_half));
  }
  const double yaw = glm::radians(opts.yaw_deg), pitch = glm::radians(opts.pitch_deg);
  const glm::dvec3 toward_eye(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                              std::cos(pitch) * std::cos(yaw));
  view.target = sphere.centre;
  view.eye = sphere.centre + distance * toward_eye;
  // Looking straight up or down: world up is parallel to the view direction, use the yaw axis.
  if (std::abs(std::cos(pitch)) < 1e-9)
    view.up = glm::dvec3(-std::sin(yaw), 0.0, -std::cos(yaw)) * (pitch > 0 ? 1.0 : -1.0);
  view.near_plane = opts.near_plane > 0.0 ? opts.near_plane
                                          : std::max(0.5 * (distance - r), 0.05 * r);
  return view;
}

bool representable(double value, const RasterConfig& cfg) {
  // Same test as snap_coordinate in setup: round at 2^-S, then compare with the range.
  const double scaled = std::nearbyint(std::ldexp(value, cfg.subpixel_bits));
  const double limit = std::ldexp(double(cfg.coord_limit_px()), cfg.subpixel_bits);
  return scaled >= -limit && scaled < limit;  // false for NaN too
}

namespace {

struct ScreenPoint {
  double x, y;
};

// One mesh vertex after the view and projection transforms.
struct ProjectedVertex {
  glm::dvec4 clip;     // clip-space position
  double near_dist;    // w - near: >= 0 on the visible side of the near plane
  ScreenPoint screen;  // valid when near_dist >= 0
};

class MeshProjector {
 public:
  MeshProjector(const Mesh& mesh, const CameraView& view, const RasterConfig& cfg)
      : mesh_(mesh), cfg_(cfg), near_(view.near_plane) {
    const double aspect = double(cfg.width) / double(cfg.height);
    const glm::dmat4 view_m = glm::lookAt(view.eye, view.target, view.up);
    const glm::dmat4 proj_m =
        glm::perspective(glm::radians(view.fov_deg), aspect, near_, near_ * 1e6);
    const glm::dmat4 clip_from_world = proj_m * view_m;
    // Every vertex is projected exactly once; faces only look positions up.
    verts_.reserve(mesh.positions.size());
    for (const auto& p : mesh.positions) {
      ProjectedVertex v;
      v.clip = clip_from_world * glm::dvec4(p, 1.0);
      v.near_dist = v.clip.w - near_;  // glm::perspective puts -z_eye in w
      v.screen = v.near_dist >= 0.0 ? to_screen(v.clip) : ScreenPoint{0.0, 0.0};
      verts_.push_back(v);
    }
  }

  void project_face(const std::array<uint32_t, 3>& face, Scene& scene) const {
    ++scene.mesh_faces;
    int inside = 0;
    for (uint32_t idx : face) inside += verts_[idx].near_dist >= 0.0;
    if (inside == 0) {
      ++scene.near_dropped;
      return;
    }
    // Sutherland-Hodgman against the near plane, keeping the face's vertex order (winding).
    ScreenPoint poly[4];
    int n = 0;
    for (int i = 0; i < 3; ++i) {
      const uint32_t cur = face[i], nxt = face[(i + 1) % 3];
      const bool cur_in = verts_[cur].near_dist >= 0.0, nxt_in = verts_[nxt].near_dist >= 0.0;
      if (cur_in) poly[n++] = verts_[cur].screen;
      if (cur_in != nxt_in) poly[n++] = edge_crossing(cur, nxt);
    }
    if (inside < 3) ++scene.near_clipped;
    // Fan-triangulate the 3- or 4-gon; drop pieces the coordinate range cannot hold.
    bool dropped = false;
    for (int k = 1; k + 1 < n; ++k) dropped |= !emit(poly[0], poly[k], poly[k + 1], scene);
    if (dropped) ++scene.range_dropped;
  }

 private:
  ScreenPoint to_screen(const glm::dvec4& clip) const {
    const double ndc_x = clip.x / clip.w, ndc_y = clip.y / clip.w;
    return {(ndc_x + 1.0) * 0.5 * cfg_.width, (1.0 - ndc_y) * 0.5 * cfg_.height};
  }

  // Where edge (a, b) crosses the near plane. The endpoints are put in a canonical order (by
  // position, then index) first, so the faces on both sides of an edge compute the same point.
  ScreenPoint edge_crossing(uint32_t a, uint32_t b) const {
    const glm::dvec3 &pa = mesh_.positions[a], &pb = mesh_.positions[b];
    const bool b_first = pb.x != pa.x ? pb.x < pa.x
                         : pb.y != pa.y ? pb.y < pa.y
                         : pb.z != pa.z ? pb.z < pa.z
                                        : b < a;
    if (b_first) std::swap(a, b);
    const ProjectedVertex &va = verts_[a], &vb = verts_[b];
    const double t = va.near_dist / (va.near_dist - vb.near_dist);  // endpoints straddle: no 0/0
    glm::dvec4 clip = va.clip + t * (vb.clip - va.clip);
    clip.w = std::max(clip.w, near_);  // rounding must not push w below the plane
    return to_screen(clip);
  }

  bool emit(ScreenPoint a, ScreenPoint b, ScreenPoint c, Scene& scene) const {
    InputTriangle tri;
    const ScreenPoint pts[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
      if (!representable(pts[i].x, cfg_) || !representable(pts[i].y, cfg_)) return false;
      tri.x[i] = pts[i].x;
      tri.y[i] = pts[i].y;
    }
    scene.tris.push_back(tri);
    ++scene.mesh_pieces;
    return true;
  }

  const Mesh& mesh_;
  const RasterConfig& cfg_;
  double near_;
  std::vector<ProjectedVertex> verts_;
};

}  // namespace

void project_mesh(const Mesh& mesh, const CameraView& view, const RasterConfig& cfg,
                  Scene& scene) {
  const MeshProjector projector(mesh, view, cfg);
  scene.tris.reserve(scene.tris.size() + mesh.faces.size());
  for (const auto& face : mesh.faces) projector.project_face(face, scene);
}

}  // namespace trirast
