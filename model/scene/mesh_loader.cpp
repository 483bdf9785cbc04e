// Mesh files through Assimp: flatten the node graph into one indexed mesh, then project it with
// the orbit camera (camera.hpp).
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

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

// Assimp 5.2's PLY reader accepts a file that ends before the elements its header declares (the
// missing vertices read as zeros, so a truncated file loads as degenerate triangles). Walk the
// body against the header, ASCII or binary, and refuse a file that ends early. Only the structure
// is checked here; the values are Assimp's (and the finiteness check's) business. A header this
// walk cannot read is left to Assimp to report.
struct PlyProperty {
  int size = 0;        // bytes of a scalar, or of a list's items
  int count_size = 0;  // list: bytes of the item count; 0 for a scalar
  bool count_unsigned = true;
};
struct PlyElement {
  std::string name;
  double count = 0;
  std::vector<PlyProperty> props;
};

int ply_type_size(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32")
    return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

std::string plural(double n, const std::string& what) {
  return token_count(n) + " " + what;
}

void check_ply_body(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  if (!in.read(magic, 3) || std::string(magic) != "ply") return;  // not PLY: Assimp decides
  in.seekg(0);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // ---- header: one keyword line after another, up to end_header ----
  size_t pos = 0;
  int line = 0;
  std::string format;
  std::vector<PlyElement> elements;
  bool ended = false;
  while (pos < text.size()) {
    size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    std::string l = text.substr(pos, eol - pos);
    if (!l.empty() && l.back() == '\r') l.pop_back();
    pos = eol + 1;
    ++line;
    std::istringstream words(l);
    std::string key;
    words >> key;
    if (key == "format") {
      words >> format;
    } else if (key == "element") {
      PlyElement e;
      std::string count;
      words >> e.name >> count;
      char* end = nullptr;
      e.count = std::strtod(count.c_str(), &end);
      if (count.empty() || *end != '\0' || !(e.count >= 0)) return;  // Assimp reports it
      elements.push_back(e);
    } else if (key == "property") {
      if (elements.empty()) return;
      std::string type;
      words >> type;
      PlyProperty p;
      if (type == "list") {
        std::string count_type, item_type;
        words >> count_type >> item_type;
        p.count_size = ply_type_size(count_type);
        p.count_unsigned = count_type[0] == 'u';
        p.size = ply_type_size(item_type);
        if (p.count_size == 0) return;
      } else {
        p.size = ply_type_size(type);
      }
      if (p.size == 0) return;
      elements.back().props.push_back(p);
    } else if (key == "end_header") {
      ended = true;
      break;
    }
  }
  if (!ended) return;
  const double size = double(text.size());
  std::string declared;
  for (const PlyElement& e : elements) {
    declared += (declared.empty() ? "" : ", ") + plural(e.count, e.name);
    // Every element takes at least a byte (binary) or a token and a blank (ASCII).
    if (e.count > size)
      throw not_a_mesh(path, "PLY header declares " + plural(e.count, e.name) +
                                 " elements, more than a file of " + token_count(size) +
                                 " bytes can hold");
  }
  // `where`: ":LINE" (ASCII) or "" (binary, where `detail` names the byte).
  auto truncated = [&](const PlyElement& e, double done, const std::string& where,
                       const std::string& detail) {
    return SceneError(path + where + ": not a readable mesh: PLY body ends" + detail + " after " +
                      token_count(done) + " of " + token_count(e.count) + " " + e.name +
                      " elements (header declares " + declared + "): truncated");
  };
  if (format == "ascii") {
    // Whitespace-separated tokens, counted with the line they sit on.
    auto next_token = [&](std::string& tok) {
      while (pos < text.size() && std::isspace((unsigned char)text[pos])) {
        if (text[pos] == '\n') ++line;
        ++pos;
      }
      if (pos >= text.size()) return false;
      const size_t start = pos;
      while (pos < text.size() && !std::isspace((unsigned char)text[pos])) ++pos;
      tok = text.substr(start, pos - start);
      return true;
    };
    ++line;  // the first body line
    std::string tok;
    for (const PlyElement& e : elements) {
      if (e.props.empty()) continue;
      for (double i = 0; i < e.count; ++i)
        for (const PlyProperty& p : e.props) {
          if (!next_token(tok)) throw truncated(e, i, ":" + std::to_string(line), "");
          if (p.count_size == 0) continue;
          char* end = nullptr;
          const double n = std::strtod(tok.c_str(), &end);
          if (*end != '\0' || !(n >= 0) || n > size) return;  // a bad count: Assimp reports it
          for (double k = 0; k < n; ++k)
            if (!next_token(tok)) throw truncated(e, i, ":" + std::to_string(line), "");
        }
    }
  } else if (format == "binary_little_endian" || format == "binary_big_endian") {
    const bool little = format == "binary_little_endian";
    auto read_count = [&](const PlyProperty& p, double& n) {
      if (pos + size_t(p.count_size) > text.size()) return false;
      uint64_t v = 0;
      for (int b = 0; b < p.count_size; ++b) {
        const uint64_t byte = (unsigned char)text[pos + (little ? b : p.count_size - 1 - b)];
        v |= byte << (8 * b);
      }
      pos += size_t(p.count_size);
      const bool negative = !p.count_unsigned && (v >> (8 * p.count_size - 1)) & 1;
      n = negative ? -1 : double(v);
      return true;
    };
    for (const PlyElement& e : elements) {
      if (e.props.empty()) continue;
      for (double i = 0; i < e.count; ++i)
        for (const PlyProperty& p : e.props) {
          double n = 1;
          if (p.count_size != 0) {
            if (!read_count(p, n)) throw truncated(e, i, "", " at byte " + std::to_string(text.size()));
            if (n < 0) return;  // a bad count: Assimp reports it
          }
          if (double(pos) + n * p.size > size)
            throw truncated(e, i, "", " at byte " + std::to_string(text.size()));
          pos += size_t(n) * size_t(p.size);
        }
    }
  }
}

std::string one_line(std::string s) {
  for (char& c : s)  // keep the message on one line
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

void check_finite(const aiScene* ai, const std::string& path) {
  for (unsigned m = 0; m < ai->mNumMeshes; ++m) {
    const aiMesh* am = ai->mMeshes[m];
    for (unsigned v = 0; v < am->mNumVertices; ++v) {
      const aiVector3D& p = am->mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw not_a_mesh(path, "vertex " + std::to_string(v) + " of mesh " + std::to_string(m) +
                                   " is not finite");
    }
  }
}

// Reads `path` with Assimp into one world-space mesh. Node transforms are applied by
// PreTransformVertices; faces that are not triangles after Triangulate (points, lines) are
// skipped.
Mesh import_mesh(const std::string& path) {
  Assimp::Importer importer;
  // Two passes: the file as read, so every vertex is checked for finiteness before
  // JoinIdenticalVertices can fold a NaN vertex into a finite neighbour (a NaN compares equal to
  // nothing, but the join's spatial hashing of it is not defined); then the post-processing.
  const unsigned post = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                        aiProcess_PreTransformVertices | aiProcess_ValidateDataStructure;
  const aiScene* ai = nullptr;
  try {
    ai = importer.ReadFile(path, 0);
    if (ai && !(ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
      check_finite(ai, path);
      ai = importer.ApplyPostProcessing(post);
    }
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {  // Assimp catches its own errors; this is a safety net
    throw not_a_mesh(path, e.what());
  }
  if (!ai) {
    const std::string why = one_line(importer.GetErrorString());
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
  check_ply_body(path);
  const Mesh mesh = import_mesh(path);
  Scene scene;
  scene.name = path;
  project_mesh(mesh, orbit_camera(bounding_sphere(mesh), cfg, cam), cfg, scene);
  return scene;
}

}  // namespace trirast
