// defaultBias from the light and map size must equal defaultBias of a depth map with that
// metadata (the renderer uses the first to avoid allocating a map every frame).
#include <gtest/gtest.h>

#include "shadowvol/volume_builder.h"

namespace shadowvol {
namespace {

TEST(DefaultBias, FromLightEqualsFromDepthMap) {
  for (LightType type : {LightType::Spot, LightType::Directional})
    for (CaptureMode capture : {CaptureMode::Front, CaptureMode::Back, CaptureMode::Midpoint})
      for (auto [w, h] : {std::pair{64, 64}, std::pair{256, 128}, std::pair{1000, 1500}}) {
        Light l;
        l.type = type;
        l.position = {1, 8, -2};
        l.direction = {0.1, -1, 0.2};
        l.fovYDegrees = 50;
        l.halfExtent = 4;
        l.nearPlane = 0.5;
        l.farPlane = 20;
        const double fromLight = defaultBias(l, w, h, capture);
        EXPECT_DOUBLE_EQ(fromLight, defaultBias(makeDepthMap(l, w, h, capture)));
        if (capture == CaptureMode::Front) {
          EXPECT_GT(fromLight, 0.0);
        } else {
          EXPECT_EQ(fromLight, 0.0);
        }
      }
}

}  // namespace
}  // namespace shadowvol
