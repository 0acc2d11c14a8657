// The sub-grid's rim bias on a whole volume (volume/rim_bias.h): a slab 0.1 thick seen from above
// with front capture at 64^2, where the bias B is a texel footprint (0.125 here, more than the
// slab's thickness). Along its outline the wall's top stands near the rim: a point 0.05 under the
// top (within B of it) just inside the outline lies in the volume, where the plain refined volume
// (no sub-grid, the whole B) leaves it out; the top itself stays out (no acne at the rim).
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

#include "mesh_invariants.h"
#include "refined_options.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/scene.h"

namespace shadowvol {
namespace {

constexpr double kTurn = 30.0, kTop = 1.55;

Scene slab() {
  const std::string json =
      R"({"objects": [{"type": "plane", "name": "ground", "size": 8}, {"type": "box", "name": "slab", "size": [2, 0.1, 2],
      "transform": {"translate": [0, 1.5, 0], "rotate": [0, )" +
      std::to_string(kTurn) + R"(, 0]}}],
      "light": {"type": "directional", "direction": [0, -1, 0], "position": [0, 5, 0], "extent": 4},
      "camera": {"eye": [0, 7, 5], "target": [0, 0, 0], "fov": 50}})";
  Scene scene = parseScene(json, "slab.json", ".").scene;
  fitLightAndCamera(scene);
  return scene;
}

// How many of the points `inset` inside the slab's outline (world units, in its own frame), at
// height y, lie in the volume: 40 along each of the four sides.
int insideAlongOutline(const VolumeMesh& mesh, double inset, double y) {
  const double a = glm::radians(kTurn);
  int in = 0;
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < 40; ++k) {
      const double u = -0.9 + 1.8 * (k + 0.5) / 40.0, v = 1.0 - inset;
      const double x = side == 0 ? v : side == 1 ? -v : u, z = side == 2 ? v : side == 3 ? -v : u;
      // The box's rotation about +y (as the scene file's transform turns it).
      const glm::dvec3 p(std::cos(a) * x + std::sin(a) * z, y, -std::sin(a) * x + std::cos(a) * z);
      in += test::insideVolume(mesh, p - mesh.origin) ? 1 : 0;
    }
  return in;
}

TEST(RimBiasVolume, TheWallsTopStandsNearTheRimWithoutAcne) {
  const Scene scene = slab();
  const EmbreeDepthOracle oracle(scene);
  const DepthMap map = captureDepthEmbree(scene, 64, 64, CaptureMode::Front);
  VolumeBuildOptions o = test::refinedWithRays(oracle, 6);
  const VolumeBuildResult plain = buildVolume(map, o);
  o.refineSubdivisions = 4;
  const VolumeBuildResult grid = buildVolume(map, o);
  ASSERT_GT(grid.stats.biasUsed, 0.1);  // the texel footprint, more than the slab's thickness
  ASSERT_GT(grid.stats.snappedCrossings, 50u);
  EXPECT_GT(grid.stats.rimCrossings, 50u);
  EXPECT_EQ(plain.stats.rimCrossings, 0u);  // no sub-grid: the walls keep the whole bias
  const double inset = 0.002;  // world units: 1/60 of a texel
  EXPECT_EQ(insideAlongOutline(plain.mesh, inset, kTop - 0.05), 0);
  EXPECT_EQ(insideAlongOutline(grid.mesh, inset, kTop - 0.05), 160);
  EXPECT_EQ(insideAlongOutline(grid.mesh, inset, kTop - 1e-4), 0);  // the lit top
  EXPECT_EQ(insideAlongOutline(plain.mesh, inset, kTop - 1e-4), 0);
}

}  // namespace
}  // namespace shadowvol
