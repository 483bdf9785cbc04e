// Mesh files through Assimp: flatten the node graph into one indexed mesh, then project it with
// the orbit camera (camera.hpp).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "scene/camera.hpp"
#include "scene/scene.hpp"
#include "scene/scene_files.hpp"

namespace trirast {

namespace {

SceneError not_a_mesh(const std::string& path, const std::string& why) {
  return SceneError(path + ": not a readable mesh: " + why);
}

std::string token_count(double n) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f", n);
  return text;
}

// Assimp 5.2's OFF reader trusts the header's counts: "OFF\n353535235358 6 0" makes it reserve
// ~16 GB and run for a quarter of a minute (assimp-testmodels invalid/OutOfMemory.off). Refuse
// headers that declare more vertices or faces than the file has bytes (each needs at least 2).
void check_off_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in.tellg();
  in.seekg(0);
  std::string keyword;
  in >> keyword;
  const bool is_off = keyword.size() >= 3 && keyword.compare(keyword.size() - 3, 3, "OFF") == 0;
  if (!is_off || size <= 0) return;  // not OFF text: Assimp decides
  // The counts follow the keyword, possibly after '#' comment lines.
  std::string token;
  double counts[2];
  int found = 0;
  while (found < 2 && in >> token) {
    if (token[0] == '#') {
      std::getline(in, token);
      continue;
    }
    char* end = nullptr;
    counts[found] = std::strtod(token.c_str(), &end);
    if (*end != '\0') return;  // malformed: Assimp reports it
    ++found;
  }
  if (found == 2 && (counts[0] > double(size) / 2 || counts[1] > double(size) / 2))
    throw not_a_mesh(path, "OFF header declares " + token_count(counts[0]) + " vertices and " +
                               token_count(counts[1]) + " faces, more than a file of " +
                               std::to_string(size) + " bytes can hold");
}

// Reads `path` with Assimp into one world-space mesh. Node transforms are applied by
// PreTransformVertices; faces that are not triangles after Triangulate (points, lines) are
// skipped.
Mesh import_mesh(const std::string& path) {
  Assimp::Importer importer;
  const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                         aiProcess_PreTransformVertices | aiProcess_ValidateDataStructure;
  const aiScene* ai = nullptr;
  try {
    ai = importer.ReadFile(path, flags);
  } catch (const std::exception& e) {  // Assimp catches its own errors; this is a safety net
    throw not_a_mesh(path, e.what());
  }
  if (!ai) {
    std::string why = importer.GetErrorString();
    for (char& c : why)  // keep the message on one line
      if (c == '\n' || c == '\r') c = ' ';
    throw not_a_mesh(path, why.empty() ? "unknown Assimp error" : why);
  }
  if (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) throw not_a_mesh(path, "incomplete scene");
  Mesh mesh;
  for (unsigned m = 0; m < ai->mNumMeshes; ++m) {
    const aiMesh* am = ai->mMeshes[m];
    const uint32_t base = uint32_t(mesh.positions.size());
    for (unsigned v = 0; v < am->mNumVertices; ++v) {
      const aiVector3D& p = am->mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw not_a_mesh(path, "vertex " + std::to_string(v) + " of mesh " + std::to_string(m) +
                                   " is not finite");
      mesh.positions.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& face = am->mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (unsigned k = 0; k < 3; ++k)
        if (face.mIndices[k] >= am->mNumVertices)
          throw not_a_mesh(path, "face " + std::to_string(f) + " has an index out of range");
      mesh.faces.push_back({base + face.mIndices[0], base + face.mIndices[1],
                            base + face.mIndices[2]});
    }
  }
  if (mesh.faces.empty()) throw not_a_mesh(path, "no triangles");
  return mesh;
}

}  // namespace

Scene load_mesh(const std::string& path, const RasterConfig& cfg, const CameraOptions& cam) {
  require_readable_file(path);
  check_off_header(path);
  const Mesh mesh = import_mesh(path);
  Scene scene;
  scene.name = path;
  project_mesh(mesh, orbit_camera(bounding_sphere(mesh), cfg, cam), cfg, scene);
  return scene;
}

}  // namespace trirast
