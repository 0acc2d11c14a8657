#include "volume/sheet_depths.h"

#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <string.h>  // memrchr
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/depth_blur.h"
#include "shadowvol/error.h"

namespace shadowvol::volume {

bool scanDepthRow(const float* __restrict src, std::uint8_t* __restrict below, int n, std::uint32_t limit) {
  std::uint32_t bad = 0;
  for (int i = 0; i < n; ++i) {
    std::uint32_t u;
    std::memcpy(&u, src + i, sizeof u);
    bad |= std::uint32_t(u > 0x7F800000u) & std::uint32_t(u != 0x80000000u);  // NaN or < -0
    below[i] = (u & 0x7FFFFFFFu) < limit;
  }
  return bad != 0;
}

std::uint32_t floatBitsAtOrAbove(double x) {
  float f = float(x);
  if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// 64-bit integer compares need more than SSE2: an AVX2 clone is chosen at load time where the CPU
// has it (AVX2 without FMA, so the same results on every machine).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("avx2", "default")))
#endif
void farFlags(const double* __restrict d, std::uint8_t* __restrict far, int n, double farPlane) {
  std::uint64_t farBits;
  std::memcpy(&farBits, &farPlane, sizeof farBits);
  for (int i = 0; i < n; ++i) {
    std::uint64_t u;
    std::memcpy(&u, d + i, sizeof u);
    far[i] = u == farBits;
  }
}

std::pair<int, int> nearSpan(const std::uint8_t* far, int n) {
  const void* first = std::memchr(far, 0, std::size_t(n));
  if (!first) return {n, -1};
#if defined(__GLIBC__)
  const void* last = memrchr(far, 0, std::size_t(n));
#else
  const std::uint8_t* last = far + n - 1;
  while (*last) --last;
#endif
  return {int(static_cast<const std::uint8_t*>(first) - far), int(static_cast<const std::uint8_t*>(last) - far)};
}

bool sheetDepthSpan(const float* __restrict src, double* __restrict d, int b, int e, SheetDepthRule rule) {
  bool bad = false;
  for (int i = b; i < e; ++i) {
    const double raw = src[i];
    bad |= !(raw >= 0.0);
    d[i] = rule.fromStored(raw);
  }
  return bad;
}

void validateDepths(const DepthMap& map) {
  for (int j = 0; j < map.height; ++j)
    for (int i = 0; i < map.width; ++i) {
      const float d = map.at(i, j);
      if (std::isnan(d) || d < 0.0f) {
        std::ostringstream field, value;
        field << "depth of texel (" << i << ", " << j << ")";
        value << d;
        throw InputError("depth map", field.str(), value.str(),
                         "depths must be non-negative light-view distances (world units) or +inf for no hit");
      }
    }
}

void SheetDepths::materialiseBlurred(Scratch<double>& grid) {
  const int w = map_.width, h = map_.height;
  const double farPlane = rule_.farPlane;
  sizeBuffer(grid, std::size_t(w) * h);
  std::atomic<bool> badTexel{false};
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& rows) {
    bool bad = false;
    BlurRowScratch scratch;
    std::vector<double> row(w);
    std::vector<std::uint8_t> below(w);
    for (int j = rows.begin(); j != rows.end(); ++j) {
      const float* src = map_.depth.data() + std::size_t(j) * w;
      double* out = grid.data() + std::size_t(j) * w;
      bad |= scanDepthRow(src, below.data(), w, floatBitsAtOrAbove(rule_.farSnap));
      if (j == 0 || j == h - 1) {
        std::fill_n(out, w, farPlane);
        continue;
      }
      // blurredDepth of the valid texels, between the first and last (the others are far).
      int b = w, e = 0;
      if (const void* p = std::memchr(below.data(), 1, std::size_t(w))) {
        b = int(static_cast<const std::uint8_t*>(p) - below.data());
        e = w;
        while (!below[e - 1]) --e;
        blurRow(map_, j, row.data(), scratch, b, e);
      }
      for (int i = 0; i < w; ++i) {
        double d = farPlane;
        if (!(i == 0 || i == w - 1 || i < b || i >= e || isFarDepth(src[i], farPlane))) d = rule_.fromBlurred(row[i]);
        out[i] = d;
      }
    }
    if (bad) badTexel.store(true, std::memory_order_relaxed);
  });
  if (badTexel.load()) validateDepths(map_);  // throws, naming the first bad texel
  grid_ = grid.data();
}

void SheetDepths::row(int j, double* d, bool& bad, int b, int e) const {
  const int w = map_.width, h = map_.height;
  if (e < 0) e = w;
  const std::size_t row = std::size_t(j) * w;
  if (j == 0 || j == h - 1) {
    std::fill(d + b, d + e, rule_.farPlane);
  } else if (grid_) {
    std::copy(grid_ + row + b, grid_ + row + e, d + b);
  } else {
    bad |= sheetDepthSpan(map_.depth.data() + row, d, b, e, rule_);
    d[0] = d[w - 1] = rule_.farPlane;  // the ring (outside [b, e) is never read)
  }
}

}  // namespace shadowvol::volume
