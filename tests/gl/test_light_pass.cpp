// Light depth pass + read-back against the Embree reference capture (issue 4, pass 1): at least
// 99.9 % of texels within 1e-4 relative depth (kNoHit must match kNoHit exactly).
#include <gtest/gtest.h>

#include "gl_test_support.h"
#include "shadowvol/embree/depth_capture.h"
#include "test_util.h"

using namespace shadowvol;

namespace {

struct Agreement {
  std::size_t texels = 0, agree = 0, hits = 0;
  double share() const { return double(agree) / double(texels); }
};

Agreement compare(const DepthMap& gpu, const DepthMap& cpu) {
  Agreement a;
  EXPECT_EQ(gpu.width, cpu.width);
  EXPECT_EQ(gpu.height, cpu.height);
  a.texels = cpu.depth.size();
  for (std::size_t k = 0; k < a.texels; ++k) {
    const float g = gpu.depth[k], c = cpu.depth[k];
    if (DepthMap::isNoHit(c) || DepthMap::isNoHit(g)) {
      a.agree += DepthMap::isNoHit(c) && DepthMap::isNoHit(g);
      continue;
    }
    ++a.hits;
    a.agree += std::abs(double(g) - double(c)) <= 1e-4 * std::abs(double(c));
  }
  return a;
}

void expectMatchesEmbree(const Scene& scene, int w, int h, CaptureMode mode) {
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(scene);
  const DepthMap gpu = r.captureDepth(w, h, mode);
  const DepthMap cpu = captureDepthEmbree(scene, w, h, mode);
  EXPECT_EQ(gpu.lightProjection, cpu.lightProjection);
  EXPECT_EQ(gpu.lightView, cpu.lightView);
  const Agreement a = compare(gpu, cpu);
  std::printf("%s %s %dx%d: %zu of %zu texels agree (%.4f %%), %zu hits\n", scene.source.c_str(), toString(mode), w, h,
              a.agree, a.texels, 100.0 * a.share(), a.hits);
  ::testing::Test::RecordProperty(std::string("agreement_") + toString(mode), std::to_string(a.share()));
  EXPECT_GT(a.hits, a.texels / 100) << "the scene must be seen by the light";
  EXPECT_GE(a.share(), 0.999);
}

}  // namespace

TEST(GlLightPass, BackCaptureMatchesEmbree) {
  expectMatchesEmbree(defaultScene(), 96, 96, CaptureMode::Back);
}
TEST(GlLightPass, FrontCaptureMatchesEmbree) {
  expectMatchesEmbree(defaultScene(), 96, 80, CaptureMode::Front);
}
TEST(GlLightPass, MidpointCaptureMatchesEmbree) {
  expectMatchesEmbree(gltest::clutterScene(), 96, 96, CaptureMode::Midpoint);
}
// Two passes (every face, then back faces only) resolved on read-back.
TEST(GlLightPass, EntryCaptureMatchesEmbree) {
  expectMatchesEmbree(defaultScene(), 96, 96, CaptureMode::Entry);
  expectMatchesEmbree(gltest::clutterScene(), 96, 96, CaptureMode::Entry);
}
// The first layer passes over faces lit nearly edge-on as the Embree capture does: a wedge's
// slope lit at half kEntryGrazingCos (its bottom recorded) and at twice it (the slope recorded).
TEST(GlLightPass, EntryCaptureOfFacesLitNearlyEdgeOnMatchesEmbree) {
  for (double share : {0.5, 2.0})
    expectMatchesEmbree(test::grazedWedgeScene(share * kEntryGrazingCos), 32, 32, CaptureMode::Entry);
}
TEST(GlLightPass, DirectionalBackCaptureMatchesEmbree) {
  expectMatchesEmbree(gltest::plateScene(), 64, 64, CaptureMode::Back);
}
TEST(GlLightPass, ClutterFrontCaptureMatchesEmbree) {
  expectMatchesEmbree(gltest::clutterScene(), 128, 128, CaptureMode::Front);
}
