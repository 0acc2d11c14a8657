// Mesh formats read through Assimp (glTF, FBX, COLLADA, ...) and the child process that isolates
// it: the same triangles as written, refusals instead of crashes, limits that hold.
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "mesh_readers/isolated_call.h"
#include "shadowvol/error.h"
#include "shadowvol/mesh_io.h"
#include "shadowvol/primitives.h"
#include "test_util.h"

namespace shadowvol {
namespace {

using mesh_readers::IsolationLimits;
using mesh_readers::runIsolated;

// `mesh` written as glTF in `dir` (box.gltf), read back as JSON for a test to alter.
nlohmann::json writtenGltf(const std::filesystem::path& dir, const TriangleMesh& mesh) {
  const auto written = dir / "box.gltf";
  writeTriangleMesh(mesh, written);
  std::ifstream in(written);
  return nlohmann::json::parse(in);
}

TEST(IsolatedCall, HandsBackTheBytesOrTheExceptionMessage) {
  const auto ok = runIsolated([] { return std::string("abc\0def", 7); });
  EXPECT_TRUE(ok.ok);
  EXPECT_EQ(ok.output, std::string("abc\0def", 7));
  const auto big = runIsolated([] { return std::string(3 << 20, 'x'); });  // more than a pipe holds
  EXPECT_TRUE(big.ok);
  EXPECT_EQ(big.output.size(), std::size_t(3 << 20));
  const auto failed = runIsolated([]() -> std::string { throw InputError("f.glb", "", "", "bad header"); });
  EXPECT_FALSE(failed.ok);
  EXPECT_EQ(failed.output, "f.glb: bad header");
}

TEST(IsolatedCall, ACrashEndsTheChildNotTheCaller) {
  const auto r = runIsolated([]() -> std::string {
    std::raise(SIGSEGV);
    return "unreachable";
  });
  const auto aborted = runIsolated([]() -> std::string { std::abort(); });
  EXPECT_FALSE(r.ok);
  EXPECT_FALSE(aborted.ok);
#if defined(__SANITIZE_ADDRESS__)  // ASan reports the fault and exits with 1 instead
  EXPECT_NE(r.output.find("ended without a result (exit 1)"), std::string::npos) << r.output;
#else
  EXPECT_NE(r.output.find("crashed (signal 11"), std::string::npos) << r.output;
  EXPECT_NE(aborted.output.find("crashed (signal 6"), std::string::npos) << aborted.output;
#endif
}

TEST(IsolatedCall, AnEndlessLoopIsStoppedAtTheTimeLimit) {
  IsolationLimits limits;
  limits.seconds = 1;
  const auto r = runIsolated(
      []() -> std::string {
        volatile unsigned long n = 0;
        for (;;) n = n + 1;
      },
      limits);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.output.find("took more than 1 s"), std::string::npos) << r.output;
}

TEST(IsolatedCall, OutputBeyondTheLimitIsRefused) {
  IsolationLimits limits;
  limits.outputBytes = 1 << 20;
  const auto r = runIsolated([] { return std::string(4 << 20, 'x'); }, limits);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.output.find("more than 1 MiB"), std::string::npos) << r.output;
}

#if !defined(__SANITIZE_ADDRESS__)
TEST(IsolatedCall, AllocationBeyondTheMemoryLimitIsRefused) {
  IsolationLimits limits;
  limits.addressSpace = 256ull << 20;
  const auto r = runIsolated(
      [] {
        std::vector<std::string> hog;
        for (int k = 0; k < 64; ++k) hog.emplace_back(64 << 20, 'x');  // 4 GiB in all
        return std::string("kept ") + std::to_string(hog.size());
      },
      limits);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.output.find("ran out of memory"), std::string::npos) << r.output;
}
#endif

// Written by our glTF writer, read back by Assimp: an independent reader, the same mesh.
TEST(AssimpReader, GltfAndGlbReadBackAsWritten) {
  const TriangleMesh box = makeBox(2, 1, 4);
  for (const char* name : {"box.glb", "box.gltf"}) {
    const auto path = test::tempDir() / name;
    writeTriangleMesh(box, path);
    const TriangleMesh back = readTriangleMesh(path);
    ASSERT_EQ(back.triangles.size(), box.triangles.size()) << name;
    ASSERT_EQ(back.positions.size(), box.positions.size()) << name;  // welded to the 8 corners
    for (std::size_t t = 0; t < box.triangles.size(); ++t)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(back.positions[back.triangles[t][c]], box.positions[box.triangles[t][c]]) << name << " triangle " << t;
  }
}

// Regression (a hostile-input probe): a glTF node matrix of zeros collapsed the mesh to a point.
// A glTF whose only primitive is points holds no triangle: said so, not in Assimp's words
// ("No meshes remaining").
TEST(AssimpReader, AFileOfOnlyPointsHasNoTriangles) {
  const auto dir = test::tempDir();
  nlohmann::json g = writtenGltf(dir, makeBox(1, 1, 1));
  for (auto& mesh : g.at("meshes"))
    for (auto& primitive : mesh.at("primitives")) {
      primitive["mode"] = 0;  // POINTS
      primitive.erase("indices");
    }
  test::writeText(dir / "points.gltf", g.dump());
  try {
    readTriangleMesh(dir / "points.gltf");
    ADD_FAILURE() << "a file of points was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no triangles (points and lines are dropped)"), std::string::npos) << e.what();
  }
}

// A singular or non-finite node transformation is refused, naming the node; a sound one still
// places the mesh.
TEST(AssimpReader, SingularNodeTransformationsAreRefused) {
  const auto dir = test::tempDir();
  const nlohmann::json gltf = writtenGltf(dir, makeBox(1, 1, 1));
  ASSERT_EQ(gltf.at("nodes").size(), 1u);
  auto withNode = [&](const char* name, const nlohmann::json& node) {
    nlohmann::json g = gltf;
    for (const auto& [key, value] : node.items()) g["nodes"][0][key] = value;
    const auto path = dir / name;
    test::writeText(path, g.dump());
    return path;
  };
  const nlohmann::json zeros = {{"name", "flat"}, {"matrix", std::vector<double>(16, 0.0)}};
  const nlohmann::json noDepth = {{"name", "flat"}, {"scale", {1.0, 0.0, 1.0}}};
  for (const auto& [name, node] : {std::pair{"zeros.gltf", zeros}, std::pair{"scale0.gltf", noDepth}}) {
    const auto path = withNode(name, node);
    try {
      readTriangleMesh(path);
      ADD_FAILURE() << name << " was read";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_EQ(e.source(), path.string()) << m;
      EXPECT_NE(m.find("node /"), std::string::npos) << m;
      EXPECT_NE(m.find("flat"), std::string::npos) << m;
      EXPECT_NE(m.find("determinant 0"), std::string::npos) << m;
    }
  }
  const TriangleMesh moved = readTriangleMesh(withNode("moved.gltf", {{"translation", {10.0, 0.0, 0.0}}}));
  ASSERT_FALSE(moved.positions.empty());
  for (const auto& p : moved.positions) EXPECT_GT(p.x, 9.0f);
  // A large uniform scale is not singular (an adversarial run: its float determinant, 1e39,
  // overflowed and was called 0): the mesh is placed, 1e13 times larger.
  const TriangleMesh large = readTriangleMesh(withNode("large.gltf", {{"scale", {1e13, 1e13, 1e13}}}));
  ASSERT_FALSE(large.positions.empty());
  float extent = 0.0f;
  for (const auto& p : large.positions) extent = std::max(extent, std::abs(p.x));
  EXPECT_GT(extent, 1e12f);
  EXPECT_TRUE(std::isfinite(extent));
}

// A node that mirrors its mesh (negative determinant) makes clockwise the front face (glTF 2.0,
// "Transformations"): the reader reverses the winding, so an outward box under a mirroring node
// reads outward (a probe found it inside out), as the scene file's own mirrors keep faces outward.
TEST(AssimpReader, MirroringNodeKeepsFacesOutward) {
  const auto dir = test::tempDir();
  nlohmann::json gltf = writtenGltf(dir, makeBox(1, 2, 3));
  ASSERT_EQ(gltf.at("nodes").size(), 1u);
  for (const auto& scale : {std::vector<double>{-1.0, 1.0, 1.0}, std::vector<double>{-1.0, -1.0, -2.0},
                            std::vector<double>{1.0, -1.0, -1.0}}) {
    gltf["nodes"][0]["scale"] = scale;
    const auto path = dir / "mirrored.gltf";
    test::writeText(path, gltf.dump());
    const double expected = 6.0 * std::abs(scale[0] * scale[1] * scale[2]);
    EXPECT_NEAR(test::signedVolume(readTriangleMesh(path)), expected, 1e-4) << scale[0] << " " << scale[1] << " " << scale[2];
  }
}

TEST(AssimpReader, BrokenFilesAreRefusedNamingTheFile) {
  const TriangleMesh box = makeBox(1, 1, 1);
  const auto good = test::tempDir() / "whole.glb";
  writeTriangleMesh(box, good);
  std::ifstream in(good, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 100u);
  std::vector<std::pair<std::string, std::string>> bad = {
      {"empty.glb", ""}, {"noise.fbx", std::string(4000, '\x7f')}, {"noise.dae", "<COLLADA><library_geometries>"},
      {"noise.3ds", std::string("\x4d\x4d\xff\xff\xff\x7f", 6) + std::string(100, '\0')}};
  for (std::size_t cut : {std::size_t(12), std::size_t(20), bytes.size() / 2, bytes.size() - 4})
    bad.push_back({"cut" + std::to_string(cut) + ".glb", bytes.substr(0, cut)});
  for (const auto& [name, content] : bad) {
    const auto path = test::tempDir() / name;
    test::writeText(path, content);
    try {
      readTriangleMesh(path);
      ADD_FAILURE() << name << " was read";
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), path.string()) << e.what();
    }
  }
}

// The glTF of an empty volume (no mesh) reads as an empty mesh where one is allowed (`check`); a
// file whose geometry Assimp could not convert (it hands back an empty scene flagged incomplete)
// stays refused (a second reader's finding: an FBX with a bad index passed `check` as empty).
TEST(AssimpReader, OnlyAGltfDeclaringNoMeshReadsAsEmpty) {
  const auto dir = test::tempDir();
  for (const char* name : {"empty.glb", "empty.gltf"}) {
    writeTriangleMesh(TriangleMesh{}, dir / name);
    EXPECT_TRUE(readTriangleMesh(dir / name, EmptyMesh::Allow).triangles.empty()) << name;
    EXPECT_THROW(readTriangleMesh(dir / name), InputError) << name;  // no triangles: not a scene object
  }
  test::writeText(dir / "bad-index.fbx", "; FBX 7.4.0 project file\nFBXHeaderExtension:  {\n\tFBXHeaderVersion: 1003\n"
                                         "\tFBXVersion: 7400\n}\nObjects:  {\n\tGeometry: 100, \"Geometry::g\", \"Mesh\" {\n"
                                         "\t\tVertices: *9 { a: 0,0,0,1,0,0,0,1,0 }\n\t\tPolygonVertexIndex: *3 { a: 0,1,-8 }\n"
                                         "\t}\n\tModel: 200, \"Model::m\", \"Mesh\" {\n\t\tVersion: 232\n\t}\n}\n"
                                         "Connections:  {\n\tC: \"OO\",100,200\n\tC: \"OO\",200,0\n}\n");
  test::writeText(dir / "no-primitives.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0}], "meshes": [{"primitives": []}]})");
  for (const char* name : {"bad-index.fbx", "no-primitives.gltf"}) {
    try {
      readTriangleMesh(dir / name, EmptyMesh::Allow);
      ADD_FAILURE() << name << " was read as an empty mesh";
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), (dir / name).string()) << e.what();
    }
  }
}

TEST(AssimpReader, UnknownExtensionsNameTheFormatsThatAreRead) {
  const auto path = test::tempDir() / "mesh.notamesh";
  test::writeText(path, "solid x\n");
  try {
    readTriangleMesh(path);
    FAIL() << "read";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(".obj, .off, .ply, .stl"), std::string::npos) << m;
    EXPECT_NE(m.find(".fbx"), std::string::npos) << m;
    EXPECT_NE(m.find(".glb"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace shadowvol
