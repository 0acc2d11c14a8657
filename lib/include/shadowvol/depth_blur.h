// The thesis's depth blur (algorithm.md, "Depth blurring"), as a pure function of a DepthMap.
// The GPU volume shader mirrors blurredDepth() sample for sample.
#pragma once

#include <vector>

#include "shadowvol/depth_map.h"

namespace shadowvol {

/// Relative tolerance under which a depth counts as "on the far plane": d >= far * (1 - kFarSnap).
/// A few float ulps (2^-20): a float depth map cannot store the far plane closer than that, and
/// a vertex that close to the far plane would only give sliver walls.
inline constexpr double kFarSnap = 1.0 / (1 << 20);

/// True when a stored depth is invalid for blurring and becomes a far-plane vertex: kNoHit (+inf),
/// or at/after the far plane (within kFarSnap). NaN and negative depths are rejected earlier
/// (buildVolume throws), so they never reach this test.
inline bool isFarDepth(double d, double farPlane) { return !(d < farPlane * (1.0 - kFarSnap)); }

/// Blurred light-view depth (world units) of texel (i, j), which must itself be valid:
/// the mean of 9 samples at offsets (dx, dy) in {-1.5, 0, +1.5}^2 texels, each a bilinear
/// interpolation of the stored depths (texel centres at integer coordinates, clamp-to-edge).
/// Bilinear weights are taken only over valid texels (see isFarDepth) and renormalised; a sample
/// whose valid texels all have zero weight is skipped; the valid samples are averaged with equal
/// weights. The centre sample (offset 0, 0) is the texel itself, so at least one sample is valid.
/// Far-plane and no-hit texels therefore never drag an occluder towards the far plane.
double blurredDepth(const DepthMap& map, int i, int j);

/// Per-row scratch of blurRow (two buffers of 5 rows), reused across calls.
struct BlurRowScratch {
  std::vector<double> values, valid;
};

/// Row j of blurDepths into out[b, e) (e = -1: the width): blurredDepth of every valid texel, bit
/// for bit (the interior as one vectorised loop, the two outermost texels and rows through
/// blurredDepth); invalid texels copied unchanged. Other entries of out are not written.
void blurRow(const DepthMap& map, int j, double* out, BlurRowScratch& scratch, int b = 0, int e = -1);

/// blurredDepth for every valid texel; invalid texels are copied unchanged (the blur never creates
/// or removes hits). Row-parallel (TBB), deterministic. Same layout as DepthMap::depth.
std::vector<double> blurDepths(const DepthMap& map);

}  // namespace shadowvol
