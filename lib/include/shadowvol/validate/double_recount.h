// The crossing counts recounted in double precision, on the volume's double positions through a
// CGAL AABB tree, with the same counting rule as Embree's (countPixel), for two kinds of pixel:
// - Counts that contradict themselves. For a closed volume every pixel ray from the eye has the
//   same net crossing (its z-fail minus z-pass count: 0 when the eye is outside, +1 inside). A
//   pixel whose Embree counts give another net lost or doubled a hit in float, which happens where
//   the volume reaches far beyond the view (walls of 3e5 units under a 2e6 ground: 1,200 wrong
//   pixels of 76,800). Such pixels are recounted.
// - Ties in the image plane. A rasteriser snaps the volume's projected vertices to its sub-pixel
//   grid (GL_SUBPIXEL_BITS, 8 on llvmpipe and NVIDIA's driver), so a pixel centre within a
//   fraction of that grid of a projected edge may be covered by the triangle on either side (or by
//   none or both where the edge is a silhouette of the volume as the camera sees it). For the
//   pixels whose stencil lies outside their admissible range, the range is widened by the counts
//   of four rays through the corners of a square of +-kImagePlaneTie pixels around the centre:
//   every edge that passes within kImagePlaneTie of the centre separates it from one corner. A
//   triangle a corner's ray meets counts at its depth there and at its plane's depth on the
//   centre's ray, where the rasteriser evaluates it.
//   A triangle smaller than the square can lie between those rays (a sub-grid's wall at a large
//   map is a few hundredths of a pixel across): every triangle whose projection meets the square
//   also widens the range, drawn or not where it only meets it, either way round where its height
//   in the image is within the snap, at any depth its plane can have at the centre with its
//   vertices moved by up to kImagePlaneTie pixels.
//   The scene's own edges snap too: where the camera sees another surface at a corner (a
//   silhouette of the scene within kImagePlaneTie of the centre), the rasteriser may have drawn
//   that surface at the pixel, so the counts split at the corner's visible depth are admitted too.
#pragma once

#include <cstddef>
#include <vector>

#include "shadowvol/camera.h"
#include "shadowvol/embree/ray_queries.h"
#include "shadowvol/volume_mesh.h"

namespace shadowvol {

/// Half the side of the square of image-plane ties, in pixels: two steps of an 8-bit sub-pixel
/// grid. One step was too few: llvmpipe covered a pixel whose centre lies 0.006 px outside a
/// projected volume edge (the fandisk under a 64 x 48 map at 128 x 96; moving that triangle
/// sideways, its coverage of the pixel began 0.006 px before the exact edge reached the centre,
/// 2026-12-05); the snap of an edge's two ends alone moves it by at most sqrt(2)/512 px.
inline constexpr double kImagePlaneTie = 2.0 / 256.0;

/// Recounts every non-background pixel whose zfail - zpass differs from `expectedNet` (0: the eye
/// is outside the volume, 1: inside). Returns the number of pixels recounted. The recount uses the
/// same primary rays, tie band and merge tolerance as countCrossings.
std::size_t recountInconsistentPixels(const VolumeMesh& volume, const Camera& camera, const CameraHits& hits,
                                      int expectedNet, CrossingCounts& counts);

/// The four corners of the square of image-plane ties, in pixels (PrimaryRays::ray's dx, dy), in
/// the order widenImagePlaneTies reads cornerDepths in.
std::vector<glm::dvec2> imagePlaneTieCorners();

/// Widens the admissible z-fail range (zfailMin, zfailMax) of each of `pixels` (indices into the
/// frame, rows top first) by the counts of the four rays +-kImagePlaneTie pixels off its centre,
/// each split at the pixel's visible depth, with each triangle a corner's ray meets taken at its
/// depth along that ray and, as a rasteriser that covers the pixel interpolates it, at its plane's
/// depth along the centre's ray. With `cornerDepths` (four per pixel: the scene's
/// visible depth along those rays, visibleDepths with imagePlaneTieCorners), where a corner sees
/// another surface (outside the tie band of the pixel's depth; not background), the centre's and
/// the corners' rays are split at that depth as well; so they are at each of `nearDepths[p]` (the
/// depths along the centre's ray of the scene's triangles whose image comes within the tie square,
/// image_plane_surfaces.h: a sliver between the corners). Returns the number of pixels whose range grew.
std::size_t widenImagePlaneTies(const VolumeMesh& volume, const Camera& camera, const CameraHits& hits,
                                const std::vector<std::size_t>& pixels, CrossingCounts& counts,
                                const std::vector<double>& cornerDepths = {},
                                const std::vector<std::vector<double>>& nearDepths = {});

}  // namespace shadowvol
