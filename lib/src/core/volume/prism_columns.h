// Stage 0p of the volume build (VolumeBuildOptions::facePrisms with withoutCasters; docs/volume.md
// "Face prisms"): the sheet hands the refined quads' columns over to the face prisms.
//
// Why: behind a closed caster the prisms of its faces turned away from the light are its shadow,
// exactly (caster_faces.h). The sheet in the same columns adds only its own errors there: between
// its samples it crosses the lit surfaces near an outline (false shadow) and its walls stand at the
// bisected contour, a fraction of a texel off the true one. So in those columns the sheet records
// the scene without the closed casters that the prisms hold whole (handedToPrisms): the ground
// under a caster, or the far plane; the caster's shadow there is the prisms'.
//
// Which columns: the refined quads of the map as captured (the first pass of stage 1r) with a
// corner at which a handed-over mesh is recorded (the oracles with and without those meshes differ
// there): their
// corner texels are the handed-over texels (a quad refined for an open mesh, or for a caster
// between the texel centres alone, stays the sheet's). A point of the light's image plane belongs
// to the texel whose centre is nearest (a square around it; ties towards the larger index,
// std::lround). The sheet is then built from the map with those texels recaptured, its rays
// (refinement's bisection, the sub-grid's samples) asking the oracle without the casters inside
// their squares and the full oracle outside; a quad with a handed-over corner and another not gets
// a boundary edge at the squares' border where their depths differ by more than the
// discontinuity rule's threshold (the caster seen at the other corner), its walls within the
// caster's shadow. The prisms fill every quad with a handed-over corner (the handed-over squares
// lie in those quads). The snap (surfaceEnds) is not asked where either end of a query lies in a
// handed-over square (the triangle it follows is not the one recorded there: bisection decides
// there), and the hidden-surface search in the quads the prisms fill is the scene's without the
// casters (CasterFreeOracles::nearerSurfaces; unset: the full scene's).
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
  std::size_t rays = 0;              ///< rays cast: the refined quads' corners, by both oracles
};

/// The columns of `refinedQuads` (quad indices qj * (W - 1) + qi) handed over, the map recaptured
/// there by `withoutCasters` (see the header comment): a quad's corner records a handed-over mesh
/// where `withoutCasters` and `full` (the oracle of the whole scene) answer differently at its
/// centre (not the map's value, which a GPU's light pass may have stored a few ulps apart).
/// texelCount 0 where none is handed over.
PrismColumns findPrismColumns(const DepthMap& map, std::span<const std::uint32_t> refinedQuads,
                              const DepthOracle& full, const DepthOracle& withoutCasters);

/// `options` with its oracles answering for the handed-over map (see the header comment); the
/// returned oracles refer to `columns`, which they keep alive.
VolumeBuildOptions handOverColumns(const VolumeBuildOptions& options, std::shared_ptr<const PrismColumns> columns);

}  // namespace shadowvol::volume
