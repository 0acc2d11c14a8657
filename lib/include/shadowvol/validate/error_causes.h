// Why a depth-map method misclassifies the pixels it does: its resolution, its capture, or (a
// shadow volume's) the light window's border.
//
// The test at unlimited resolution: the surface the map's capture mode records on the pixel's own
// light ray (the depth oracle, embree_depth_oracle.h), pushed away from the light by the method's
// offset, lies before the pixel's surface point: captured + offset < the point's light-view depth.
// A pixel the method gets wrong but this test gets right is a resolution error (texel sampling,
// the sheet's interpolation between texel centres, walls within 2^-(K+1) texel, features thinner
// than a texel or than the sub-grid's cells): a finer map, refinement or --fit view can remove it.
// One the test gets wrong as well is a capture error: the capture mode (back capture through an
// open mesh), the bias (acne or a leak within it) or the exact shadow ray's own offset decide it,
// whatever the resolution. A shadow map's slope-scaled bias scales with the texel footprint and
// vanishes at unlimited resolution; its constant bias stays.
//
// The border: a shadow volume's sheet puts the map's outermost texel ring on the far plane
// (docs/volume.md, "Sheet vertices"), so where a shadow reaches the light window's edge the volume
// slants down across the last texel and the band between the window's edge and the centres of the
// second ring (texel coordinate below 1 from the window's first texel centre, i.e. 1.5 texels from
// its edge) may be lit. Refinement does not move it; a wider window (the light's extent or fov, or
// a fitted one, which keeps a margin) or a finer map does. A missed pixel (exact: shadowed) the
// test above gets right whose point lies in that band is counted there rather than as resolution.
// The accuracy verdict allows kMaxBorderPixels of them. The volumes' own maps reach a guard band
// past the window (DepthMap::guard, kVolumeGuardTexels in light.h) that puts the ring and its slope
// outside the window: for them the strip counted is the same one, less than a texel inside the
// window's own outermost texel centres, which the band is there to keep shadowed (0 when it does;
// a map without a band, guard 0, shows the lit strip).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "shadowvol/depth_map.h"
#include "shadowvol/embree/ray_queries.h"
#include "shadowvol/scene.h"

namespace shadowvol {

inline constexpr std::size_t kMaxBorderPixels = 16;  ///< border pixels a frame may have (round-off)

struct ErrorCauses {
  std::size_t resolution = 0;  ///< misclassified pixels the unlimited-resolution test gets right
  std::size_t capture = 0;     ///< misclassified pixels it gets wrong too
  std::size_t border = 0;      ///< of the missed ones it gets right, those in a volume's border band (see above)
  double offset = 0.0;         ///< the method's depth offset used (world units, away from the light)
};

/// Splits the misclassified pixels (exact Lit or Shadowed, methodShadowed[k] != 0 disagreeing with
/// it) of a frame with one depth map `map` (spot or directional light; the map read back from the
/// GPU is fine: the oracle casts Embree rays with its matrices, range and capture mode) by the
/// test above; `volumeRing`: the method is a shadow volume built over `map` (its border band
/// counts). One ray per misclassified pixel, through a BVH of `scene` built here.
ErrorCauses splitErrorCauses(const Scene& scene, const DepthMap& map, double offset, const CameraHits& hits,
                             const std::vector<PixelClass>& exact, const std::vector<std::uint8_t>& methodShadowed,
                             bool volumeRing = false);

/// Whether continuous texel coordinates (DepthMap::texelOf) lie in a volume's border band over a
/// width x height map: less than one texel inside the outermost ring's centres.
bool inVolumeBorderBand(const glm::dvec2& texel, int width, int height);

}  // namespace shadowvol
