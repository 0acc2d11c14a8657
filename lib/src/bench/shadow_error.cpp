#include "shadowvol/bench/shadow_error.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shadowvol/check.h"

namespace shadowvol {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Felzenszwalb & Huttenlocher's 1D squared distance transform of f (n samples), lower envelope
// of parabolas. v and z are scratch of size n and n + 1.
void transform1d(const double* f, int n, double* d, int* v, double* z) {
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (f[q] == kInf) continue;
    double s = -kInf;
    while (k >= 0) {
      s = ((f[q] + double(q) * q) - (f[v[k]] + double(v[k]) * v[k])) / (2.0 * (q - v[k]));
      if (s <= z[k]) --k;
      else break;
    }
    ++k;
    v[k] = q;
    z[k] = k == 0 ? -kInf : s;
    z[k + 1] = kInf;
  }
  if (k < 0) {
    std::fill(d, d + n, kInf);
    return;
  }
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (z[j + 1] < q) ++j;
    d[q] = double(q - v[j]) * (q - v[j]) + f[v[j]];
  }
}

}  // namespace

std::vector<double> squaredDistanceTransform(int w, int h, const std::vector<std::uint8_t>& site) {
  SV_CHECK_EQ(site.size(), std::size_t(w) * std::size_t(h));
  std::vector<double> g(site.size());
  for (std::size_t k = 0; k < site.size(); ++k) g[k] = site[k] ? 0.0 : kInf;
  const int n = std::max(w, h);
  std::vector<double> f(n), d(n), z(n + 1);
  std::vector<int> v(n);
  for (int x = 0; x < w; ++x) {  // columns
    for (int y = 0; y < h; ++y) f[y] = g[std::size_t(y) * w + x];
    transform1d(f.data(), h, d.data(), v.data(), z.data());
    for (int y = 0; y < h; ++y) g[std::size_t(y) * w + x] = d[y];
  }
  for (int y = 0; y < h; ++y) {  // rows
    transform1d(&g[std::size_t(y) * w], w, d.data(), v.data(), z.data());
    std::copy(d.begin(), d.begin() + w, g.begin() + std::ptrdiff_t(y) * w);
  }
  return g;
}

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
