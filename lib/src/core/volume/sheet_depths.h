// Stage 1 of the volume builder: the sheet depth of every texel (sheet_depth.h's rule), either
// computed per row where a later stage needs it, or, with blur (which needs each texel's
// neighbours), materialised once into a grid. Also the row kernels that scan stored depths:
// validity, far flags, spans.
#pragma once

#include <cstdint>
#include <utility>

#include "shadowvol/depth_map.h"
#include "shadowvol/sheet_depth.h"
#include "volume/build_buffers.h"

namespace shadowvol::volume {

/// One pass over n stored depths, on their bits (integer compares vectorise; float compares do
/// not under GCC's default trapping math): below[i] = 1 where the depth is less than the float
/// whose bits are `limit` (for valid depths, which are >= 0 or +inf, the order of the magnitude
/// bits is the order of the values; -0 counts as 0); returns true when a depth is NaN or negative.
bool scanDepthRow(const float* __restrict src, std::uint8_t* __restrict below, int n, std::uint32_t limit);

/// Bits of the smallest float f with double(f) >= x (x > 0): for every float d, double(d) < x
/// exactly when d < f.
std::uint32_t floatBitsAtOrAbove(double x);

/// far[i] = (d[i] == farPlane) for i in [0, n), compared as bits (d is never NaN, farPlane > 0).
void farFlags(const double* __restrict d, std::uint8_t* __restrict far, int n, double farPlane);

/// The first and last i in [0, n) with far[i] == 0 (n and -1 when there is none).
std::pair<int, int> nearSpan(const std::uint8_t* far, int n);

/// rule.fromStored of texels [b, e) of one interior row from the stored depths src into d;
/// returns true when a stored depth is NaN or negative.
bool sheetDepthSpan(const float* __restrict src, double* __restrict d, int b, int e, SheetDepthRule rule);

/// Throws InputError naming the first texel (row-major from texel (0, 0)) holding NaN or a
/// negative depth. The builder's passes flag such texels as they read them and call this only then.
void validateDepths(const DepthMap& map);

/// The sheet depths of one map under one rule.
/// The sheet's depth at fraction f from depth d0 to d1 along a straight line in texel space, as the
/// light's projection interpolates it: linearly for a directional light, its inverse linearly for a
/// spot light (`perspective`).
inline double depthAlongEdge(double d0, double d1, double f, bool perspective) {
  return perspective ? 1.0 / ((1.0 - f) / d0 + f / d1) : (1.0 - f) * d0 + f * d1;
}

class SheetDepths {
 public:
  SheetDepths(const DepthMap& map, const SheetDepthRule& rule) : map_(map), rule_(rule) {}

  /// Computes every texel's blurred sheet depth into `grid`, row-parallel, and reads it from
  /// there afterwards. Throws InputError (validateDepths) for a NaN or negative stored depth.
  void materialiseBlurred(Scratch<double>& grid);
  bool materialised() const { return grid_ != nullptr; }

  /// Sheet depth of texel (i, j), one at a time (the row loops give the same values).
  double at(int i, int j) const {
    const std::size_t t = map_.index(i, j);
    if (grid_) return grid_[t];
    if (SheetDepthRule::ring(i, j, map_.width, map_.height)) return rule_.farPlane;
    return rule_.fromStored(map_.depth[t]);
  }

  /// Sheet depths of texels [b, e) of row j into d (e < 0: the width); `bad` is set when a
  /// stored depth read here is NaN or negative. The same values as at().
  void row(int j, double* d, bool& bad, int b = 0, int e = -1) const;

  const SheetDepthRule& rule() const { return rule_; }
  const DepthMap& map() const { return map_; }

 private:
  const DepthMap& map_;
  SheetDepthRule rule_;
  const double* grid_ = nullptr;
};

}  // namespace shadowvol::volume
