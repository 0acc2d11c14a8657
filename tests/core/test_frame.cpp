// The backend-neutral frame types (frame.h): a frame's pass times with each name once; the
// explicit volume's depth source chosen by ExplicitDepth::Auto.
#include <cmath>

#include <gtest/gtest.h>

#include "shadowvol/frame.h"

namespace shadowvol {
namespace {

// A point light's refined GPU cube volume runs light, crossings and volume once per face: each
// name once, in the order the names first ran, with the sum of its times.
TEST(Frame, PassTotalsSumARepeatedPassInFirstRunOrder) {
  const std::vector<PassTime> passes = {{"camera", 5.0}, {"volume", 0.5}, {"light", 1.0}, {"crossings", 2.0},
                                        {"volume", 3.0}, {"light", 1.5}, {"crossings", 2.5}, {"volume", 3.5},
                                        {"lighting", 0.25}};
  const std::vector<PassTime> t = passTotals(passes);
  ASSERT_EQ(t.size(), 5u);
  const char* names[] = {"camera", "volume", "light", "crossings", "lighting"};
  const double ms[] = {5.0, 7.0, 2.5, 4.5, 0.25};
  for (std::size_t k = 0; k < t.size(); ++k) {
    EXPECT_EQ(t[k].name, names[k]);
    EXPECT_DOUBLE_EQ(t[k].ms, ms[k]) << names[k];
  }
  EXPECT_TRUE(passTotals({}).empty());
}

// ExplicitDepth::Auto's rule (chooseExplicitDepth): rays only where the frame can cast them (the
// refined explicit volume's oracle given, not the walk), on a software rasteriser, and with at
// least kRayDepthTrianglesPerTexel triangles per texel; given sources are kept.
TEST(Frame, ExplicitDepthAutoTakesRaysOnlyWhereTheyAreExpectedCheaper) {
  RenderOptions o;
  o.method = ShadowMethod::Hybrid;
  o.volume = VolumeSource::Explicit;
  o.depthWidth = o.depthHeight = 128;
  o.volumeOptions.refineSteps = 6;
  o.volumeOptions.depthOracle = [](const DepthMap&, std::span<const glm::dvec2>, std::span<float> d) {
    for (float& x : d) x = DepthMap::kNoHit;
  };
  o.explicitDepth = ExplicitDepth::Auto;
  const std::size_t texels = 128 * 128;
  const auto atLeast = std::size_t(std::ceil(kRayDepthTrianglesPerTexel * double(texels)));
  EXPECT_EQ(chooseExplicitDepth(o, atLeast, true), ExplicitDepth::Rays);
  EXPECT_EQ(chooseExplicitDepth(o, atLeast - 1, true), ExplicitDepth::LightPass);
  EXPECT_EQ(chooseExplicitDepth(o, atLeast, false), ExplicitDepth::LightPass);  // a hardware GPU
  EXPECT_EQ(chooseExplicitDepth(o, atLeast, true, 6), ExplicitDepth::LightPass);  // six faces' texels
  EXPECT_EQ(chooseExplicitDepth(o, 6 * atLeast, true, 6), ExplicitDepth::Rays);

  RenderOptions walk = o;
  walk.refineCrossings = RefineCrossings::GpuWalk;  // follows the light pass's triangle record
  EXPECT_EQ(chooseExplicitDepth(walk, atLeast, true), ExplicitDepth::LightPass);
  RenderOptions noOracle = o;
  noOracle.volumeOptions.depthOracle = nullptr;  // unrefined: no rays at hand
  EXPECT_EQ(chooseExplicitDepth(noOracle, atLeast, true), ExplicitDepth::LightPass);
  RenderOptions gpuVolume = o;
  gpuVolume.volume = VolumeSource::Gpu;
  EXPECT_EQ(chooseExplicitDepth(gpuVolume, atLeast, true), ExplicitDepth::LightPass);
  RenderOptions shadowMap = o;
  shadowMap.method = ShadowMethod::ShadowMap;
  EXPECT_EQ(chooseExplicitDepth(shadowMap, atLeast, true), ExplicitDepth::LightPass);

  for (ExplicitDepth given : {ExplicitDepth::LightPass, ExplicitDepth::Rays}) {
    RenderOptions g = o;
    g.explicitDepth = given;
    EXPECT_EQ(chooseExplicitDepth(g, 0, false), given);
    EXPECT_EQ(chooseExplicitDepth(g, 10 * texels, true), given);
  }
  ExplicitDepth parsed{};
  ASSERT_TRUE(parseExplicitDepth("auto", parsed));
  EXPECT_EQ(parsed, ExplicitDepth::Auto);
  EXPECT_STREQ(toString(ExplicitDepth::Auto), "auto");
  EXPECT_FALSE(parseExplicitDepth("light", parsed));
}

}  // namespace
}  // namespace shadowvol
