// The accuracy verdict's leak criterion (shadow_leaks.h): missed pixels deep inside the exact shadow,
// further from its outline than the method's texels reach. GL-free: the camera's hits, the exact
// classes and the method's test are made by hand over a ground plane seen straight from above.
#include <vector>

#include <gtest/gtest.h>

#include "shadowvol/validate/shadow_leaks.h"
#include "test_util.h"

namespace shadowvol {
namespace {

constexpr int kW = 60, kH = 40;

// A camera 1 unit above the ground (y = 0) looking straight down, fov 90: an image pixel is
// 2 / 40 = 0.05 units wide; the light straight down (directionalDown: an 8 x 8 window).
struct GroundFrame {
  Scene scene;
  CameraHits hits;
  std::vector<PixelClass> exact;
  std::vector<std::uint8_t> method;

  GroundFrame() {
    scene.light = test::directionalDown(6.0);
    scene.camera.eye = {0, 1, 0};
    scene.camera.target = {0, 0, 0};
    scene.camera.up = {0, 0, -1};
    scene.camera.fovYDegrees = 90.0;
    scene.camera.width = kW;
    scene.camera.height = kH;
    hits.width = kW;
    hits.height = kH;
    const std::size_t n = std::size_t(kW) * kH;
    hits.depth.assign(n, 1.0f);
    hits.normal.assign(n, glm::vec3(0, 1, 0));
    hits.triangle.assign(n, CameraHits::Triangle{0, 0});
    hits.point.resize(n);
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) hits.point[index(x, y)] = {0.05 * (x - kW / 2 + 0.5), 0.0, 0.05 * (y - kH / 2 + 0.5)};
    exact.assign(n, PixelClass::Lit);
    method.assign(n, 0);
    // An exact shadow of 30 x 30 pixels (1.5 units), which the method draws.
    for (int y = 5; y < 35; ++y)
      for (int x = 15; x < 45; ++x) {
        exact[index(x, y)] = PixelClass::Shadowed;
        method[index(x, y)] = 1;
      }
  }
  static std::size_t index(int x, int y) { return std::size_t(y) * kW + std::size_t(x); }
  void miss(int x0, int y0, int x1, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) method[index(x, y)] = 0;
  }
  ShadowLeaks leaks(const LeakTexels& texels = {}) const {
    return findShadowLeaks(scene, texels, hits, exact, method);
  }
};

TEST(ShadowLeaks, AHoleInsideTheShadowIsDeepItsOutlineIsNot) {
  GroundFrame f;
  // Along the outline, 2 pixels wide: within an exact method's allowance (kLeakPixels), not deep.
  f.miss(15, 5, 17, 35);
  EXPECT_EQ(f.leaks().deep, 0u);
  // A 6 x 6 hole in the middle, 12 pixels from the outline: deep for an exact method (its allowance
  // is kLeakPixels), all 36 of it.
  f.miss(27, 17, 33, 23);
  const ShadowLeaks exactMethod = f.leaks();
  EXPECT_EQ(exactMethod.deep, 36u);
  ASSERT_FALSE(exactMethod.firstDeep.empty());
  EXPECT_EQ(exactMethod.firstDeep.front(), GroundFrame::index(27, 17));
  // A 16 x 16 map over the 8 x 8 window: texels of 0.5 units, 10 pixels; 3 texels reach further
  // than the hole's 12 pixels from the outline.
  const DepthMap coarse = makeDepthMap(f.scene.light, 16, 16, CaptureMode::Back);
  EXPECT_EQ(f.leaks({&coarse, 0}).deep, 0u);
  // A 512 x 512 map: texels of 1/64 unit, a third of a pixel: the hole is deep again.
  const DepthMap fine = makeDepthMap(f.scene.light, 512, 512, CaptureMode::Back);
  EXPECT_EQ(f.leaks({&fine, 0}).deep, 36u);
}

// The allowance grows where the method's texels stretch along the surface (a receiver tilted from
// the light), with its depth offset, and with a point light's cube faces' texels (2 d / N).
TEST(ShadowLeaks, TheAllowanceFollowsTheTiltTheOffsetAndTheCubeFaces) {
  GroundFrame f;
  f.miss(27, 17, 33, 23);  // 12.5 to 15 pixels (0.63 to 0.75 units) inside the outline
  const DepthMap fine = makeDepthMap(f.scene.light, 512, 512, CaptureMode::Back);  // texels of 1/64 unit
  ASSERT_EQ(f.leaks({&fine}).deep, 36u);
  // A depth offset of 0.04 along the light's axis on a receiver facing it (sin a floored at 0.05):
  // 0.8 units more along the surface.
  EXPECT_EQ(f.leaks({&fine, 0, 0.04}).deep, 0u);
  // The same as a slope bias needs tan a: none on a receiver facing the light.
  EXPECT_EQ(f.leaks({&fine, 0, 0.0, 100.0}).deep, 36u);
  // Normals tilted until N . L = 0.05 (the floor): 3 texels reach 0.94 units along the surface.
  GroundFrame tilted;
  tilted.miss(27, 17, 33, 23);
  for (auto& n : tilted.hits.normal) n = glm::vec3(std::sqrt(1.0 - 0.05 * 0.05), 0.05, 0.0);
  EXPECT_EQ(tilted.leaks({&fine}).deep, 0u);
  // A point light 5 above the ground: its cube faces' texels are 10 / N wide there, 3 of them 0.47
  // units at N = 64 (the hole stays deep), 0.94 at N = 32 (it does not).
  f.scene.light.type = LightType::Point;
  EXPECT_EQ(f.leaks({nullptr, 64}).deep, 36u);
  EXPECT_EQ(f.leaks({nullptr, 32}).deep, 0u);
}

// Pixels that are not exactly shadowed, the image's border and jumps in the camera's view all count
// as the outline: a shadow whose edge the camera cannot see is not judged deep next to them.
TEST(ShadowLeaks, OutlinesTheCameraCannotSeeAreAssumedNearby) {
  GroundFrame f;
  for (std::size_t k = 0; k < f.exact.size(); ++k) {  // the whole view shadowed and missed
    f.exact[k] = PixelClass::Shadowed;
    f.method[k] = 0;
  }
  // Deep: more than kLeakPixels (2) from an outline pixel's edge, so 3 pixels or more from the
  // border: columns 3 to 56, rows 3 to 36.
  EXPECT_EQ(f.leaks().deep, std::size_t(54 * 34));
  // Outside the light (a frustum border: the map's outer ring) is an outline: column 30 takes
  // columns 28 to 32 out.
  for (int y = 0; y < kH; ++y) f.exact[GroundFrame::index(30, y)] = PixelClass::OutsideLight;
  EXPECT_EQ(f.leaks().deep, std::size_t(49 * 34));
  // Another object in column 20, a jump in depth in column 40: each makes its column and the two
  // beside it outline, and takes 7 columns out.
  for (int y = 0; y < kH; ++y) f.hits.triangle[GroundFrame::index(20, y)].geomID = 1;
  for (int y = 0; y < kH; ++y) f.hits.depth[GroundFrame::index(40, y)] = 1.5f;
  EXPECT_EQ(f.leaks().deep, std::size_t(35 * 34));
}

}  // namespace
}  // namespace shadowvol
