// Why a depth-map method misclassifies the pixels it does: its resolution, or its capture.
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
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "shadowvol/depth_map.h"
#include "shadowvol/embree/ray_queries.h"
#include "shadowvol/scene.h"

namespace shadowvol {

struct ErrorCauses {
  std::size_t resolution = 0;  ///< misclassified pixels the unlimited-resolution test gets right
  std::size_t capture = 0;     ///< misclassified pixels it gets wrong too
  double offset = 0.0;         ///< the method's depth offset used (world units, away from the light)
};

/// Splits the misclassified pixels (exact Lit or Shadowed, methodShadowed[k] != 0 disagreeing with
/// it) of a frame with one depth map `map` (spot or directional light; the map read back from the
/// GPU is fine: the oracle casts Embree rays with its matrices, range and capture mode) by the
/// test above. One ray per misclassified pixel, through a BVH of `scene` built here.
ErrorCauses splitErrorCauses(const Scene& scene, const DepthMap& map, double offset, const CameraHits& hits,
                             const std::vector<PixelClass>& exact, const std::vector<std::uint8_t>& methodShadowed);

}  // namespace shadowvol
