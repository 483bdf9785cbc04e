// Procedural indexed meshes for the built-in 3D scenes. Every builder shares vertices by index
// (poles, seams and grid nodes are one vertex each) and winds faces counter-clockwise seen from
// outside (right-handed, y up), as mesh files usually do.
#pragma once
#include <string>

#include "scene/camera.hpp"

namespace trirast {

// UV sphere: `stacks` >= 2 bands from pole to pole, `slices` >= 3 around; 2*slices*(stacks-1)
// triangles.
Mesh make_uv_sphere(int stacks, int slices, double radius, glm::dvec3 centre);

// Torus around the y axis: `rings` segments around the main circle, `sides` around the tube;
// 2*rings*sides triangles.
Mesh make_torus(int rings, int sides, double major_radius, double minor_radius,
                glm::dvec3 centre);

// Axis-aligned box with half-size `half`, 12 triangles.
Mesh make_box(glm::dvec3 half, glm::dvec3 centre);

// Height field y = height * f(u, v) over the square [-1, 1]^2 (x = u * half_size, z = v *
// half_size), sampled on a res x res grid of quads (2*res*res triangles), like GR3's surface
// plots. func: "waves" (sin * cos), "bump" (Gaussian), "ripple" (radial damped cosine).
Mesh make_height_field(int res, const std::string& func, double height, double half_size,
                       glm::dvec3 centre);

}  // namespace trirast
