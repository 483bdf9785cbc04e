// Procedural meshes (see mesh_builders.hpp).
#include "scene/mesh_builders.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace trirast {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Flips `face` if its counter-clockwise normal points toward `inside` rather than away.
void orient_away_from(Mesh& mesh, std::array<uint32_t, 3>& face, const glm::dvec3& inside) {
  const glm::dvec3 &a = mesh.positions[face[0]], &b = mesh.positions[face[1]],
                   &c = mesh.positions[face[2]];
  const glm::dvec3 normal = glm::cross(b - a, c - a);
  const glm::dvec3 centroid = (a + b + c) / 3.0;
  if (glm::dot(normal, centroid - inside) < 0.0) std::swap(face[1], face[2]);
}

// Adds the two triangles of quad (a, b, c, d), given in order around the quad.
void add_quad(Mesh& mesh, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  mesh.faces.push_back({a, b, c});
  mesh.faces.push_back({a, c, d});
}

}  // namespace

Mesh make_uv_sphere(int stacks, int slices, double radius, glm::dvec3 centre) {
  Mesh mesh;
  // Vertex 0 is the north pole, then stacks-1 rings of `slices` vertices, then the south pole.
  mesh.positions.push_back(centre + glm::dvec3(0.0, radius, 0.0));
  for (int i = 1; i < stacks; ++i) {
    const double theta = kPi * i / stacks;
    for (int j = 0; j < slices; ++j) {
      const double phi = 2.0 * kPi * j / slices;
      mesh.positions.push_back(centre + radius * glm::dvec3(std::sin(theta) * std::cos(phi),
                                                            std::cos(theta),
                                                            std::sin(theta) * std::sin(phi)));
    }
  }
  const uint32_t south = uint32_t(mesh.positions.size());
  mesh.positions.push_back(centre - glm::dvec3(0.0, radius, 0.0));
  auto ring = [&](int i, int j) { return uint32_t(1 + (i - 1) * slices + (j % slices)); };
  for (int j = 0; j < slices; ++j) {
    mesh.faces.push_back({0, ring(1, j), ring(1, j + 1)});
    for (int i = 1; i + 1 < stacks; ++i) add_quad(mesh, ring(i, j), ring(i + 1, j),
                                                  ring(i + 1, j + 1), ring(i, j + 1));
    mesh.faces.push_back({south, ring(stacks - 1, j + 1), ring(stacks - 1, j)});
  }
  for (auto& f : mesh.faces) orient_away_from(mesh, f, centre);
  return mesh;
}

Mesh make_torus(int rings, int sides, double major_radius, double minor_radius,
                glm::dvec3 centre) {
  Mesh mesh;
  for (int i = 0; i < rings; ++i) {
    const double u = 2.0 * kPi * i / rings;
    for (int j = 0; j < sides; ++j) {
      const double v = 2.0 * kPi * j / sides;
      const double ring_r = major_radius + minor_radius * std::cos(v);
      mesh.positions.push_back(centre + glm::dvec3(ring_r * std::cos(u), minor_radius * std::sin(v),
                                                   ring_r * std::sin(u)));
    }
  }
  auto at = [&](int i, int j) { return uint32_t((i % rings) * sides + (j % sides)); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) add_quad(mesh, at(i, j), at(i + 1, j), at(i + 1, j + 1),
                                             at(i, j + 1));
  // Outward is away from the tube's centre circle at the face's angle around the y axis.
  for (auto& f : mesh.faces) {
    const glm::dvec3 c = (mesh.positions[f[0]] + mesh.positions[f[1]] + mesh.positions[f[2]]) /
                         3.0 - centre;
    const double u = std::atan2(c.z, c.x);
    orient_away_from(mesh, f, centre + major_radius * glm::dvec3(std::cos(u), 0.0, std::sin(u)));
  }
  return mesh;
}

Mesh make_box(glm::dvec3 half, glm::dvec3 centre) {
  Mesh mesh;
  for (int k = 0; k < 8; ++k)
    mesh.positions.push_back(centre + half * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1,
                                                        k & 4 ? 1 : -1));
  // Faces as quads of corner indices (bit 0 = +x, bit 1 = +y, bit 2 = +z).
  const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) add_quad(mesh, q[0], q[1], q[2], q[3]);
  for (auto& f : mesh.faces) orient_away_from(mesh, f, centre);
  return mesh;
}

Mesh make_height_field(int res, const std::string& func, double height, double half_size,
                       glm::dvec3 centre) {
  auto f = [&](double u, double v) {
    const double r = std::sqrt(u * u + v * v);
    if (func == "bump") return std::exp(-4.0 * r * r);
    if (func == "ripple") return std::cos(4.0 * kPi * r) * std::exp(-2.0 * r);
    return std::sin(2.0 * kPi * u) * std::cos(1.5 * kPi * v);  // "waves"
  };
  Mesh mesh;
  for (int i = 0; i <= res; ++i)
    for (int j = 0; j <= res; ++j) {
      const double u = -1.0 + 2.0 * j / res, v = -1.0 + 2.0 * i / res;
      mesh.positions.push_back(centre +
                               glm::dvec3(u * half_size, height * f(u, v), v * half_size));
    }
  auto at = [&](int i, int j) { return uint32_t(i * (res + 1) + j); };
  // Counter-clockwise seen from above (+y): (i, j) -> (i+1, j) -> (i+1, j+1) runs +z then +x.
  for (int i = 0; i < res; ++i)
    for (int j = 0; j < res; ++j) add_quad(mesh, at(i, j), at(i + 1, j), at(i + 1, j + 1),
                                           at(i, j + 1));
  return mesh;
}

}  // namespace trirast
