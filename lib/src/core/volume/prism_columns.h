// Stage 0p of the volume build (VolumeBuildOptions::facePrisms with withoutCasters; docs/volume.md
// "Face prisms"): the sheet hands the refined quads' columns over to the face prisms.
//
// Why: behind a closed caster the prisms of its faces turned towards the light are its shadow (and
// its inside), exactly (caster_faces.h). The sheet in the same columns adds only its own errors
// there: between its samples it crosses the lit surfaces near an outline (false shadow) and its
// walls stand at the bisected contour, a fraction of a texel off the true one. So in those columns
// the sheet records the scene without the closed casters that the prisms hold whole
// (handedToPrisms): the ground under a caster, or the far plane; the caster's shadow there is the
// prisms'.
//
// Which columns: the refined quads of the map as captured (the first pass of stage 1r) with a
// corner at which the capture records a handed-over mesh (the hand-over oracle says so: the
// recorded hit's mesh, so an open mesh recorded in front of a handed one, or entry capture's front
// face before a handed mesh's back face, stays recorded); their corner texels are the handed-over
// texels, and a quad refined for an open mesh, or for a caster between the texel centres alone,
// stays the sheet's. A point of the light's image plane belongs to the texel whose centre is
// nearest (a square around it; a tie may go either way: both texels are corners of the quads the
// prisms fill). The sheet is then built from the map with the handed-over texels recaptured: its
// rays (refinement's bisection, the sub-grid's samples) ask the hand-over oracle inside those
// squares (the caster-free record where a handed-over mesh is recorded, the capture's own
// elsewhere) and the full oracle outside. A quad with a handed-over corner and another that sees
// the caster gets a boundary edge at the squares' border where their depths differ by more than
// the discontinuity rule's threshold, its walls within the caster's shadow. The prisms fill every
// quad with a handed-over corner (the handed-over squares lie in those quads) and, as without the
// hand-over, the refined quads of the build. The snap's (surfaceEnds) answers are dropped where
// either end of a query lies in a handed-over square (the triangle it follows may not be the one
// recorded there: bisection decides there), and the hidden-surface search in the quads the prisms
// fill looks at the scene without the handed-over meshes (CasterFreeOracles::nearerSurfaces; unset:
// the whole scene's flags are kept there). Midpoint capture records no single mesh: nothing is
// handed over.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "shadowvol/depth_map.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol::volume {

struct PrismColumns {
  DepthMap map;                      ///< the map with the handed-over texels recaptured without the casters
  std::vector<std::uint8_t> texels;  ///< per texel: 1 = handed over
  std::vector<std::uint8_t> quads;   ///< per quad: 1 = a handed-over corner (the prisms' columns)
  std::size_t texelCount = 0;        ///< handed-over texels
  std::size_t rays = 0;              ///< rays cast: one per refined quad's corner, one more where handed over
};

/// The columns of `refinedQuads` (quad indices qj * (W - 1) + qi) handed over and the map
/// recaptured there by `handOver` (see the header comment); texelCount 0 where none is.
PrismColumns findPrismColumns(const DepthMap& map, std::span<const std::uint32_t> refinedQuads,
                              const HandOverOracle& handOver);

/// `options` with its oracles answering for the handed-over map (see the header comment); the
/// returned oracles refer to `columns`, which they keep alive.
VolumeBuildOptions handOverColumns(const VolumeBuildOptions& options, std::shared_ptr<const PrismColumns> columns);

}  // namespace shadowvol::volume
