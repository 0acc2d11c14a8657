// The depth blur (depth_blur.h): the 9-sample rule, invalid texels, clamp-to-edge.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "shadowvol/depth_blur.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol {
namespace {

DepthMap orthoMap(int w, int h, double farPlane = 20.0) {
  Light light;
  light.type = LightType::Directional;
  light.position = {0, 10, 0};
  light.direction = {0, -1, 0};
  light.halfExtent = 4.0;
  light.nearPlane = 1.0;
  light.farPlane = farPlane;
  return makeDepthMap(light, w, h, CaptureMode::Back);
}

TEST(Blur, ConstantAndLinearMapsAreUnchanged) {
  DepthMap m = orthoMap(12, 10);
  for (int j = 0; j < m.height; ++j)
    for (int i = 0; i < m.width; ++i) m.depth[m.index(i, j)] = 7.0f;
  for (int j = 0; j < m.height; ++j)
    for (int i = 0; i < m.width; ++i) EXPECT_DOUBLE_EQ(blurredDepth(m, i, j), 7.0) << i << "," << j;  // clamp-to-edge
  for (int j = 0; j < m.height; ++j)
    for (int i = 0; i < m.width; ++i) m.depth[m.index(i, j)] = float(3.0 + 0.25 * i + 0.5 * j);
  for (int j = 2; j < m.height - 2; ++j)  // symmetric samples: a linear ramp is reproduced
    for (int i = 2; i < m.width - 2; ++i) EXPECT_NEAR(blurredDepth(m, i, j), 3.0 + 0.25 * i + 0.5 * j, 1e-12);
}

TEST(Blur, StepBetweenTwoValidSurfaces) {
  // Left columns (i < 8) at 2, right columns at 10: by hand, texel 6 -> (2 + 2 + 6) / 3,
  // texel 7 -> (2 + 2 + 10) / 3, texel 8 -> (2 + 10 + 10) / 3.
  DepthMap m = orthoMap(16, 8);
  for (int j = 0; j < m.height; ++j)
    for (int i = 0; i < m.width; ++i) m.depth[m.index(i, j)] = i < 8 ? 2.0f : 10.0f;
  EXPECT_NEAR(blurredDepth(m, 6, 4), 10.0 / 3.0, 1e-12);
  EXPECT_NEAR(blurredDepth(m, 7, 4), 14.0 / 3.0, 1e-12);
  EXPECT_NEAR(blurredDepth(m, 8, 4), 22.0 / 3.0, 1e-12);
  EXPECT_NEAR(blurredDepth(m, 4, 4), 2.0, 1e-12);
}

TEST(Blur, InvalidTexelsNeverDragTowardsTheFarPlane) {
  DepthMap m = orthoMap(16, 16);
  for (int j = 5; j < 9; ++j)
    for (int i = 5; i < 9; ++i) m.depth[m.index(i, j)] = 3.0f;
  m.depth[m.index(12, 12)] = 25.0f;  // beyond the far plane: invalid like kNoHit
  m.depth[m.index(12, 11)] = 20.0f;  // exactly at the far plane: invalid
  const auto blurred = blurDepths(m);
  for (int j = 0; j < m.height; ++j)
    for (int i = 0; i < m.width; ++i) {
      const float d = m.at(i, j);
      if (d == 3.0f) EXPECT_DOUBLE_EQ(blurred[m.index(i, j)], 3.0) << i << "," << j;
      else EXPECT_EQ(blurred[m.index(i, j)], double(d)) << i << "," << j;  // invalid texels stay as they are
    }
}

TEST(Blur, PartlyValidSamplesAreRenormalisedAndEmptySamplesSkipped) {
  DepthMap m = orthoMap(12, 12);
  m.depth[m.index(5, 5)] = 3.0f;
  EXPECT_DOUBLE_EQ(blurredDepth(m, 5, 5), 3.0);  // every other sample has no valid texel
  m.depth[m.index(6, 5)] = 5.0f;
  // Sample (+1.5, 0) sees texels 6 (valid, weight 1/2) and 7 (invalid): renormalised to 5.
  // All other samples but the centre are empty: mean (3 + 5) / 2.
  EXPECT_DOUBLE_EQ(blurredDepth(m, 5, 5), 4.0);
  // Texel 6: centre 5; sample (-1.5, 0) sees texels 4 (invalid) and 5 (valid): 3.
  EXPECT_DOUBLE_EQ(blurredDepth(m, 6, 5), 4.0);
}

TEST(Blur, BuildVolumeBlurKeepsHitsAndAddsOffset) {
  DepthMap m = orthoMap(16, 16);
  for (int j = 4; j < 11; ++j)
    for (int i = 3; i < 12; ++i) m.depth[m.index(i, j)] = 4.0f;
  VolumeBuildOptions o;
  o.blur = true;
  o.blurOffset = 0.25;
  o.bias = 0.0;
  const auto r = buildVolume(m, o);
  VolumeBuildOptions plain = o;
  plain.blur = false;
  plain.blurOffset = 0.0;
  const auto p = buildVolume(m, plain);
  // Same texels used (blur creates or removes no hit), every hit vertex moved by the offset only
  // (the occluder is flat and its no-hit surroundings are ignored).
  ASSERT_EQ(r.mesh.vertexCount(), p.mesh.vertexCount());
  std::size_t hits = 0;
  for (std::size_t v = 0; v < r.mesh.vertexCount(); ++v) {
    const double dr = m.viewDepthOf(r.mesh.positions[v]), dp = m.viewDepthOf(p.mesh.positions[v]);
    if (std::abs(dp - m.farPlane) < 1e-9) {
      EXPECT_NEAR(dr, m.farPlane, 1e-9);
    } else {
      EXPECT_NEAR(dr, dp + 0.25, 1e-9);
      ++hits;
    }
  }
  EXPECT_EQ(hits, 7u * 9u);
}

// blurDepths (the row kernel the builder uses: a vectorised interior, blurredDepth at the edges)
// equals blurredDepth bit for bit, on random maps with no-hit, far-plane and near-far texels, from
// maps too small for an interior up to rows of 70.
TEST(Blur, RowKernelEqualsBlurredDepthBitForBit) {
  std::uint64_t seed = 11;
  auto next = [&] {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return seed >> 33;
  };
  for (const auto& [w, h] : {std::pair{3, 3}, std::pair{4, 7}, std::pair{5, 5}, std::pair{9, 6}, std::pair{70, 23}}) {
    DepthMap m = orthoMap(w, h);
    const double farSnap = m.farPlane * (1.0 - kFarSnap);
    for (auto& d : m.depth) {
      const int kind = int(next() % 10);
      d = kind == 0   ? DepthMap::kNoHit
          : kind == 1 ? float(m.farPlane)
          : kind == 2 ? std::nextafter(float(farSnap), 0.0f)
                      : float(1.0 + (next() % 100000) * 1e-4);
    }
    const std::vector<double> rows = blurDepths(m);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const double d = m.at(i, j);
        const double expected = isFarDepth(d, m.farPlane) ? d : blurredDepth(m, i, j);
        EXPECT_EQ(rows[m.index(i, j)], expected) << w << "x" << h << " texel " << i << "," << j;
      }
    // Parts of rows (the builder blurs only between a row's first and last valid texel).
    BlurRowScratch scratch;
    std::vector<double> part(std::size_t(w), -1.0);
    for (int j = 0; j < h; ++j)
      for (int b = 0; b < w; b += 3) {
        const int e = std::min(w, b + 1 + int(next() % std::uint64_t(w)));
        std::fill(part.begin(), part.end(), -1.0);
        blurRow(m, j, part.data(), scratch, b, e);
        for (int i = 0; i < w; ++i)
          EXPECT_EQ(part[std::size_t(i)], i >= b && i < e ? rows[m.index(i, j)] : -1.0)
              << w << "x" << h << " texel " << i << "," << j << " part " << b << ".." << e;
      }
  }
}

}  // namespace
}  // namespace shadowvol
