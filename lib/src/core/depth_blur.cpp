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

std::vector<double> blurDepths(const DepthMap& map) {
  SV_CHECK_EQ(map.depth.size(), std::size_t(map.width) * std::size_t(map.height));
  std::vector<double> out(map.depth.size());
  tbb::parallel_for(tbb::blocked_range<int>(0, map.height), [&](const tbb::blocked_range<int>& rows) {
    for (int j = rows.begin(); j != rows.end(); ++j)
      for (int i = 0; i < map.width; ++i) {
        const double d = map.at(i, j);
        out[map.index(i, j)] = isFarDepth(d, map.farPlane) ? d : blurredDepth(map, i, j);
      }
  });
  return out;
}

}  // namespace shadowvol
