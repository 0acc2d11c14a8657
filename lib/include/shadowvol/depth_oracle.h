// A depth oracle: the captured depth at any point of a light's image plane, not only at texel
// centres. Silhouette refinement (VolumeBuildOptions::refineSteps) asks it where the near surface
// ends along a boundary edge. The volume core does not link a ray tracer: the caller hands one in
// (shadowvol_embree: EmbreeDepthOracle; tests: analytic scenes).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/depth_map.h"

namespace shadowvol {

/// Writes depth[k] = what the map's capture would store at light NDC (x, y) = ndc[k] (depth_map.h:
/// light-view depth in world units, DepthMap::kNoHit where nothing is hit in [near, far]), using
/// the map's light matrices, near/far and capture mode. At a texel centre it gives the map's own
/// value (up to capture differences between a GPU light pass and the oracle's rays). Called with
/// batches of points (one batch per refinement step), from one thread at a time; it may run the
/// batch in parallel itself. ndc.size() == depth.size().
using DepthOracle = std::function<void(const DepthMap& map, std::span<const glm::dvec2> ndc, std::span<float> depth)>;

/// Where the surface the capture records ends (refinement's snap, crossing_snap.h): for each k, the
/// triangle the map's capture mode records on the light ray through light NDC from[k], followed in
/// the light's image plane towards to[k]. Writes t[k] = the fraction of the way from[k] -> to[k] at
/// which that straight path leaves the triangle's image (0 when from[k] lies on its edge already;
/// may exceed 1), NaN where the capture records no single triangle there (no hit; midpoint
/// capture, which records the middle of two surfaces; a triangle edge-on to the light or reaching
/// behind a spot light's apex plane). Writes triangle[k] = that triangle's corners (the map's
/// coordinates, as its rays: triangleDepthAt in triangle_exit.h reads the depth it shows anywhere),
/// all NaN with t[k]. Same calling rules as DepthOracle.
using SurfaceEndOracle =
    std::function<void(const DepthMap& map, std::span<const glm::dvec2> from, std::span<const glm::dvec2> to,
                       std::span<double> t, std::span<std::array<glm::dvec3, 3>> triangle)>;

/// Which quads hide a surface nearer than the sheet (the sub-grid's search for hidden surfaces,
/// nearer_surfaces.h): sets flags[q] = 1 for each quad q = qj * (W - 1) + qi of the map's grid
/// whose square holds a point of a surface the map's capture can record, nearer than limit[q]
/// (light-view depth), and flags[q] |= kRimFlag (nearer_surfaces.h) where a point of an open
/// mesh's rim (a border: where light passes through a hole or around a sheet's edge) lies in that
/// square nearer than rimLimit[q] (empty rimLimit: no rim search); leaves the other flags. The
/// Embree oracle answers it from the scene's triangles and rims (findNearerSurfaces,
/// findOpenRims). Same calling rules as DepthOracle.
using NearerSurfaceOracle = std::function<void(const DepthMap& map, std::span<const float> limit,
                                               std::span<const float> rimLimit, std::span<std::uint8_t> flags)>;

/// The casters' faces for the refined volume's face prisms (VolumeBuildOptions::facePrisms): the
/// faces findCasterFaces (caster_faces.h) selects for the quads flagged non-zero in `quads`
/// ((W - 1) * (H - 1) entries, q = qj * (W - 1) + qi), corners in the map's coordinates (as its
/// rays). The Embree oracle answers it from the scene's triangles. Same calling rules as DepthOracle.
using CasterFaceOracle =
    std::function<std::vector<std::array<glm::dvec3, 3>>(const DepthMap& map, std::span<const std::uint8_t> quads)>;

/// The sheet's hand-over of the face prisms' columns (VolumeBuildOptions::withoutCasters): for each
/// k, handed[k] = 1 where the map's capture records, on the light ray through light NDC ndc[k], a
/// closed mesh that the prisms hold whole for this map (handedToPrisms, caster_faces.h), and then
/// depth[k] = what the capture of the scene without those meshes records there; handed[k] = 0 and
/// depth[k] = the capture's own record elsewhere (and always for midpoint capture, which records
/// no single surface). Same calling rules as DepthOracle; handed.size() == depth.size() == ndc.size().
using HandOverOracle = std::function<void(const DepthMap& map, std::span<const glm::dvec2> ndc, std::span<float> depth,
                                          std::span<std::uint8_t> handed)>;

/// The oracles of the hand-over (EmbreeDepthOracle::withoutCasters): `depth` as above;
/// `nearerSurfaces` (optional) a NearerSurfaceOracle of the scene without the handed-over meshes,
/// asked about the quads the prisms fill (unset: the whole scene's search is kept there).
struct CasterFreeOracles {
  HandOverOracle depth;
  NearerSurfaceOracle nearerSurfaces;
};

/// Fills every texel of `map` (its size, light matrices, planes and capture mode as given) with
/// the oracle at the texel's centre: the map a capture by the oracle's rays stores (with
/// EmbreeDepthOracle, captureDepthEmbree's values). Whole rows of up to 65,536 texels per oracle
/// call (one call for maps up to 256 x 256), so the points asked for stay small beside the map.
/// Throws what the oracle throws; an unset oracle is a logic error (SV_CHECK).
void fillFromOracle(DepthMap& map, const DepthOracle& oracle);

}  // namespace shadowvol
