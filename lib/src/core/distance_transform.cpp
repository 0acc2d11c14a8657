#include "shadowvol/distance_transform.h"

#include <algorithm>
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

}  // namespace shadowvol
