// How far a texel's sample lies off the chord of its two neighbours, along the x axis, the y axis
// and both diagonals: the bend of the sampled surface there, which the sheet's straight runs
// between texel centres do not follow. Read by the crease quads (front capture's bias,
// crease_quads.h) and the thin quads (back capture, thin_quads.h).
#pragma once

#include <limits>

#include "volume/sheet_depths.h"

namespace shadowvol::volume {

/// Texel (x, y)'s sample as the boundary-edge rule reads it (SheetDepthRule::fromStored: with the
/// bias, without the blur's averaging); +inf where far, on the border ring or off the map.
inline double chordSample(const SheetDepths& sheet, int x, int y) {
  const DepthMap& map = sheet.map();
  const SheetDepthRule& rule = sheet.rule();
  constexpr double kFar = std::numeric_limits<double>::infinity();
  if (x < 0 || y < 0 || x >= map.width || y >= map.height || SheetDepthRule::ring(x, y, map.width, map.height))
    return kFar;
  const double u = rule.fromStored(map.at(x, y));
  return u < rule.farPlane ? u : kFar;
}

/// The four directions (di, dj) of the chords: x, y and both diagonals.
inline constexpr int kChordDi[4] = {1, 0, 1, 1}, kChordDj[4] = {0, 1, 1, -1};

/// Calls f(d, behind) for each direction d whose two neighbours of texel (i, j) are both sampled,
/// behind = how far (i, j)'s sample lies behind their chord (negative: in front), the chord taken
/// as the projection interpolates (depth for a directional light, its inverse for a spot light).
/// Nothing when (i, j) itself is not sampled.
template <class F>
void forEachChord(const SheetDepths& sheet, int i, int j, bool perspective, F f) {
  const double c = chordSample(sheet, i, j);
  if (c == std::numeric_limits<double>::infinity()) return;
  for (int d = 0; d < 4; ++d) {
    const double a = chordSample(sheet, i - kChordDi[d], j - kChordDj[d]),
                 b = chordSample(sheet, i + kChordDi[d], j + kChordDj[d]);
    if (a == std::numeric_limits<double>::infinity() || b == std::numeric_limits<double>::infinity()) continue;
    f(d, c - depthAlongEdge(a, b, 0.5, perspective));
  }
}

}  // namespace shadowvol::volume
