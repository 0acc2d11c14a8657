// The chord offsets (volume/chord_offsets.h) read row by row, as the thin, crease and hidden quads'
// passes over the whole map read them, against the rule per texel: the same samples and the same
// calls with the same values, bit for bit, on maps with far texels, steps and every texel's
// neighbours, under a directional and a spot light.
#include <cstdint>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "shadowvol/sheet_depth.h"
#include "test_util.h"
#include "volume/chord_offsets.h"
#include "volume/sheet_depths.h"

namespace shadowvol {
namespace {

// A map of random depths within the light's range, about one texel in six far (no hit), some
// beyond the far snap; odd sizes so that no row or column pattern lines up.
DepthMap randomMap(const Light& light, int width, int height, std::uint32_t seed) {
  DepthMap map = makeDepthMap(light, width, height, CaptureMode::Back);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> depth(map.nearPlane, map.farPlane);
  std::uniform_int_distribution<int> kind(0, 11);
  for (float& d : map.depth) {
    const int k = kind(rng);
    d = k < 2 ? std::numeric_limits<float>::infinity() : k == 2 ? float(map.farPlane) : float(depth(rng));
  }
  return map;
}

using Calls = std::vector<std::pair<int, double>>;

TEST(ChordOffsets, RowsGiveTheSameSamplesAndChordsAsThePerTexelRule) {
  for (const Light& light : {test::directionalDown(6.0), test::refinementSpot()}) {
    const DepthMap map = randomMap(light, 37, 29, 7u);
    const SheetDepthRule rule(map, 0.01, 0.0);
    const volume::SheetDepths sheet(map, rule);
    const bool perspective = map.lightProjection[2][3] != 0.0;
    const int w = map.width, h = map.height;
    std::vector<std::vector<double>> rows(std::size_t(h) + 2, std::vector<double>(std::size_t(w)));
    for (int j = -1; j <= h; ++j) {  // rows off the map too: all far
      volume::chordSampleRow(sheet, j, rows[std::size_t(j + 1)].data());
      for (int i = 0; i < w; ++i)
        ASSERT_EQ(rows[std::size_t(j + 1)][std::size_t(i)], volume::chordSample(sheet, i, j)) << i << " " << j;
    }
    std::size_t chords = 0;
    for (int j = 0; j < h; ++j)
      for (int i = 1; i < w - 1; ++i) {
        Calls perTexel, fromRows;
        volume::forEachChord(sheet, i, j, perspective, [&](int d, double b) { perTexel.push_back({d, b}); });
        volume::forEachChordInRows(rows[std::size_t(j)].data(), rows[std::size_t(j + 1)].data(),
                                   rows[std::size_t(j + 2)].data(), i, perspective, [&](int d, double b) {
                                     fromRows.push_back({d, b});
                                   });
        ASSERT_EQ(fromRows, perTexel) << i << " " << j;
        chords += perTexel.size();
      }
    EXPECT_GT(chords, std::size_t(w * h));  // most sampled texels have several chords
  }
}

}  // namespace
}  // namespace shadowvol
