// The sub-grid's rim bias on a whole volume (volume/rim_bias.h): a slab 0.1 thick seen from above
// with front capture at 64^2, where the bias B is a texel footprint (0.125 here, more than the
// slab's thickness). Along its outline the wall's top stands near the rim: a point 0.05 under the
// top (within B of it) just inside the outline lies in the volume, where the plain refined volume
// (no sub-grid, the whole B) leaves it out; the top itself stays out (no acne at the rim). And a
// block whose side is lit nearly edge-on: the wall's top at its outline goes down to where the
// side ends, so the side's lit face stays out of the volume all the way down.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

#include "mesh_invariants.h"
#include "refined_options.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/scene.h"
#include "test_util.h"

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
  return test::fittedScene(json, "slab.json");
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

// The scene's volumes from its front-capture map at 64^2, refined with K = 6 (and the snap): plain,
// and on the 4 x 4 sub-grid.
struct FrontVolumes {
  VolumeBuildResult plain, grid;
};
FrontVolumes frontVolumes(const Scene& scene) {
  const EmbreeDepthOracle oracle(scene);
  const DepthMap map = captureDepthEmbree(scene, 64, 64, CaptureMode::Front);
  VolumeBuildOptions o = test::refinedWithRays(oracle, 6);
  FrontVolumes v{buildVolume(map, o), {}};
  o.refineSubdivisions = 4;
  v.grid = buildVolume(map, o);
  return v;
}

TEST(RimBiasVolume, TheWallsTopStandsNearTheRimWithoutAcne) {
  const auto [plain, grid] = frontVolumes(slab());
  ASSERT_GT(grid.stats.biasUsed, 0.1);  // the texel footprint, more than the slab's thickness
  ASSERT_GT(grid.stats.snappedCrossings, 50u);
  EXPECT_GT(grid.stats.rimCrossings, 50u);
  EXPECT_EQ(plain.stats.rimCrossings, 0u);  // no sub-grid: the walls keep the whole bias
  const double inset = 0.002;  // world units: 1/60 of a texel
  EXPECT_EQ(insideAlongOutline(plain.mesh, inset, kTop - 0.05), 0);
  EXPECT_EQ(insideAlongOutline(grid.mesh, inset, kTop - 0.05), 160);
  // The straight outline keeps straight walls in the plain quads (their snapped chord points lie on
  // them; the fan from a chord point tilted the sheet here: 148 of the 160 above).
  EXPECT_GT(grid.stats.refinedCells - grid.stats.subgridQuads, 40u);
  EXPECT_EQ(grid.stats.plainBends, 0u);
  EXPECT_EQ(insideAlongOutline(grid.mesh, inset, kTop - 1e-4), 0);  // the lit top
  EXPECT_EQ(insideAlongOutline(plain.mesh, inset, kTop - 1e-4), 0);
}

// A block 0.5 high and 2 wide, 1.25 above the ground, turned 0.2 degrees about z under a light
// straight down: its +x side faces the light at N.L = sin(0.2 deg), about 0.0035, and its image
// from the light is a strip 0.0017 wide (1/70 of a texel at 64^2) along the block's outline,
// falling 0.5 in depth across it.
constexpr double kTilt = 0.2, kBlockTop = 1.75, kBlockHeight = 0.5;

Scene tiltedBlock() {
  const std::string json =
      R"({"objects": [{"type": "plane", "name": "ground", "size": 8}, {"type": "box", "name": "block", "size": [2, 0.5, 2],
      "transform": {"translate": [0, 1.5, 0], "rotate": [0, 0, )" +
      std::to_string(kTilt) + R"(]}}],
      "light": {"type": "directional", "direction": [0, -1, 0], "position": [0, 5, 0], "extent": 4},
      "camera": {"eye": [0, 7, 5], "target": [0, 0, 0], "fov": 50}})";
  return test::fittedScene(json, "block.json");
}

// How many of 40 x 8 points on the block's lit +x side (40 along it, 8 heights from 0.1 to 0.45
// under its top edge), 1e-4 off it along its normal, lie in the volume.
int insideOnLitSide(const VolumeMesh& mesh) {
  const double a = glm::radians(kTilt);
  const glm::dvec3 normal(std::cos(a), std::sin(a), 0.0);
  int in = 0;
  for (int k = 0; k < 40; ++k)
    for (int h = 0; h < 8; ++h) {
      const double z = -0.9 + 1.8 * (k + 0.5) / 40.0, y = kBlockHeight / 2 - (0.1 + 0.05 * h);
      // The block's own frame (centre at the origin) turned about +z, then moved to its centre.
      const glm::dvec3 local(1.0, y, z);
      const glm::dvec3 p(std::cos(a) * local.x - std::sin(a) * local.y, std::sin(a) * local.x + std::cos(a) * local.y,
                         local.z);
      in += test::insideVolume(mesh, p + glm::dvec3(0, kBlockTop - kBlockHeight / 2, 0) + 1e-4 * normal - mesh.origin)
                ? 1
                : 0;
    }
  return in;
}

TEST(RimBiasVolume, ASideLitNearlyEdgeOnStaysOutAllTheWayDown) {
  const VolumeBuildResult grid = frontVolumes(tiltedBlock()).grid;
  ASSERT_GT(grid.stats.biasUsed, 0.1);  // a texel footprint, 0.125: a fifth of the side's fall
  ASSERT_GT(grid.stats.rimCrossings, 10u);
  EXPECT_TRUE(test::closedOrientedManifold(grid.mesh));
  EXPECT_EQ(insideOnLitSide(grid.mesh), 0);
  // The block's shadow on the ground is there.
  EXPECT_TRUE(test::insideVolume(grid.mesh, glm::dvec3(0.3, 0.01, 0.2) - grid.mesh.origin));
}

}  // namespace
}  // namespace shadowvol
