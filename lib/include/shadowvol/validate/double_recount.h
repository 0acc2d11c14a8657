// The crossing counts recounted in double precision where Embree's float counts contradict
// themselves. For a closed volume every pixel ray from the eye has the same net crossing (its
// z-fail minus z-pass count: 0 when the eye is outside, +1 inside). A pixel whose Embree counts
// give another net lost or doubled a hit in float, which happens where the volume reaches far
// beyond the view (walls of 3e5 units under a 2e6 ground: 1,200 wrong pixels of 76,800). Such
// pixels are recounted on the volume's double positions, through a CGAL AABB tree, with the
// same counting rule (countPixel).
#pragma once

#include <cstddef>

#include "shadowvol/camera.h"
#include "shadowvol/embree/ray_queries.h"
#include "shadowvol/volume_mesh.h"

namespace shadowvol {

/// Recounts every non-background pixel whose zfail - zpass differs from `expectedNet` (0: the eye
/// is outside the volume, 1: inside). Returns the number of pixels recounted. The recount uses the
/// same primary rays, tie band and merge tolerance as countCrossings.
std::size_t recountInconsistentPixels(const VolumeMesh& volume, const Camera& camera, const CameraHits& hits,
                                      int expectedNet, CrossingCounts& counts);

}  // namespace shadowvol
