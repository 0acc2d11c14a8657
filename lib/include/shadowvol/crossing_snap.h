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
//     sheet vertex is, without a bias (back and midpoint capture: the triangle's own depth at s_e,
//     the rim, measured worse there: for back capture it is where the lit front faces meet the
//     back faces, and the wall's top then touches them). With a bias B > 0 (front capture), without
//     blur and with CrossingSnap::rimBias (the sub-grid's crossings) it moves to the rim plus the bias the rim needs, if that is nearer
//     (rimVertexDepth): B holds the whole sheet back from the surface it records, and next to the
//     silhouette, where a surface turns away from the light, B is what lost the shadows that start
//     within it (a model's parts shading each other, the terminator of a faceted curve). A surface
//     segment's far vertex goes to the probe's surface (where it lies beyond the near vertex; else
//     it stays at d(hi)). Snapped;
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

/// The least fraction of the bias B that a snapped crossing's near vertex keeps above the rim
/// (rimVertexDepth): for the depth precision and a bend the rule cannot see (measured in
/// docs/results/rim-bias).
inline constexpr double kRimBiasFloor = 1.0 / 8.0;
/// The least distance in texels between lo and the rim from which rimVertexDepth carries the rim's
/// triangle back to the segment's near end (nearer, float rounding of d(lo) would dominate).
inline constexpr double kRimBaseTexels = 1e-3;

/// The depth of the near vertex of segment g's crossing snapped at sExit (bracket b: d(lo) with
/// the bias, as every sample), where the recorded triangle shows depth `rim` (SurfaceEndOracle).
/// With B = rule.bias > 0 and a finite rim: rim + keep, never beyond d(lo) nor before the near
/// plane, keep = min(B, kRimBiasFloor * B + e), e = how far the rim's triangle, carried back along
/// the segment to its near end (from its depths at lo and at the rim, as the light's projection
/// interpolates: depthAlongEdge), lies behind the near end's sample (0 when in front). The sheet's
/// straight run from the near end to the rim passes in front of the surface between them only
/// where the surface bends away from the light, and by at most e then (a bend away: the surface
/// lies between the chord and the rim triangle's plane); a fold towards the silhouette (e <= 0)
/// needs nothing. keep = B when lo and the rim lie within kRimBaseTexels or the near end is on
/// the far plane. Without a bias or a finite rim: d(lo).
double rimVertexDepth(const DepthMap& map, const BisectionSegment& g, const BisectionBracket& b, double sExit,
                      double rim, const SheetDepthRule& rule);

/// The crossings of `segments` (texel coordinates of `map`) from their last brackets, snapped by
/// the header comment's rule; `steps` is the bisection's K. Adds the rays of both oracles and the
/// time inside them to `budget`, the crossings snapped to *snapped.
std::vector<Crossing> snapCrossings(const DepthMap& map, std::span<const BisectionSegment> segments,
                                    std::span<const BisectionBracket> brackets, const SheetDepthRule& rule, bool blur,
                                    int steps, const DepthOracle& oracle, const SurfaceEndOracle& ends,
                                    RayBudget& budget, std::size_t& snapped, bool rimBias = false);

}  // namespace shadowvol
