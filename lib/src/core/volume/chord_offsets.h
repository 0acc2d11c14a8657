// How far a texel's sample lies off the chord of its two neighbours, along the x axis, the y axis
// and both diagonals: the bend of the sampled surface there, which the sheet's straight runs
// between texel centres do not follow. Read by the crease quads (front capture's bias,
// crease_quads.h) and the thin quads (back capture, thin_quads.h); the rows of samples
// (chordSampleRow) also by the hidden-surface search's limits (hidden_quads.h).
#pragma once

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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

/// chordSample of every texel of row j into out[0, width): +inf on the ring, off the map and where
/// far. A pass over the whole map reads each stored depth once this way (forEachChordInRows),
/// where chordSample per texel and neighbour reads it nine times.
inline void chordSampleRow(const SheetDepths& sheet, int j, double* out) {
  const DepthMap& map = sheet.map();
  const SheetDepthRule& rule = sheet.rule();
  constexpr double kFar = std::numeric_limits<double>::infinity();
  const int w = map.width;
  if (j <= 0 || j >= map.height - 1) {
    std::fill(out, out + w, kFar);
    return;
  }
  const float* src = map.depth.data() + map.index(0, j);
  out[0] = out[w - 1] = kFar;
  for (int i = 1; i < w - 1; ++i) {
    const double u = rule.fromStored(src[i]);
    out[i] = u < rule.farPlane ? u : kFar;
  }
}

/// The four directions (di, dj) of the chords: x, y and both diagonals.
inline constexpr int kChordDi[4] = {1, 0, 1, 1}, kChordDj[4] = {0, 1, 1, -1};

/// The rule of forEachChord for a sample c (finite) and its neighbours a[d] = (i - di, j - dj) and
/// b[d] = (i + di, j + dj) in each direction d.
template <class F>
void forEachChordOf(double c, const double (&a)[4], const double (&b)[4], bool perspective, F f) {
  for (int d = 0; d < 4; ++d) {
    if (a[d] == std::numeric_limits<double>::infinity() || b[d] == std::numeric_limits<double>::infinity()) continue;
    f(d, c - depthAlongEdge(a[d], b[d], 0.5, perspective));
  }
}

/// Calls f(d, behind) for each direction d whose two neighbours of texel (i, j) are both sampled,
/// behind = how far (i, j)'s sample lies behind their chord (negative: in front), the chord taken
/// as the projection interpolates (depth for a directional light, its inverse for a spot light).
/// Nothing when (i, j) itself is not sampled.
template <class F>
void forEachChord(const SheetDepths& sheet, int i, int j, bool perspective, F f) {
  const double c = chordSample(sheet, i, j);
  if (c == std::numeric_limits<double>::infinity()) return;
  double a[4], b[4];
  for (int d = 0; d < 4; ++d) {
    a[d] = chordSample(sheet, i - kChordDi[d], j - kChordDj[d]);
    b[d] = chordSample(sheet, i + kChordDi[d], j + kChordDj[d]);
  }
  forEachChordOf(c, a, b, perspective, f);
}

/// forEachChord for texel (i, j) from chordSampleRow's rows j - 1 (`up`), j (`row`) and j + 1
/// (`down`): the same calls, the same values.
template <class F>
void forEachChordInRows(const double* up, const double* row, const double* down, int i, bool perspective, F f) {
  const double c = row[i];
  if (c == std::numeric_limits<double>::infinity()) return;  // also the ring: i - 1 and i + 1 exist below
  const double a[4] = {row[i - 1], up[i], up[i - 1], down[i - 1]};
  const double b[4] = {row[i + 1], down[i], down[i + 1], up[i + 1]};
  forEachChordOf(c, a, b, perspective, f);
}

/// Calls visit(j, up, row, down) for every row j in [1, height - 1) (the ring's rows hold no sample)
/// with chordSampleRow's rows j - 1, j and j + 1 (width values each), in parallel blocks of rows,
/// each block rolling the three rows down the map: how the passes over the whole map (thin and
/// crease quads) read every sample once per row. `visit` must be safe to call concurrently for
/// different rows.
template <class Visit>
void forEachSampledRow(const SheetDepths& sheet, Visit visit) {
  const int w = sheet.map().width, h = sheet.map().height;
  tbb::parallel_for(tbb::blocked_range<int>(1, std::max(1, h - 1)), [&](const tbb::blocked_range<int>& rows) {
    const auto n = static_cast<std::size_t>(w);
    std::vector<double> up(n), row(n), down(n);
    chordSampleRow(sheet, rows.begin() - 1, up.data());
    chordSampleRow(sheet, rows.begin(), row.data());
    for (int j = rows.begin(); j != rows.end(); ++j) {
      chordSampleRow(sheet, j + 1, down.data());
      visit(j, static_cast<const double*>(up.data()), static_cast<const double*>(row.data()),
            static_cast<const double*>(down.data()));
      std::swap(up, row);    // up: row j
      std::swap(row, down);  // row: row j + 1
    }
  });
}

}  // namespace shadowvol::volume
