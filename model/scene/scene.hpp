// Scenes: screen-space triangle lists from a .tri file, a mesh file (through Assimp and a GLM
// camera), or a built-in generator. Everything downstream sees only Scene.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/config.hpp"
#include "common/setup.hpp"

namespace trirast {

struct Scene {
  std::string name;                    // as given on the command line
  std::vector<InputTriangle> tris;     // screen-space triangles, index = position
  uint64_t near_clipped = 0;           // mesh triangles cut by the near plane (pieces kept)
  uint64_t near_dropped = 0;           // mesh triangles wholly behind the near plane
  uint64_t range_dropped = 0;          // mesh triangles whose projection left the coordinate range
  uint64_t mesh_faces = 0;             // mesh triangles projected (kept, clipped or dropped)
  uint64_t mesh_pieces = 0;            // triangles in `tris` those became (clipping may make 2)
  // Triangles in the file or built-in, before near-plane clipping and drops.
  uint64_t source_triangles() const { return tris.size() - mesh_pieces + mesh_faces; }
};

// Raised for unreadable or malformed scenes. what() is one line naming the file and line (or the
// built-in and key) at fault.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Camera for mesh scenes: look-at + perspective built with GLM. By default the mesh's bounding
// sphere is fitted to the viewport.
struct CameraOptions {
  double yaw_deg = 30.0;     // rotation about the world up axis (y)
  double pitch_deg = 20.0;   // elevation above the horizontal plane
  double distance = 0.0;     // eye distance in bounding-sphere radii; 0 = fit to the viewport
  double fov_deg = 45.0;     // vertical field of view
  double near_plane = 0.0;   // near plane distance in world units; 0 = automatic
};

// Reads a .tri file: '#' comments and blank lines ignored, one triangle per line
// "x0 y0 x1 y1 x2 y2". Throws SceneError("FILE:LINE: ...") on any malformed line.
Scene read_tri_file(const std::string& path);
// Parses .tri text (name used in messages).
Scene parse_tri_text(const std::string& text, const std::string& name);

// Loads a mesh (OBJ, PLY, STL, OFF, glTF, ... anything Assimp reads), projects it with the camera
// to the viewport and clips at the near plane. Throws SceneError("FILE: ...").
Scene load_mesh(const std::string& path, const RasterConfig& cfg, const CameraOptions& cam);

struct BuiltinInfo {
  std::string name;
  std::string description;  // one line, with its keys and their defaults
};

// All built-in scenes, for `trirast scenes`.
const std::vector<BuiltinInfo>& builtin_scenes();

// Builds "NAME[:key=value,...]" (the part after "builtin:"). Throws SceneError naming the
// built-in and the bad key or value.
Scene make_builtin(const std::string& spec, const RasterConfig& cfg, const CameraOptions& cam);

// Loads any scene argument: "builtin:..." , a .tri file, or a mesh file (by extension).
Scene load_scene(const std::string& arg, const RasterConfig& cfg, const CameraOptions& cam);

}  // namespace trirast
