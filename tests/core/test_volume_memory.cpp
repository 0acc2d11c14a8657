// volumeBuildBytes (depth_map.h): the memory a volume may need, from the map's islands of hit texels
// and their borders, beside depthMapBytes' plain per-texel bound.
#include <gtest/gtest.h>

#include <functional>

#include "shadowvol/depth_map.h"
#include "test_util.h"

namespace shadowvol {
namespace {

// An N x N map of the test light with a hit where `hit(i, j)`.
DepthMap mapWhere(int n, const std::function<bool(int, int)>& hit) {
  DepthMap m = makeDepthMap(test::directionalDown(), n, n, CaptureMode::Back);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (hit(i, j)) m.depth[m.index(i, j)] = 3.0f;
  return m;
}

std::uint64_t extra(const DepthMap& m) { return volumeBuildBytes(m) - depthMapBytes(m.width, m.height); }

// Islands are 8-connected (a quad joins diagonal texels); a border texel is a hit beside a texel
// without one (or the map's edge). A fourteenth probe's map of isolated hits needed about nine times
// depthMapBytes' bound: here 16 islands of one texel each, every one a border texel.
TEST(VolumeMemory, IslandsOfHitTexelsAndTheirBordersAreCounted) {
  constexpr std::uint64_t kIsland = 4096, kBorder = 64;
  EXPECT_EQ(extra(mapWhere(8, [](int, int) { return false; })), 0u);
  EXPECT_EQ(extra(mapWhere(8, [](int i, int j) { return i % 2 == 0 && j % 2 == 0; })), 16 * (kIsland + kBorder));
  EXPECT_EQ(extra(mapWhere(8, [](int i, int j) { return (i + j) % 2 == 0; })), kIsland + 32 * kBorder);  // diagonals join
  EXPECT_EQ(extra(mapWhere(8, [](int, int j) { return j % 2 == 0; })), 4 * kIsland + 32 * kBorder);   // stripes
  // A 4 x 4 square in the middle: one island, its 12 outer texels on its border.
  EXPECT_EQ(extra(mapWhere(8, [](int i, int j) { return i >= 2 && i < 6 && j >= 2 && j < 6; })), kIsland + 12 * kBorder);
  // The whole map hit: one island, its edge its border (28 texels).
  EXPECT_EQ(extra(mapWhere(8, [](int, int) { return true; })), kIsland + 28 * kBorder);
  // A U whose base is scanned last (row 5): its arms are two islands until the base joins them.
  EXPECT_EQ(extra(mapWhere(8, [](int i, int j) { return (j == 5 && i >= 1 && i <= 5) || ((i == 1 || i == 5) && j >= 1 && j <= 5); })),
            kIsland + 13 * kBorder);
}

}  // namespace
}  // namespace shadowvol
