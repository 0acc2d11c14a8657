// The Embree oracle's search for hidden surfaces (EmbreeDepthOracle::nearerSurfaces) agrees with
// Embree's own capture on real meshes: the triangle a texel's ray records passes through the texel
// centre, so every quad with a captured corner holds a surface no farther than that corner's depth.
// This pins the search's facing rule (back capture) and projection to the capture's.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/primitives.h"
#include "shadowvol/scene.h"
#include "test_util.h"

namespace shadowvol {
namespace {

TEST(NearerSurfacesEmbree, EveryQuadWithACapturedCornerIsFlagged) {
  for (const char* name : {"bunny.json", "lion-head.json", "tree.json"}) {
    Scene scene = loadScene(test::sourceDir() / "data/scenes" / name).scene;
    fitLightAndCamera(scene);
    const EmbreeDepthOracle oracle(scene);
    const NearerSurfaceOracle search = oracle.nearerSurfaces();
    for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint, CaptureMode::Entry}) {
      // Entry capture reads the faces towards the light of closed meshes only: the lion head is open
      // (entry capture records its lit side where its inside lies behind, which the search's rule
      // does not see, as the capture warning says of open meshes).
      if (mode == CaptureMode::Entry && std::string(name) == "lion-head.json") continue;
      const DepthMap map = captureDepthEmbree(scene, 96, 96, mode);
      const int qw = map.width - 1, qh = map.height - 1;
      std::vector<float> limit(std::size_t(qw) * std::size_t(qh), -1.0f);
      std::size_t withHit = 0;
      for (int qj = 0; qj < qh; ++qj)
        for (int qi = 0; qi < qw; ++qi) {
          float farthest = -1.0f;
          for (int c = 0; c < 4; ++c) {
            const float d = map.at(qi + (c & 1), qj + (c >> 1));
            if (!DepthMap::isNoHit(d)) farthest = std::max(farthest, d);
          }
          if (farthest < 0.0f) continue;
          limit[std::size_t(qj) * std::size_t(qw) + std::size_t(qi)] = farthest * (1.0f + 1e-4f);
          ++withHit;
        }
      ASSERT_GT(withHit, 100u) << name;
      std::vector<std::uint8_t> flags(limit.size(), 0);
      search(map, limit, {}, flags);
      std::size_t missing = 0, flagged = 0;
      for (std::size_t q = 0; q < limit.size(); ++q) {
        missing += limit[q] > 0.0f && !flags[q];
        flagged += flags[q];
      }
      EXPECT_EQ(missing, 0u) << name << " " << toString(mode);
      EXPECT_EQ(flagged, withHit) << name << " " << toString(mode);  // the others' limit: -1
    }
  }
}

// The facing rule itself: a single-sided square facing the light is neither captured nor found by
// back capture; turned over, it is both (a closed mesh cannot tell: its front faces are nearer).
TEST(NearerSurfacesEmbree, BackCaptureFindsWhatItCaptures) {
  for (bool turned : {false, true}) {
    TriangleMesh square = makePlane(3.0, 3.0, 2);
    for (glm::vec3& p : square.positions) p.y += 1.0f;
    if (turned)
      for (auto& t : square.triangles) std::swap(t[1], t[2]);
    const Scene scene = test::sceneWith({SceneObject{"square", "mesh", square}});
    const EmbreeDepthOracle oracle(scene);
    const DepthMap map = captureDepthEmbree(scene, 32, 32, CaptureMode::Back);
    EXPECT_EQ(map.hitCount() > 0, turned);
    std::vector<float> limit(31 * 31, float(map.farPlane));
    std::vector<std::uint8_t> flags(limit.size(), 0);
    oracle.nearerSurfaces()(map, limit, {}, flags);
    EXPECT_EQ(std::count(flags.begin(), flags.end(), std::uint8_t(1)) > 0, turned);
  }
}

// Entry capture: the single-sided square facing the light is neither captured nor found (no back
// face behind it); a closed box's top, facing the light, is both, in every quad under the box.
TEST(NearerSurfacesEmbree, EntryCaptureFindsTheLitSideOfClosedMeshes) {
  TriangleMesh square = makePlane(3.0, 3.0, 2);
  for (glm::vec3& p : square.positions) p.y += 1.0f;
  TriangleMesh box = makeBox(0.8, 0.4, 0.8);
  for (glm::vec3& p : box.positions) p += glm::vec3(2.5f, 1.0f, 0.0f);
  for (bool withBox : {false, true}) {
    std::vector<SceneObject> objects{SceneObject{"square", "mesh", square}};
    if (withBox) objects.push_back(SceneObject{"box", "mesh", box});
    const Scene scene = test::sceneWith(std::move(objects));
    const EmbreeDepthOracle oracle(scene);
    const DepthMap map = captureDepthEmbree(scene, 32, 32, CaptureMode::Entry);
    EXPECT_EQ(map.hitCount() > 0, withBox);
    // The limit: just behind each quad's captured corners (none: the far plane).
    std::vector<float> limit(31 * 31, float(map.farPlane));
    std::size_t underBox = 0;
    for (int qj = 0; qj < 31; ++qj)
      for (int qi = 0; qi < 31; ++qi) {
        float d = map.at(qi, qj);
        for (int c = 1; c < 4; ++c) d = std::min(d, map.at(qi + (c & 1), qj + (c >> 1)));
        if (DepthMap::isNoHit(d)) continue;
        limit[std::size_t(qj) * 31 + std::size_t(qi)] = d * (1.0f + 1e-4f);
        ++underBox;
      }
    std::vector<std::uint8_t> flags(limit.size(), 0);
    oracle.nearerSurfaces()(map, limit, {}, flags);
    std::size_t flagged = 0, flaggedUnder = 0;
    for (std::size_t q = 0; q < flags.size(); ++q) {
      flagged += flags[q];
      flaggedUnder += flags[q] && limit[q] < float(map.farPlane);
    }
    EXPECT_EQ(flaggedUnder, underBox) << withBox;
    EXPECT_EQ(flagged > 0, withBox) << withBox;
  }
}

}  // namespace
}  // namespace shadowvol
