// Exported volumes read back through OpenMesh's half-edge kernel (as MeshLab or Blender would)
// with every vertex and triangle: the exact cap's pinch copies keep the mesh manifold.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <filesystem>
#include <string>

#include "shadowvol/error.h"
#include "shadowvol/mesh_io.h"
#include "shadowvol/primitives.h"
#include "shadowvol/volume_builder.h"
#include "test_util.h"

namespace shadowvol {
namespace {

TEST(VolumeExport, RoundTripThroughOpenMesh) {
  Light light;
  light.type = LightType::Spot;
  light.position = {0, 8, 0};
  light.direction = {0, -1, 0};
  light.fovYDegrees = 50;
  light.nearPlane = 1;
  light.farPlane = 12;
  DepthMap m = makeDepthMap(light, 40, 36, CaptureMode::Back);
  std::uint64_t s = 3;
  for (auto& d : m.depth) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    if ((s >> 33) % 100 < 35) d = float(3.0 + double((s >> 20) % 1000) * 0.005);
  }
  const auto dir = test::tempDir();
  for (FarCap cap : {FarCap::Exact, FarCap::Quad}) {
    VolumeBuildOptions o;
    o.cap = cap;
    const auto r = buildVolume(m, o);
    if (cap == FarCap::Exact) {
      EXPECT_GT(r.stats.splitVertices, 0u);  // pinches are part of the test
    }
    const TriangleMesh mesh = r.mesh.toTriangleMesh();
    ASSERT_EQ(mesh.positions.size(), r.mesh.vertexCount());
    for (const char* ext : {".ply", ".off", ".obj"}) {
      const auto path = dir / (std::string("volume_") + toString(cap) + ext);
      writeTriangleMesh(mesh, path);
      const TriangleMesh back = readTriangleMesh(path);
      EXPECT_EQ(back.positions.size(), mesh.positions.size()) << path;
      EXPECT_EQ(back.triangles.size(), mesh.triangles.size()) << path;
      EXPECT_EQ(back.triangles, mesh.triangles) << path;
    }
  }
}

// A volume far from its mesh origin (a scene whose origin stays 0 beside detail at 1e6: a
// twenty-second probe's float files held zero-area triangles) is written relative to its box's
// centre, which the file names and the writer returns; as written, nothing coincides or collapses.
TEST(VolumeExport, FloatOutputFarFromTheOriginIsRebasedAndNamed) {
  VolumeMesh v;
  const double step = 0.01;  // far below float's spacing at 1e6 (0.0625)
  const TriangleMesh box = makeBox(step, step, step);  // centred on 0
  for (const glm::vec3& p : box.positions) v.positions.push_back(glm::dvec3(p) + glm::dvec3(1e6, 2.0, -3.0));
  v.triangles.assign(box.triangles.begin(), box.triangles.end());
  const auto dir = test::tempDir();
  for (const char* ext : {".ply", ".obj", ".stl", ".glb"}) {
    const auto path = dir / (std::string("far") + ext);
    const WrittenVolume w = writeVolumeMesh(v, path);
    EXPECT_NEAR(w.origin.x, 1e6, 1e-9) << ext;
    EXPECT_EQ(w.coincidentVertices, 0u) << ext;
    EXPECT_EQ(w.collapsedTriangles, 0u) << ext;
    // Read back in double: PLY, OBJ and STL hold the coordinates relative to the origin they name;
    // glTF's node translation places them (the reader rebases them again).
    const RebasedMesh back = readRebasedTriangleMesh(path);
    const glm::dvec3 placed = std::string(ext) == ".glb" ? back.origin : w.origin;
    EXPECT_EQ(back.mesh.positions.size(), box.positions.size()) << ext;  // welded by position: none joined
    for (const glm::vec3& p : back.mesh.positions)
      EXPECT_LE(glm::length(glm::dvec3(p) + placed - glm::dvec3(1e6, 2.0, -3.0)), step) << ext;
    if (std::string(ext) == ".ply" || std::string(ext) == ".obj") {  // the origin named in the header
      EXPECT_NE(test::readText(path).find("shadowvol origin 1000000 2 -3"), std::string::npos) << ext;
    }
  }
  // An origin whose text does not fit STL's 80-byte header is refused, not cut.
  VolumeMesh odd = v;
  for (std::size_t k = 0; k < odd.positions.size(); ++k) odd.positions[k] = glm::dvec3(box.positions[k]);
  odd.origin = {-123456789012.34567, -1.2420184702932602e-07, -2.345678904447368e-07};
  EXPECT_THROW(writeVolumeMesh(odd, dir / "odd.stl"), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "odd.stl"));
  EXPECT_NO_THROW(writeVolumeMesh(odd, dir / "odd.ply"));
}

}  // namespace
}  // namespace shadowvol
