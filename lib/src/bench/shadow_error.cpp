#include "shadowvol/bench/shadow_error.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shadowvol/check.h"

namespace shadowvol {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

ShadowErrorMetrics measureShadowError(int w, int h, const std::vector<PixelClass>& exact,
                                      const std::vector<std::uint8_t>& testShadowed, double band) {
  const std::size_t n = std::size_t(w) * std::size_t(h);
  SV_CHECK_EQ(exact.size(), n);
  SV_CHECK_EQ(testShadowed.size(), n);
  std::vector<std::uint8_t> lit(n, 0), shadowed(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    lit[k] = exact[k] == PixelClass::Lit;
    shadowed[k] = exact[k] == PixelClass::Shadowed;
  }
  const std::vector<double> toLit = squaredDistanceTransform(w, h, lit);
  const std::vector<double> toShadowed = squaredDistanceTransform(w, h, shadowed);
  ShadowErrorMetrics m;
  std::vector<double> distances;
  for (std::size_t k = 0; k < n; ++k) {
    if (!lit[k] && !shadowed[k]) continue;
    ++m.pixels;
    const double d2 = shadowed[k] ? toLit[k] : toShadowed[k];
    const double dist = d2 == kInf ? kInf : std::sqrt(d2) - 0.5;
    const bool inBand = dist <= band;
    const bool isLeak = shadowed[k] && !testShadowed[k];
    const bool isAcne = lit[k] && testShadowed[k];
    m.leak += isLeak;
    m.acne += isAcne;
    if (inBand) {
      ++m.bandPixels;
      m.bandLeak += isLeak;
      m.bandAcne += isAcne;
    }
    if ((isLeak || isAcne) && dist != kInf) distances.push_back(dist);
  }
  if (!distances.empty()) {
    std::sort(distances.begin(), distances.end());
    double sum = 0.0;
    for (double d : distances) sum += d;
    m.distMean = sum / double(distances.size());
    const std::size_t rank = std::size_t(std::ceil(0.99 * double(distances.size())));
    m.distP99 = distances[std::max<std::size_t>(rank, 1) - 1];
    m.distMax = distances.back();
  }
  return m;
}

}  // namespace shadowvol
