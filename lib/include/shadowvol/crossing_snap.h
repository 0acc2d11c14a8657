// Refinement's snap: each crossing found by bisection (silhouette_refinement.h) moved from the
// middle of its last bracket to where the recorded surface ends, so that on a polygonal mesh a
// wall stands on the light ray through the silhouette itself, not within 2^-(K+1) of a texel of it.
//
// Per segment, with its last bracket [lo, hi] (lo on the near side, hi off it) and L its length in
// texels, up to kSnapRounds rounds, each one batch of the SurfaceEndOracle (depth_oracle.h: where
// the triangle recorded at lo ends on the way to hi, s_e) and one batch of the depth oracle (a probe
// just beyond it, at s_p = s_e + min(kSnapProbeTexels / L, (hi - s_e) / 2)):
//   - the probe is off the near side (bisection's rule: no hit for a far segment; for a surface
//     segment, no hit or not nearer than the middle of d(lo) and d(hi)): the surface ends at s_e,
//     the crossing moves there. Its near vertex stays at d(lo), a sample of the surface as every
//     sheet vertex is (the triangle's own depth at s_e, the rim, measured worse: for back capture
//     it is where the lit front faces meet the back faces, and the wall's top then touches them);
//     the triangle is kept with the crossing (Crossing::rim), from which the sub-grid with front
//     capture's bias sets the near vertex nearer the rim (volume/rim_bias.h). A surface segment's
//     far vertex goes to the probe's surface (where it lies beyond the near vertex; else it stays
//     at d(hi)). Snapped;
//   - the probe is on the near side (the surface goes on in a neighbouring triangle): lo = s_p,
//     d(lo) = its depth, and the next round starts from there.
// A triangle that ends at hi itself (within kSnapEndSlack of the bracket) ends the surface there
// without a probe (hi is off the near side). Left in the middle of its last bracket, as without
// the snap: a segment whose recorded surface has no single triangle (NaN: midpoint capture, an
// edge-on triangle), whose triangle reaches past hi (the capture at hi records a nearer surface),
// or whose rounds run out. A snapped s is clamped into [2^-(K+2), 1 - 2^-(K+2)] (strictly inside
// the segment, as bisection's crossings; nearer an end than that it moves by less than
// bisection's own error). Both oracles' rays count.
#pragma once

#include <span>
#include <vector>

#include "shadowvol/depth_oracle.h"
#include "shadowvol/sheet_depth.h"
#include "shadowvol/silhouette_refinement.h"

namespace shadowvol {

/// Rounds of the snap per segment (each: one surface-end ray, one probe ray).
inline constexpr int kSnapRounds = 3;
/// How far beyond a triangle's end the probe looks, in texels: above the few 1e-4 texel by which a
/// float ray through a 4096^2 map can stray, far below bisection's 2^-(K+1) at the K used.
inline constexpr double kSnapProbeTexels = 1.0 / 4096.0;
/// A triangle's end up to this fraction of the bracket past hi counts as at hi (rounding).
inline constexpr double kSnapEndSlack = 1e-9;

/// The crossings of `segments` (texel coordinates of `map`) from their last brackets, snapped by
/// the header comment's rule; `steps` is the bisection's K. Adds the rays of both oracles and the
/// time inside them to `budget`, the crossings snapped to *snapped.
std::vector<Crossing> snapCrossings(const DepthMap& map, std::span<const BisectionSegment> segments,
                                    std::span<const BisectionBracket> brackets, const SheetDepthRule& rule, bool blur,
                                    int steps, const DepthOracle& oracle, const SurfaceEndOracle& ends,
                                    RayBudget& budget, std::size_t& snapped);

}  // namespace shadowvol
