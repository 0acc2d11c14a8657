// The backend-neutral frame types (frame.h): a frame's pass times with each name once.
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

}  // namespace
}  // namespace shadowvol
