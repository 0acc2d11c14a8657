// The sub-grid's search for open rims on a whole volume (volume/hidden_quads.h, docs/volume.md
// "Hidden surfaces"): a plate over the ground, lit from straight above, with a hole 0.72 texel
// wide between the texel centres of a 32^2 map (front capture: the plate is open). Every texel
// centre sees the plate, so without the rims the sheet covers the hole and the ground under it
// is in shadow; the rim puts the hole's quad on the sub-grid, whose nodes see the ground through
// it, and the volume leaves the hole's light through. A builder reused across builds searches as a
// fresh one does.
#include <gtest/gtest.h>

#include "mesh_invariants.h"
#include "refined_options.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/primitives.h"
#include "shadowvol/scene.h"
#include "test_util.h"

namespace shadowvol {
namespace {

VolumeBuildResult build(bool searchRims) {
  const Scene scene = test::sceneWith({SceneObject{"ground", "plane", makePlane(8.0, 8.0, 1)},
                                       SceneObject{"plate", "mesh", test::holedPlate(3.0, 1.0, 0.16, 0.34, 0.16, 0.34)}});
  const EmbreeDepthOracle oracle(scene);
  const DepthMap map = captureDepthEmbree(scene, 32, 32, CaptureMode::Front);
  VolumeBuildOptions o = test::refinedWithRays(oracle, 6);
  o.refineSubdivisions = 4;
  o.nearerSurfaces = oracle.nearerSurfaces();
  o.refineHidden = searchRims;  // off: neither hidden surfaces nor rims
  return buildVolume(map, o);
}

TEST(OpenRimsVolume, AHoleBetweenTexelCentresLetsItsLightThrough) {
  const glm::dvec3 underHole(0.25, 0.01, 0.25), underPlate(-0.5, 0.01, 0.6);
  const VolumeBuildResult without = build(false);
  EXPECT_TRUE(test::insideVolume(without.mesh, underHole - without.mesh.origin));  // the hole is lost
  const VolumeBuildResult r = build(true);
  EXPECT_EQ(r.stats.rimQuads, r.stats.hiddenQuads);
  EXPECT_GE(r.stats.rimQuads, 1u);
  EXPECT_TRUE(test::closedOrientedManifold(r.mesh));
  EXPECT_FALSE(test::insideVolume(r.mesh, underHole - r.mesh.origin));
  EXPECT_TRUE(test::insideVolume(r.mesh, underPlate - r.mesh.origin));
}

// One VolumeBuilder reused for the sub-grid with its search (whose per-quad limits and flags it
// keeps between builds) across map sizes, captures and scenes, one with a rim and one with hidden
// quads, gives exactly what a fresh build gives.
TEST(OpenRimsVolume, AReusedBuilderSearchesAsAFreshOne) {
  const Scene holed = test::sceneWith({SceneObject{"ground", "plane", makePlane(8.0, 8.0, 1)},
                                       SceneObject{"plate", "mesh", test::holedPlate(3.0, 1.0, 0.16, 0.34, 0.16, 0.34)}});
  const Scene sphere = defaultScene();
  VolumeBuilder builder;
  VolumeBuildResult reused;
  std::size_t hidden = 0;
  for (const Scene* scene : {&holed, &sphere, &holed})
    for (const int n : {32, 48, 24})
      for (const CaptureMode mode : {CaptureMode::Front, CaptureMode::Back}) {
        const EmbreeDepthOracle oracle(*scene);
        const DepthMap map = captureDepthEmbree(*scene, n, n, mode);
        VolumeBuildOptions o = test::refinedWithRays(oracle, 6);
        o.refineSubdivisions = 4;
        o.nearerSurfaces = oracle.nearerSurfaces();
        const VolumeBuildResult fresh = buildVolume(map, o);
        builder.build(map, o, reused);
        EXPECT_EQ(reused.mesh.positions, fresh.mesh.positions) << n << " " << toString(mode);
        EXPECT_EQ(reused.mesh.triangles, fresh.mesh.triangles) << n << " " << toString(mode);
        EXPECT_EQ(reused.stats.hiddenQuads, fresh.stats.hiddenQuads) << n << " " << toString(mode);
        hidden += fresh.stats.hiddenQuads;
      }
  EXPECT_GT(hidden, 0u);
}

}  // namespace
}  // namespace shadowvol
