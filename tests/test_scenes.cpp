// Scenes: the .tri reader, mesh loading through Assimp and the camera, built-in generators.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "common/setup.hpp"
#include "scene/camera.hpp"
#include "scene/mesh_builders.hpp"
#include "scene/scene.hpp"
#include "common/reference_raster.hpp"
#include "common/watertight.hpp"

namespace trirast {
namespace {

const std::string kData = std::string(TRIRAST_SOURCE_DIR) + "/tests/data/";

// Runs `fn`, expects a SceneError, and returns its message ("" if none was thrown).
template <typename Fn>
std::string scene_error(Fn fn) {
  try {
    fn();
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no SceneError thrown";
  return "";
}

// A scratch file removed at the end of the test.
struct TempFile {
  std::string path;
  explicit TempFile(const std::string& name, const std::string& content)
      : path(::testing::TempDir() + "trirast_scenes_" + std::to_string(::getpid()) + "_" + name) {
    std::ofstream(path, std::ios::binary) << content;
  }
  ~TempFile() { std::remove(path.c_str()); }
};

double signed_area(const InputTriangle& t) {
  return 0.5 * ((t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.y[1] - t.y[0]) * (t.x[2] - t.x[0]));
}

bool same_bits(const Scene& a, const Scene& b) {
  if (a.tris.size() != b.tris.size()) return false;
  for (size_t i = 0; i < a.tris.size(); ++i)
    if (std::memcmp(a.tris[i].x, b.tris[i].x, sizeof a.tris[i].x) != 0 ||
        std::memcmp(a.tris[i].y, b.tris[i].y, sizeof a.tris[i].y) != 0)
      return false;
  return true;
}

// How many triangle corners use each screen position, by exact bit pattern.
std::map<std::pair<uint64_t, uint64_t>, int> corner_uses(const Scene& scene) {
  std::map<std::pair<uint64_t, uint64_t>, int> uses;
  for (const auto& t : scene.tris)
    for (int i = 0; i < 3; ++i) {
      uint64_t bx, by;
      std::memcpy(&bx, &t.x[i], 8);
      std::memcpy(&by, &t.y[i], 8);
      ++uses[{bx, by}];
    }
  return uses;
}

// ---------------------------------------------------------------- .tri text

TEST(TriReader, CommentsBlankLinesAndLineNumbers) {
  const Scene s = parse_tri_text(
      "# header\n\n  1 2 3 4 5 6  # trailing comment\n\t\n#\n7 8 9 10 11 12\r\n-1.5e1 0x10 +3 .5 "
      "6. 7",
      "t.tri");
  ASSERT_EQ(s.tris.size(), 3u);
  EXPECT_EQ(s.tris[0].line, 3);
  EXPECT_EQ(s.tris[1].line, 6);
  EXPECT_EQ(s.tris[2].line, 7);
  EXPECT_EQ(s.tris[0].x[0], 1.0);
  EXPECT_EQ(s.tris[0].y[2], 6.0);
  EXPECT_EQ(s.tris[1].x[2], 11.0);
  EXPECT_EQ(s.tris[2].x[0], -15.0);
  EXPECT_EQ(s.tris[2].y[0], 16.0);
  EXPECT_EQ(s.tris[2].x[2], 6.0);
}

TEST(TriReader, NonFiniteTextPassesThroughToSetup) {
  const Scene s = parse_tri_text("nan 0 inf 0 -infinity 1e999\n", "t.tri");
  ASSERT_EQ(s.tris.size(), 1u);
  EXPECT_TRUE(std::isnan(s.tris[0].x[0]));
  EXPECT_TRUE(std::isinf(s.tris[0].x[1]));
  EXPECT_TRUE(std::isinf(s.tris[0].x[2]) && s.tris[0].x[2] < 0);
  EXPECT_TRUE(std::isinf(s.tris[0].y[2]));
}

TEST(TriReader, MalformedLinesNameFileAndLine) {
  EXPECT_EQ(scene_error([] { parse_tri_text("1 2 3 4 5 6\n\n1 2 3 4 5\n", "a.tri"); }),
            "a.tri:3: expected 6 numbers, found 5");
  EXPECT_EQ(scene_error([] { parse_tri_text("1 2 3 4 5 6 7\n", "a.tri"); }),
            "a.tri:1: expected 6 numbers, found 7");
  EXPECT_EQ(scene_error([] { parse_tri_text("# c\n1 2 abc 4 5 6\n", "a.tri"); }),
            "a.tri:2: 'abc' is not a number");
  EXPECT_EQ(scene_error([] { parse_tri_text("1 2 3 4 5 6.5x\n", "a.tri"); }),
            "a.tri:1: '6.5x' is not a number");
  EXPECT_EQ(scene_error([] { parse_tri_text("1,2 3 4 5 6 7\n", "a.tri"); }),
            "a.tri:1: '1,2' is not a number");
  EXPECT_EQ(scene_error([] { parse_tri_text("1 2 3 4 5 6\n7", "a.tri"); }),
            "a.tri:2: expected 6 numbers, found 1");
  // A very long token is shortened in the message, which stays one line.
  const std::string msg =
      scene_error([] { parse_tri_text("1 2 3 4 5 " + std::string(5000, 'z') + "\n", "a.tri"); });
  EXPECT_LT(msg.size(), 100u);
  EXPECT_EQ(msg.find('\n'), std::string::npos);
}

TEST(TriReader, EmptyAndBinaryText) {
  EXPECT_EQ(scene_error([] { parse_tri_text("", "e.tri"); }), "e.tri: empty scene (no triangles)");
  EXPECT_EQ(scene_error([] { parse_tri_text("# only\n\n   \n", "e.tri"); }),
            "e.tri: empty scene (no triangles)");
  EXPECT_EQ(scene_error([] { parse_tri_text(std::string("1 2 3\0 4 5 6\n", 13), "b.tri"); }),
            "b.tri: binary data, not a .tri text file");
  EXPECT_EQ(scene_error([] { parse_tri_text("1 2 3 4 5 6\x1b\n", "b.tri"); }),
            "b.tri: binary data, not a .tri text file");
}

TEST(TriReader, FileErrors) {
  const std::string missing = kData + "no_such_file.tri";
  EXPECT_EQ(scene_error([&] { read_tri_file(missing); }),
            missing + ": cannot open: No such file or directory");
  EXPECT_EQ(scene_error([] { read_tri_file(kData); }), kData + ": is a directory");
  TempFile empty("empty.tri", "");
  EXPECT_EQ(scene_error([&] { read_tri_file(empty.path); }),
            empty.path + ": empty scene (no triangles)");
  std::string garbage(4096, '\0');
  for (size_t i = 0; i < garbage.size(); ++i) garbage[i] = char((i * 2654435761u) >> 13);
  TempFile binary("binary.tri", garbage);
  EXPECT_EQ(scene_error([&] { read_tri_file(binary.path); }),
            binary.path + ": binary data, not a .tri text file");
  TempFile bad("bad.tri", "1 2 3 4 5 6\n1 2 3 4 5\n");
  EXPECT_EQ(scene_error([&] { read_tri_file(bad.path); }),
            bad.path + ":2: expected 6 numbers, found 5");
}

TEST(TriReader, ReadsFileThroughLoadScene) {
  const Scene s = load_scene(kData + "two_tris.tri", RasterConfig{}, CameraOptions{});
  ASSERT_EQ(s.tris.size(), 2u);
  EXPECT_EQ(s.tris[0].line, 2);
  EXPECT_EQ(s.tris[1].line, 4);
  EXPECT_EQ(s.name, kData + "two_tris.tri");
}

TEST(LoadScene, PathErrors) {
  const RasterConfig cfg;
  const CameraOptions cam;
  for (const std::string name : {"missing.obj", "missing.tri", "missing"}) {
    const std::string path = kData + name;
    EXPECT_EQ(scene_error([&] { load_scene(path, cfg, cam); }),
              path + ": cannot open: No such file or directory");
  }
  const std::string dir = kData.substr(0, kData.size() - 1);
  EXPECT_EQ(scene_error([&] { load_scene(dir, cfg, cam); }), dir + ": is a directory");
  EXPECT_EQ(scene_error([&] { load_mesh(dir, cfg, cam); }), dir + ": is a directory");
}

// ---------------------------------------------------------------- mesh files

TEST(MeshLoader, SameCubeInEveryFormat) {
  const RasterConfig cfg;
  const CameraOptions cam;
  double reference_area = 0.0;
  for (const char* name : {"cube.obj", "cube.ply", "cube.stl", "cube.off", "cube.gltf"}) {
    SCOPED_TRACE(name);
    const Scene s = load_scene(kData + name, cfg, cam);
    ASSERT_EQ(s.tris.size(), 12u);
    EXPECT_EQ(s.near_clipped + s.near_dropped + s.range_dropped, 0u);
    // Default camera: 3 of 6 faces seen from outside. The file's faces are counter-clockwise
    // from outside, so the 6 front triangles are counter-clockwise on screen (negative signed
    // area in y-down coordinates) and the 6 back ones clockwise.
    int front = 0;
    double area = 0.0;
    for (const auto& t : s.tris) {
      front += signed_area(t) < 0;
      area += std::abs(signed_area(t));
      for (int i = 0; i < 3; ++i) {  // fitted inside the viewport
        EXPECT_GT(t.x[i], 0.0);
        EXPECT_LT(t.x[i], cfg.width);
        EXPECT_GT(t.y[i], 0.0);
        EXPECT_LT(t.y[i], cfg.height);
      }
    }
    EXPECT_EQ(front, 6);
    // STL stores 36 separate corners: they must still map to exactly 8 screen positions.
    EXPECT_EQ(corner_uses(s).size(), 8u);
    if (reference_area == 0.0) reference_area = area;
    EXPECT_NEAR(area, reference_area, 1e-6 * reference_area);
  }
}

TEST(MeshLoader, NotWhatTheExtensionSays) {
  const RasterConfig cfg;
  const CameraOptions cam;
  for (const char* name : {"garbage.obj", "not_stl.stl", "obj_content.ply", "bomb.off"}) {
    SCOPED_TRACE(name);
    const std::string path = kData + name;
    const std::string msg = scene_error([&] { load_scene(path, cfg, cam); });
    EXPECT_EQ(msg.rfind(path + ": not a readable mesh: ", 0), 0u) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos);
  }
  TempFile binary("noise.glb", std::string("glTF\x02\0\0\0\x10\0\0\0garbage", 19));
  EXPECT_NE(scene_error([&] { load_mesh(binary.path, cfg, cam); }).find("not a readable mesh"),
            std::string::npos);
}

TEST(MeshLoader, AssimpInvalidModelsGiveSceneError) {
  const std::string dir = "/usr/share/assimp/models/invalid/";
  struct stat st;
  if (::stat(dir.c_str(), &st) != 0) GTEST_SKIP() << dir << " not installed";
  for (const char* name : {"empty.obj", "empty.off", "empty.ply", "malformed.obj",
                           "OutOfMemory.off", "empty.3ds", "empty.x", "emptyIrrMesh.xml"}) {
    SCOPED_TRACE(name);
    if (::stat((dir + name).c_str(), &st) != 0) continue;
    try {
      const Scene s = load_scene(dir + name, RasterConfig{}, CameraOptions{});
      // A loader may salvage something; then it must be triangles, not a crash.
      EXPECT_FALSE(s.tris.empty());
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("not a readable mesh"), std::string::npos) << e.what();
    }
  }
}

// ---------------------------------------------------------------- camera and projection

TEST(Projection, SharedVerticesAreBitIdentical) {
  const RasterConfig cfg;
  const Mesh torus = make_torus(40, 20, 1.0, 0.35, glm::dvec3(0.0));
  Scene s;
  project_mesh(torus, orbit_camera(bounding_sphere(torus), cfg, CameraOptions{}), cfg, s);
  ASSERT_EQ(s.tris.size(), torus.faces.size());
  // Every torus vertex is its own screen position, used by its 6 faces.
  const auto uses = corner_uses(s);
  EXPECT_EQ(uses.size(), torus.positions.size());
  for (const auto& kv : uses) EXPECT_EQ(kv.second, 6);
}

TEST(Projection, NearPlaneCutsAgreeAcrossEdges) {
  const RasterConfig cfg;
  // Camera inside a big torus tube: the near plane cuts many faces of a closed mesh.
  const Mesh torus = make_torus(64, 32, 4.0, 1.5, glm::dvec3(0.0));
  CameraView view;
  view.eye = glm::dvec3(4.0, 0.0, 0.0);
  view.target = glm::dvec3(4.0, 0.0, -1.0);
  view.near_plane = 0.3;
  Scene s;
  project_mesh(torus, view, cfg, s);
  ASSERT_GT(s.near_clipped, 0u);
  ASSERT_GT(s.near_dropped, 0u);
  ASSERT_EQ(s.range_dropped, 0u);
  // In a closed mesh every point lies on at least two kept pieces: an original vertex on all its
  // faces, a cut point on both faces of its edge. A cut computed differently from the two sides
  // would leave points used once.
  for (const auto& kv : corner_uses(s)) EXPECT_GE(kv.second, 2);
}

TEST(Projection, NearPlaneCounts) {
  RasterConfig cfg;
  cfg.width = 100;
  cfg.height = 100;
  CameraView view;  // eye at z = 1 looking down -z, near plane at z = 0.9
  view.eye = glm::dvec3(0.0, 0.0, 1.0);
  view.target = glm::dvec3(0.0);
  view.near_plane = 0.1;
  Mesh mesh;
  mesh.positions = {{-0.2, -0.2, 0.0}, {0.2, -0.2, 0.0}, {0.0, 0.2, 0.0},  // in front
                    {0.0, 0.2, 2.0},                                       // behind the eye
                    {-0.2, -0.2, 2.0}, {0.2, -0.2, 2.0}};
  mesh.faces = {{0, 1, 2}, {0, 1, 3}, {0, 4, 3}, {4, 5, 3}};
  Scene s;
  project_mesh(mesh, view, cfg, s);
  // Face 0 whole; face 1 one vertex behind: a quad, 2 pieces; face 2 two behind: 1 piece;
  // face 3 wholly behind.
  EXPECT_EQ(s.tris.size(), 1u + 2u + 1u);
  EXPECT_EQ(s.near_clipped, 2u);
  EXPECT_EQ(s.near_dropped, 1u);
  EXPECT_EQ(s.range_dropped, 0u);
  // Face 0 is centred: its top vertex (0, 0.2) lands on the vertical centre line.
  EXPECT_DOUBLE_EQ(s.tris[0].x[2], 50.0);
  // Winding is kept: face 0 is counter-clockwise seen from the eye and stays counter-clockwise
  // on screen (negative area in y-down coordinates); face 2 is seen from behind.
  EXPECT_LT(signed_area(s.tris[0]), 0.0);
  EXPECT_GT(signed_area(s.tris[3]), 0.0);
}

TEST(Projection, OutOfRangeTrianglesAreDropped) {
  RasterConfig cfg;
  cfg.coord_int_bits = 12;  // range [-2048, 2048)
  CameraView view;
  view.eye = glm::dvec3(0.0, 0.0, 1.0);
  view.target = glm::dvec3(0.0);
  view.near_plane = 0.01;
  Mesh mesh;
  mesh.positions = {{-0.1, 0.0, 0.0}, {0.1, 0.0, 0.0}, {0.0, 0.1, 0.0},
                    {-0.1, 0.0, 0.98}, {0.1, 0.0, 0.98}, {0.0, 0.1, 0.98}};  // 2 in front of eye
  mesh.faces = {{0, 1, 2}, {3, 4, 5}};
  Scene s;
  project_mesh(mesh, view, cfg, s);
  EXPECT_EQ(s.tris.size(), 1u);
  EXPECT_EQ(s.range_dropped, 1u);
  EXPECT_FALSE(representable(2048.0, cfg));
  EXPECT_FALSE(representable(2047.999, cfg));  // rounds up to 2048
  EXPECT_TRUE(representable(-2048.0, cfg));
  EXPECT_FALSE(representable(std::nan(""), cfg));
}

// ---------------------------------------------------------------- built-ins

TEST(Builtin, EveryBuiltinIsDeterministicAndSetsUp) {
  RasterConfig cfg;
  cfg.width = 640;
  cfg.height = 480;
  const CameraOptions cam;
  ASSERT_GE(builtin_scenes().size(), 30u);
  for (const BuiltinInfo& info : builtin_scenes()) {
    SCOPED_TRACE(info.name);
    EXPECT_FALSE(info.description.empty());
    EXPECT_EQ(info.description.find('\n'), std::string::npos);
    const Scene a = load_scene("builtin:" + info.name, cfg, cam);
    const Scene b = make_builtin(info.name, cfg, cam);
    EXPECT_GT(a.tris.size(), 0u);
    EXPECT_LE(a.tris.size(), 200000u);
    EXPECT_EQ(a.name, "builtin:" + info.name);
    EXPECT_TRUE(same_bits(a, b));
    // Every coordinate is finite and inside the default range: setup must accept the scene.
    EXPECT_NO_THROW(setup_scene(a.tris, cfg));
    if (info.description.find("seed=") != std::string::npos) {
      const Scene c = make_builtin(info.name + ":seed=2", cfg, cam);
      const Scene d = make_builtin(info.name + ":seed=2", cfg, cam);
      EXPECT_TRUE(same_bits(c, d));
      EXPECT_FALSE(same_bits(a, c)) << "seed changes nothing";
    }
  }
}

TEST(Builtin, DescriptionsListEveryKeyWithItsDefault) {
  const std::set<std::string> expected = {
      "random", "fan", "quad-grid", "strip", "sphere", "torus", "surface", "lowpoly-far",
      "lowpoly-near", "highpoly-far", "highpoly-near", "mixed", "hard-shared-edges",
      "hard-centre-edges", "hard-vertex-on-centre", "hard-horizontal-edges",
      "hard-middle-vertex-row", "hard-vertical", "hard-near-horizontal", "hard-slivers",
      "hard-degenerate", "hard-tiny", "hard-large-coords", "hard-negative", "hard-snap-ties",
      "hard-viewport-edges", "hard-whole-screen", "hard-one-vertex", "hard-t-junctions",
      "hard-projected", "hard-all"};
  std::set<std::string> names;
  for (const auto& info : builtin_scenes()) names.insert(info.name);
  EXPECT_EQ(names, expected);
  for (const auto& info : builtin_scenes()) {
    if (info.name != "random") continue;
    for (const char* key : {"count=1000", "size=mixed", "grid=float", "margin=0", "seed=1"})
      EXPECT_NE(info.description.find(key), std::string::npos) << key;
  }
}

TEST(Builtin, ErrorsNameTheBuiltinAndKey) {
  const RasterConfig cfg;
  const CameraOptions cam;
  auto err = [&](const std::string& arg) {
    return scene_error([&] { load_scene(arg, cfg, cam); });
  };
  EXPECT_EQ(err("builtin:nope"), "builtin:nope: unknown built-in scene (see `trirast scenes`)");
  EXPECT_EQ(err("builtin:nope:count=3"),
            "builtin:nope: unknown built-in scene (see `trirast scenes`)");
  EXPECT_EQ(err("builtin:random:foo=1"), "builtin:random: unknown key 'foo'");
  EXPECT_EQ(err("builtin:fan:seed=1"), "builtin:fan: unknown key 'seed'");
  EXPECT_EQ(err("builtin:random:count=x").rfind("builtin:random: bad value for 'count': 'x'", 0),
            0u);
  EXPECT_EQ(err("builtin:random:count=0").rfind("builtin:random: bad value for 'count': '0'", 0),
            0u);
  EXPECT_EQ(err("builtin:random:count=12abc")
                .rfind("builtin:random: bad value for 'count': '12abc'", 0),
            0u);
  EXPECT_EQ(err("builtin:random:size=enormous")
                .rfind("builtin:random: bad value for 'size': 'enormous'", 0),
            0u);
  EXPECT_EQ(err("builtin:fan:radius=nan").rfind("builtin:fan: bad value for 'radius': 'nan'", 0),
            0u);
  EXPECT_EQ(err("builtin:random:count=3,count=4"), "builtin:random: key 'count' given twice");
  EXPECT_EQ(err("builtin:random:count"), "builtin:random: expected key=value, got 'count'");
}

TEST(Builtin, RandomSizeClassesAndGrids) {
  RasterConfig cfg;
  cfg.width = 320;
  cfg.height = 200;
  const CameraOptions cam;
  const Scene tiny = make_builtin("random:count=500,size=tiny", cfg, cam);
  ASSERT_EQ(tiny.tris.size(), 500u);
  for (const auto& t : tiny.tris) EXPECT_LT(std::abs(signed_area(t)), 1.0);
  const Scene large = make_builtin("random:count=200,size=large,seed=7", cfg, cam);
  for (const auto& t : large.tris) {
    EXPECT_GT(std::abs(signed_area(t)), 100.0);  // 10^4 px^2, shrunk to fit a 320x200 screen
    for (int i = 0; i < 3; ++i) {               // margin=0: vertices inside the viewport
      EXPECT_GE(t.x[i], 0.0);
      EXPECT_LE(t.x[i], cfg.width);
      EXPECT_GE(t.y[i], 0.0);
      EXPECT_LE(t.y[i], cfg.height);
    }
  }
  const Scene half = make_builtin("random:count=300,grid=half", cfg, cam);
  const Scene sub = make_builtin("random:count=300,grid=subpixel,margin=50", cfg, cam);
  bool outside = false;
  for (size_t k = 0; k < 300; ++k)
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(half.tris[k].x[i] * 2, std::nearbyint(half.tris[k].x[i] * 2));
      EXPECT_EQ(sub.tris[k].y[i] * 256, std::nearbyint(sub.tris[k].y[i] * 256));
      EXPECT_GE(sub.tris[k].x[i], -50.0);
      outside |= sub.tris[k].x[i] < 0.0 || sub.tris[k].y[i] > cfg.height;
    }
  EXPECT_TRUE(outside) << "margin=50 never used";
}

// Single-triangle hard cases hold each triangle in 6 vertex orders, consecutively.
TEST(Builtin, HardCasesComeInAllSixOrders) {
  const RasterConfig cfg;
  for (const char* name : {"hard-centre-edges", "hard-vertex-on-centre", "hard-horizontal-edges",
                           "hard-middle-vertex-row", "hard-degenerate", "hard-tiny",
                           "hard-negative", "hard-snap-ties", "hard-slivers"}) {
    SCOPED_TRACE(name);
    const Scene s = make_builtin(name, cfg, CameraOptions{});
    ASSERT_EQ(s.tris.size() % 6, 0u);
    for (size_t k = 0; k < s.tris.size(); k += 6) {
      std::multiset<std::pair<double, double>> first;
      for (int i = 0; i < 3; ++i) first.insert({s.tris[k].x[i], s.tris[k].y[i]});
      for (size_t j = 1; j < 6; ++j) {
        std::multiset<std::pair<double, double>> other;
        for (int i = 0; i < 3; ++i) other.insert({s.tris[k + j].x[i], s.tris[k + j].y[i]});
        EXPECT_EQ(first, other);
      }
      // Orders 3..5 have the opposite winding of 0..2.
      const double a = signed_area(s.tris[k]);
      if (std::abs(a) > 1e-6) {
        EXPECT_NEAR(signed_area(s.tris[k + 1]), a, 1e-9 * std::abs(a) + 1e-12);
        EXPECT_NEAR(signed_area(s.tris[k + 3]), -a, 1e-9 * std::abs(a) + 1e-12);
      }
    }
  }
}

TEST(Builtin, HardSnapTiesAreExactlyHalfway) {
  const RasterConfig cfg;
  const Scene s = make_builtin("hard-snap-ties", cfg, CameraOptions{});
  bool negative = false;
  for (const auto& t : s.tris)
    for (int i = 0; i < 3; ++i)
      for (double v : {t.x[i], t.y[i]}) {
        const double scaled = v * 256.0;  // exact: a power of two
        EXPECT_EQ(scaled - std::floor(scaled), 0.5) << v;
        negative |= v < 0;
      }
  EXPECT_TRUE(negative);
}

TEST(Builtin, HardLargeCoordsReachTheRange) {
  const RasterConfig cfg;
  const Scene s = make_builtin("hard-large-coords", cfg, CameraOptions{});
  double lo = 0, hi = 0;
  for (const auto& t : s.tris)
    for (int i = 0; i < 3; ++i) {
      lo = std::min({lo, t.x[i], t.y[i]});
      hi = std::max({hi, t.x[i], t.y[i]});
    }
  EXPECT_LE(lo, -32000.0);
  EXPECT_GE(hi, 32000.0);
  EXPECT_NO_THROW(setup_scene(s.tris, cfg));
}

TEST(Builtin, ProjectedScenesCountNearPlaneWork) {
  const RasterConfig cfg;
  const Scene s = make_builtin("hard-projected", cfg, CameraOptions{});
  EXPECT_GT(s.near_clipped, 0u);
  EXPECT_GT(s.near_dropped, 0u);
  const Scene sphere = make_builtin("sphere:tess=12", cfg, CameraOptions{});
  EXPECT_EQ(sphere.tris.size(), size_t(2 * 24 * 11));
  EXPECT_EQ(sphere.near_clipped + sphere.near_dropped + sphere.range_dropped, 0u);
}

// Closed 2D configurations must share bit-identical vertices: checked by rasterizing with the
// test reference rasterizer and the watertightness check.
TEST(Builtin, ClosedConfigurationsAreWatertight) {
  RasterConfig cfg;
  cfg.width = 320;
  cfg.height = 240;
  for (const char* spec : {"fan:n=7,centre=pixel", "fan:n=5,centre=free,rotation=13",
                           "quad-grid:cols=9,rows=7,angle=37,diag=alternate",
                           "quad-grid:angle=0,diag=anti,cols=8,rows=8", "strip:n=40"}) {
    SCOPED_TRACE(spec);
    const Scene s = make_builtin(spec, cfg, CameraOptions{});
    const SetupResult setup = setup_scene(s.tris, cfg);
    const SpanList spans = test::reference_raster(s.tris, cfg);
    const WatertightResult w = check_watertight(setup, spans, cfg);
    EXPECT_GT(w.covered, 1000);
    EXPECT_EQ(w.doubles, 0) << w.first_problem;
    EXPECT_EQ(w.cracks, 0) << w.first_problem;
  }
}

}  // namespace
}  // namespace trirast
