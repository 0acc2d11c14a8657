// validate's split of a depth-map method's errors by cause (error_causes.h): pixels that the same
// capture at unlimited resolution gets right (resolution) or wrong (capture). GL-free: the method
// here is the explicit volume's crossing counts, which the GPU stencil reproduces (test_validation).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/embree/embree_scene.h"
#include "shadowvol/embree/ray_queries.h"
#include "shadowvol/validate/error_causes.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol {
namespace {

struct Split {
  std::size_t wrong = 0, exactShadowed = 0;
  ErrorCauses causes;
};

// The explicit volume of a res x res map of `scene` (fitted), scored against exact shadows and
// split by cause (`volumeRing`: as a shadow volume's, the border band counted).
// `guard`: the volume's map's guard band; `judgedGuard`: that of the map the causes are split
// over (validate's, the renderer's map: the same, unless a band went missing).
Split splitOfScene(Scene scene, int res, CaptureMode mode, bool volumeRing = false, int guard = 0,
                   int judgedGuard = -1) {
  fitLightAndCamera(scene);
  const DepthMap map = captureDepthEmbree(scene, res, res, mode, guard);
  const DepthMap judged = judgedGuard < 0 ? map : captureDepthEmbree(scene, res, res, mode, judgedGuard);
  const VolumeBuildResult volume = buildVolume(map);
  const EmbreeDevice device;
  std::vector<const TriangleMesh*> meshes;
  for (const auto& o : scene.objects) meshes.push_back(&o.mesh);
  const EmbreeScene sceneRt(device, meshes);
  const CameraHits hits = castPrimaryRays(sceneRt, scene.camera);
  const std::vector<PixelClass> exact = exactShadows(sceneRt, scene, hits);
  const TriangleMesh volumeF = volume.mesh.toTriangleMesh();
  const EmbreeScene volumeRt(device, {&volumeF});
  const CrossingCounts counts = countCrossings(volumeRt, scene.camera, hits);
  std::vector<std::uint8_t> shadowed(exact.size());
  Split s;
  for (std::size_t k = 0; k < exact.size(); ++k) {
    shadowed[k] = counts.zfail[k] != 0;
    if (exact[k] == PixelClass::Shadowed) ++s.exactShadowed;
    if ((exact[k] == PixelClass::Lit || exact[k] == PixelClass::Shadowed) &&
        (exact[k] == PixelClass::Shadowed) != (shadowed[k] != 0))
      ++s.wrong;
  }
  s.causes = splitErrorCauses(scene, judged, volume.stats.biasUsed, hits, exact, shadowed, volumeRing);
  EXPECT_EQ(s.causes.offset, volume.stats.biasUsed);
  return s;
}

// The same over a ground under the spot light of test_validation's scenes, with `objects` added.
Split splitOf(const std::string& objects, int res, CaptureMode mode) {
  const std::string json = R"({"objects": [{"type": "plane", "name": "ground", "size": 20}, )" + objects +
                           R"(], "light": {"type": "spot", "position": [3, 9, 2], "target": [-0.3, 0, -0.2], "fov": 55},
      "camera": {"eye": [0, 6, 11], "target": [0, 1, 0], "fov": 45, "width": 160, "height": 120}})";
  return splitOfScene(parseScene(json, "causes.json", ".").scene, res, mode);
}

const std::string kSphere = R"({"type": "sphere", "radius": 1, "detail": 4, "transform": {"translate": [0, 2, 0]}})";
// A one-sided square facing the light: back capture records nothing on it (no back face).
const std::string kOpenSheet = R"({"type": "plane", "name": "sheet", "size": 3, "transform": {"translate": [0, 2, 0]}})";

TEST(ErrorCauses, AClosedOccludersErrorsAtACoarseMapAreOfResolution) {
  const Split s = splitOf(kSphere, 16, CaptureMode::Back);
  ASSERT_GT(s.wrong, 20u);  // 16^2 over the whole ground: the sphere's shadow is a few texels wide
  EXPECT_EQ(s.causes.resolution + s.causes.capture, s.wrong);
  EXPECT_LE(s.causes.capture * 10, s.wrong) << "resolution " << s.causes.resolution;
}

TEST(ErrorCauses, AnOpenSheetUnderBackCaptureIsACaptureError) {
  const Split back = splitOf(kOpenSheet, 64, CaptureMode::Back);
  ASSERT_GT(back.exactShadowed, 200u);
  ASSERT_GE(back.wrong, back.exactShadowed * 9 / 10);  // the sheet casts no shadow at all
  EXPECT_EQ(back.causes.resolution + back.causes.capture, back.wrong);
  EXPECT_GE(back.causes.capture * 20, back.wrong * 19) << "resolution " << back.causes.resolution;
  // Front capture records the sheet: what is left lies along its outline, a matter of resolution.
  const Split front = splitOf(kOpenSheet, 64, CaptureMode::Front);
  EXPECT_LT(front.wrong * 5, back.wrong);
  EXPECT_EQ(front.causes.resolution + front.causes.capture, front.wrong);
  EXPECT_LE(front.causes.capture * 10, front.wrong) << "resolution " << front.causes.resolution;
}

// A directional light's given window inside a plate's shadow (a twentieth probe's scene).
Scene windowInsidePlateShadow() {
  return parseScene(R"({"objects": [{"type": "plane", "name": "ground", "size": 8},
      {"type": "box", "name": "plate", "size": [2, 0.1, 2], "transform": {"translate": [0, 1.5, 0]}}],
      "camera": {"eye": [0.3, 1.0, 0.4], "target": [0.3, 0, 0.4], "up": [0, 0, -1], "fov": 90, "width": 160, "height": 120},
      "light": {"type": "directional", "direction": [0, -1, 0], "position": [0, 5, 0], "extent": 0.8}})",
                    "window.json", ".")
      .scene;
}

TEST(ErrorCauses, AShadowCutByTheLightWindowIsABorderErrorOfVolumesOnly) {
  // A directional light's given window lies inside a plate's shadow (a twentieth probe's scene):
  // the volume's outermost texel ring lies on the far plane, so a band along the window's edge is
  // lit in the middle of the umbra. Refinement would not move it: it is the border's, not the
  // resolution's, for a volume; a shadow map's errors there (none expected) would be resolution.
  const Scene scene = windowInsidePlateShadow();
  const Split asVolume = splitOfScene(scene, 32, CaptureMode::Back, true);
  ASSERT_GT(asVolume.wrong, 100u);  // the band: about a texel (0.05 units) wide along the window's square
  EXPECT_EQ(asVolume.causes.resolution + asVolume.causes.capture + asVolume.causes.border, asVolume.wrong);
  EXPECT_EQ(asVolume.causes.border, asVolume.wrong)
      << "resolution " << asVolume.causes.resolution << ", capture " << asVolume.causes.capture;
  const Split asMap = splitOfScene(scene, 32, CaptureMode::Back, false);
  EXPECT_EQ(asMap.causes.border, 0u);
  EXPECT_EQ(asMap.causes.resolution, asMap.wrong);
}

// With the volume map's guard band (light.h) the volume keeps the plate's shadow up to the window's
// edge; a volume without one, judged over a guarded map (a renderer whose band went missing), has
// its lit strip counted as border still: the strip is measured in the window's own texels.
TEST(ErrorCauses, AGuardBandKeepsTheWindowsEdgeAndTheStripIsStillCounted) {
  const Scene scene = windowInsidePlateShadow();
  const Split guarded = splitOfScene(scene, 32, CaptureMode::Back, true, kVolumeGuardTexels);
  EXPECT_EQ(guarded.wrong, 0u);
  EXPECT_GT(guarded.exactShadowed, 1000u);
  const Split bandLost = splitOfScene(scene, 32, CaptureMode::Back, true, 0, kVolumeGuardTexels);
  ASSERT_GT(bandLost.wrong, 100u);
  EXPECT_EQ(bandLost.causes.border, bandLost.wrong) << "resolution " << bandLost.causes.resolution;
}

TEST(ErrorCauses, TheBorderBandIsLessThanATexelInsideTheRingsCentres) {
  // Texel centres at integers; the ring's at 0 and W - 1, the band reaches to the next centres.
  EXPECT_TRUE(inVolumeBorderBand({-0.5, 5.0}, 8, 8));
  EXPECT_TRUE(inVolumeBorderBand({0.99, 5.0}, 8, 8));
  EXPECT_FALSE(inVolumeBorderBand({1.0, 5.0}, 8, 8));
  EXPECT_FALSE(inVolumeBorderBand({6.0, 6.0}, 8, 8));
  EXPECT_TRUE(inVolumeBorderBand({6.01, 3.0}, 8, 8));
  EXPECT_TRUE(inVolumeBorderBand({3.0, 6.5}, 8, 8));
  EXPECT_FALSE(inVolumeBorderBand({3.0, 3.0}, 8, 5));
  EXPECT_TRUE(inVolumeBorderBand({3.0, 3.5}, 8, 5));
}

TEST(ErrorCauses, NoErrorsNoRays) {
  // A frame the method gets right everywhere splits nothing (and casts no ray).
  Scene scene = parseScene(R"({"objects": [{"type": "plane", "size": 20}], "light": {"type": "spot", "position": [3, 9, 2],
      "target": [0, 0, 0], "fov": 55}, "camera": {"eye": [0, 6, 11], "target": [0, 1, 0], "fov": 45, "width": 8, "height": 6}})",
                           "empty.json", ".").scene;
  fitLightAndCamera(scene);
  const DepthMap map = captureDepthEmbree(scene, 8, 8, CaptureMode::Back);
  const EmbreeDevice device;
  const EmbreeScene sceneRt(device, {&scene.objects[0].mesh});
  const CameraHits hits = castPrimaryRays(sceneRt, scene.camera);
  const std::vector<PixelClass> exact = exactShadows(sceneRt, scene, hits);
  std::vector<std::uint8_t> shadowed(exact.size());
  for (std::size_t k = 0; k < exact.size(); ++k) shadowed[k] = exact[k] == PixelClass::Shadowed;
  const ErrorCauses c = splitErrorCauses(scene, map, 0.25, hits, exact, shadowed);
  EXPECT_EQ(c.resolution + c.capture, 0u);
  EXPECT_EQ(c.offset, 0.25);
}

}  // namespace
}  // namespace shadowvol
