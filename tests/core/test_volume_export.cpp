// Exported volumes read back through OpenMesh's half-edge kernel (as MeshLab or Blender would)
// with every vertex and triangle: the exact cap's pinch copies keep the mesh manifold.
#include <gtest/gtest.h>

#include "shadowvol/mesh_io.h"
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

}  // namespace
}  // namespace shadowvol
