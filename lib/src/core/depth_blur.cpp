#include "shadowvol/depth_blur.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/check.h"

namespace shadowvol {

double blurredDepth(const DepthMap& map, int i, int j) {
  const int w = map.width, h = map.height;
  const double farPlane = map.farPlane;
  SV_CHECK(!isFarDepth(map.at(i, j), farPlane));
  // Offsets -1.5, 0, +1.5 give integer base texels and fractions 0.5, 0, 0.5 along each axis.
  static constexpr int kBase[3] = {-2, 0, 1};
  static constexpr double kFrac[3] = {0.5, 0.0, 0.5};
  double sum = 0.0;
  int samples = 0;
  for (int sy = 0; sy < 3; ++sy) {
    const int y0 = std::clamp(j + kBase[sy], 0, h - 1), y1 = std::clamp(j + kBase[sy] + 1, 0, h - 1);
    const double fy = kFrac[sy];
    for (int sx = 0; sx < 3; ++sx) {
      const int x0 = std::clamp(i + kBase[sx], 0, w - 1), x1 = std::clamp(i + kBase[sx] + 1, 0, w - 1);
      const double fx = kFrac[sx];
      const int xs[4] = {x0, x1, x0, x1};
      const int ys[4] = {y0, y0, y1, y1};
      const double ws[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
      double value = 0.0, weight = 0.0;
      for (int k = 0; k < 4; ++k) {
        if (ws[k] == 0.0) continue;
        const double d = map.at(xs[k], ys[k]);
        if (isFarDepth(d, farPlane)) continue;
        value += ws[k] * d;
        weight += ws[k];
      }
      if (weight > 0.0) {
        sum += value / weight;
        ++samples;
      }
    }
  }
  SV_CHECK_GT(samples, 0);
  return sum / samples;
}

namespace {

// The interior of a row, [b, e) with 2 <= b, e <= w - 2, rows j - 2 .. j + 2 in range: the same
// 9 samples as blurredDepth with the clamps gone and the validity tests made arithmetic, so the
// loop over texels vectorises. v[r] and f[r] hold row j - 2 + r as (valid ? d : 0) and
// (valid ? 1 : 0). A tap adds w * v and w * f: exactly w * d and w for a valid texel, and +0
// otherwise, which leaves the sums as blurredDepth's (its sums start at +0 and only add
// non-negative terms), in the same order; a sample's value / weight is taken only where its
// weight is > 0, as there. Texels whose own depth is invalid get unspecified values.
// One of the 9 samples at texel i: Sx, Sy in {0, 1, 2} for offsets -1.5, 0, +1.5 (blurredDepth's
// kBase -2, 0, 1 and kFrac 0.5, 0, 0.5), its taps in blurredDepth's order, zero weights left out.
template <int Sx, int Sy>
inline void addSample(const double* const* v, const double* const* f, int i, double& sum, double& samples) {
  constexpr int x0 = Sx == 0 ? -2 : Sx == 1 ? 0 : 1, y0 = Sy == 0 ? 0 : Sy == 1 ? 2 : 3;  // y0: row in v
  constexpr double wx = Sx == 1 ? 1.0 : 0.5, wy = Sy == 1 ? 1.0 : 0.5, w = wx * wy;
  double value = 0.0, weight = 0.0;
  value += w * v[y0][i + x0];
  weight += w * f[y0][i + x0];
  if constexpr (Sx != 1) {
    value += w * v[y0][i + x0 + 1];
    weight += w * f[y0][i + x0 + 1];
  }
  if constexpr (Sy != 1) {
    value += w * v[y0 + 1][i + x0];
    weight += w * f[y0 + 1][i + x0];
    if constexpr (Sx != 1) {
      value += w * v[y0 + 1][i + x0 + 1];
      weight += w * f[y0 + 1][i + x0 + 1];
    }
  }
  // Every operation unconditional (a conditional division cannot be vectorised under trapping
  // math); a sample without valid taps divides 0 by 1 and adds +0.
  const double any = weight > 0.0 ? 1.0 : 0.0;
  const double mean = value / (weight + (1.0 - any));
  sum += any * mean;
  samples += any;
}

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("avx2", "default")))  // AVX2 without FMA: the same IEEE operations
#endif
void blurInterior(const double* const* v, const double* const* f, int b, int e, double* __restrict out) {
  for (int i = b; i < e; ++i) {
    double sum = 0.0, samples = 0.0;
    addSample<0, 0>(v, f, i, sum, samples);
    addSample<1, 0>(v, f, i, sum, samples);
    addSample<2, 0>(v, f, i, sum, samples);
    addSample<0, 1>(v, f, i, sum, samples);
    addSample<1, 1>(v, f, i, sum, samples);
    addSample<2, 1>(v, f, i, sum, samples);
    addSample<0, 2>(v, f, i, sum, samples);
    addSample<1, 2>(v, f, i, sum, samples);
    addSample<2, 2>(v, f, i, sum, samples);
    out[i] = sum / samples;
  }
}

}  // namespace

void blurRow(const DepthMap& map, int j, double* out, BlurRowScratch& scratch, int b, int e) {
  const int w = map.width, h = map.height;
  if (e < 0) e = w;
  SV_CHECK(0 <= b && b <= e && e <= w);
  const double farPlane = map.farPlane;
  const float* row = map.depth.data() + std::size_t(j) * w;
  auto exact = [&](int i) { out[i] = isFarDepth(row[i], farPlane) ? double(row[i]) : blurredDepth(map, i, j); };
  // The interior [ib, ie): texels whose 5 x 5 neighbourhood lies inside the map.
  const int ib = std::max(b, 2), ie = std::min(e, w - 2);
  if (j < 2 || j > h - 3 || ib >= ie) {
    for (int i = b; i < e; ++i) exact(i);
    return;
  }
  for (int i = b; i < ib; ++i) exact(i);
  for (int i = ie; i < e; ++i) exact(i);
  // Rows j - 2 .. j + 2 over the columns the interior reads, [ib - 2, ie + 2).
  scratch.values.resize(std::size_t(5) * w);
  scratch.valid.resize(std::size_t(5) * w);
  const double* v[5];
  const double* f[5];
  for (int r = 0; r < 5; ++r) {
    const float* src = map.depth.data() + std::size_t(j - 2 + r) * w;
    double* vr = scratch.values.data() + std::size_t(r) * w;
    double* fr = scratch.valid.data() + std::size_t(r) * w;
    for (int i = ib - 2; i < ie + 2; ++i) {
      const bool ok = !isFarDepth(src[i], farPlane);
      vr[i] = ok ? double(src[i]) : 0.0;
      fr[i] = ok ? 1.0 : 0.0;
    }
    v[r] = vr;
    f[r] = fr;
  }
  blurInterior(v, f, ib, ie, out);
  for (int i = ib; i < ie; ++i)
    if (isFarDepth(row[i], farPlane)) out[i] = row[i];
}

std::vector<double> blurDepths(const DepthMap& map) {
  SV_CHECK_EQ(map.depth.size(), std::size_t(map.width) * std::size_t(map.height));
  std::vector<double> out(map.depth.size());
  tbb::parallel_for(tbb::blocked_range<int>(0, map.height), [&](const tbb::blocked_range<int>& rows) {
    BlurRowScratch scratch;
    for (int j = rows.begin(); j != rows.end(); ++j) blurRow(map, j, out.data() + map.index(0, j), scratch);
  });
  return out;
}

}  // namespace shadowvol
