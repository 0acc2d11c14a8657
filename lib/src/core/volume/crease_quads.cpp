#include "volume/crease_quads.h"

#include <algorithm>
#include <limits>

#include "volume/chord_offsets.h"
#include "volume/quad_codes.h"

namespace shadowvol::volume {
namespace {

// Whether the boundary edges have the step from texel (i, j) to its neighbour (i + di, j + dj), di
// and dj in {-1, 0, 1}: along an axis, that grid edge is a boundary edge; along a diagonal, a side of
// the quad the two share is one (the quad is refined, and its sub-grid samples the step).
bool stepOnBoundary(const std::uint8_t* splitBits, int width, int i, int j, int di, int dj) {
  const auto edges = [&](int x, int y) { return splitBits[std::size_t(y) * std::size_t(width) + std::size_t(x)] & 3; };
  const int x = std::min(i, i + di), y = std::min(j, j + dj);
  if (dj == 0) return (edges(x, y) & 1) != 0;
  if (di == 0) return (edges(x, y) & 2) != 0;
  return ((edges(x, y) | (edges(x, y + 1) & 1) | (edges(x + 1, y) & 2)) != 0);
}

// How far texel (i, j)'s sample lies behind the chord of its neighbours, the most over the four
// directions (0 when it lies on or in front of every chord, or has no neighbour pair that counts),
// from chordSampleRow's rows j - 1, j and j + 1.
// More than 2 B behind is a jump, left to the boundary edges where they have it (a step on either
// side of the sample is on a boundary edge); where they do not (the discontinuity rule keeps a
// step continuous next to steep neighbours, as on ground lit at a grazing angle) it counts here.
double behindChord(const double* up, const double* row, const double* down, double bias, const std::uint8_t* splitBits,
                   int width, int i, int j, bool perspective) {
  double most = 0.0;
  forEachChordInRows(up, row, down, i, perspective, [&](int d, double behind) {
    if (behind > 2.0 * bias && (stepOnBoundary(splitBits, width, i, j, -kChordDi[d], -kChordDj[d]) ||
                                stepOnBoundary(splitBits, width, i, j, kChordDi[d], kChordDj[d])))
      return;  // a jump the boundary edges have
    most = std::max(most, behind);
  });
  return most;
}

}  // namespace

std::vector<std::uint32_t> findCreaseQuads(const SheetDepths& sheet, int subdivisions, std::uint8_t* splitBits) {
  const DepthMap& map = sheet.map();
  const double bias = sheet.rule().bias;
  std::vector<std::uint32_t> creases;
  if (!(bias > 0.0)) return creases;
  const int w = map.width, qw = w - 1, qh = map.height - 1;
  const bool perspective = map.lightProjection[2][3] != 0.0;
  const double threshold = kCreaseChordShare * bias / subdivisions;
  std::vector<std::uint8_t> behind(std::size_t(w) * std::size_t(map.height), 0);
  forEachSampledRow(sheet, [&](int j, const double* up, const double* row, const double* down) {
    for (int i = 1; i < w - 1; ++i)
      behind[std::size_t(j) * w + i] = behindChord(up, row, down, bias, splitBits, w, i, j, perspective) > threshold;
  });
  for (int qj = 0; qj < qh; ++qj) {
    std::uint8_t* lower = splitBits + std::size_t(qj) * w;
    const std::uint8_t* upper = lower + w;
    const std::uint8_t* b0 = behind.data() + std::size_t(qj) * w;
    const std::uint8_t* b1 = b0 + w;
    for (int qi = 0; qi < qw; ++qi) {
      if ((lower[qi] & (3 | kHiddenQuadBit)) | (lower[qi + 1] & 2) | (upper[qi] & 1)) continue;
      if (!(b0[qi] | b0[qi + 1] | b1[qi] | b1[qi + 1])) continue;
      lower[qi] |= kHiddenQuadBit;
      creases.push_back(std::uint32_t(qj) * std::uint32_t(qw) + std::uint32_t(qi));
    }
  }
  return creases;
}

}  // namespace shadowvol::volume
