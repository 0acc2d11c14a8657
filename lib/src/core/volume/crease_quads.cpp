#include "volume/crease_quads.h"

#include <algorithm>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "volume/quad_codes.h"

namespace shadowvol::volume {
namespace {

constexpr double kFar = std::numeric_limits<double>::infinity();

// How far texel (i, j)'s sample lies behind the chord of its neighbours, the most over the four
// directions (0 when it lies on or in front of every chord, or has no neighbour pair that counts).
double behindChord(const SheetDepths& sheet, int i, int j, bool perspective) {
  const DepthMap& map = sheet.map();
  const SheetDepthRule& rule = sheet.rule();
  const auto sample = [&](int x, int y) {  // +inf where far, on the ring or off the map
    if (x < 0 || y < 0 || x >= map.width || y >= map.height || SheetDepthRule::ring(x, y, map.width, map.height))
      return kFar;
    const double u = rule.fromStored(map.at(x, y));
    return u < rule.farPlane ? u : kFar;
  };
  const double c = sample(i, j);
  if (c == kFar) return 0.0;
  constexpr int kDi[4] = {1, 0, 1, 1}, kDj[4] = {0, 1, 1, -1};
  double most = 0.0;
  for (int d = 0; d < 4; ++d) {
    const double a = sample(i - kDi[d], j - kDj[d]), b = sample(i + kDi[d], j + kDj[d]);
    if (a == kFar || b == kFar) continue;
    const double behind = c - depthAlongEdge(a, b, 0.5, perspective);
    if (behind <= 2.0 * rule.bias) most = std::max(most, behind);  // more: a jump, not a crease
  }
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
  tbb::parallel_for(tbb::blocked_range<int>(0, map.height), [&](const tbb::blocked_range<int>& rows) {
    for (int j = rows.begin(); j != rows.end(); ++j)
      for (int i = 0; i < w; ++i) behind[std::size_t(j) * w + i] = behindChord(sheet, i, j, perspective) > threshold;
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
