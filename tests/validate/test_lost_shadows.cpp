// The accuracy verdict's per-occluder criterion (lost_shadows.h): each object's shadow is judged on
// its own, so a thin occluder's lost shadow is not diluted by a large one elsewhere.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "shadowvol/validate/lost_shadows.h"

namespace shadowvol {
namespace {

TEST(LostShadows, EachOccludersShadowIsJudgedOnItsOwn) {
  // 1000 pixels: object 1 shadows 500 (10 missed), object 2 shadows 40 (30 missed), object 3
  // shadows 20 (all missed, too few to judge); the rest lit or facing away.
  std::vector<PixelClass> exact(1000, PixelClass::Lit);
  std::vector<std::uint8_t> shadowed(1000, 0);
  std::vector<std::uint32_t> occluder(1000, kNoOccluder);
  for (std::size_t k = 0; k < 500; ++k) exact[k] = PixelClass::Shadowed, occluder[k] = 1, shadowed[k] = k >= 10;
  for (std::size_t k = 600; k < 640; ++k) exact[k] = PixelClass::Shadowed, occluder[k] = 2, shadowed[k] = k >= 630;
  for (std::size_t k = 700; k < 720; ++k) exact[k] = PixelClass::Shadowed, occluder[k] = 3;
  for (std::size_t k = 900; k < 950; ++k) exact[k] = PixelClass::FacingAway, occluder[k] = 4;  // not a shadow
  // Receivers: object 1's first 4 missed pixels lie on object 1 itself (self-shadows), the rest of
  // the image on the ground (object 0).
  std::vector<std::uint32_t> receiver(1000, 0);
  for (std::size_t k = 0; k < 4; ++k) receiver[k] = 1;
  receiver[20] = 1;  // shadowed by object 1 and not missed: not counted
  const LostShadows lost = findLostShadows(exact, shadowed, occluder, receiver);
  EXPECT_EQ(lost.occluders, 3u);
  EXPECT_EQ(lost.judged, 2u);
  ASSERT_TRUE(lost.worst);
  EXPECT_EQ(lost.worst->object, 2u);
  EXPECT_EQ(lost.worst->pixels, 40u);
  EXPECT_EQ(lost.worst->missed, 30u);
  EXPECT_EQ(lost.worst->first, 600u);
  EXPECT_EQ(lost.worst->missedSelf, 0u);
  EXPECT_EQ(lost.missedSelf, 4u);
  EXPECT_EQ(lost.missedOnOthers, 10u - 4u + 30u + 20u);  // object 3's unjudged shadow counts here too
  // The whole frame's share (10 + 30 + 20 of 560) would hide it.
  for (std::size_t k = 600; k < 640; ++k) shadowed[k] = 1;
  const LostShadows found = findLostShadows(exact, shadowed, occluder, receiver);
  ASSERT_TRUE(found.worst);
  EXPECT_EQ(found.worst->object, 1u);  // 10 of 500 now the worst share
  EXPECT_EQ(found.worst->missedSelf, 4u);
}

TEST(LostShadows, NoShadowNoVerdict) {
  const std::vector<PixelClass> exact(16, PixelClass::Lit);
  const LostShadows lost = findLostShadows(exact, std::vector<std::uint8_t>(16, 0), std::vector<std::uint32_t>(16, kNoOccluder),
                                          std::vector<std::uint32_t>(16, 0));
  EXPECT_EQ(lost.occluders, 0u);
  EXPECT_EQ(lost.missedSelf + lost.missedOnOthers, 0u);
  EXPECT_FALSE(lost.worst);
}

}  // namespace
}  // namespace shadowvol
