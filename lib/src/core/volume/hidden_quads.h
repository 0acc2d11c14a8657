// Stage 1h of the volume builder (the sub-grid's search for hidden surfaces, docs/volume.md
// "Hidden surfaces"; the geometry in shadowvol/nearer_surfaces.h): which quads without a boundary
// edge hide an occluder, or a gap in one, that no texel centre sees, so that the sub-grid samples
// them too.
#pragma once

#include <cstdint>
#include <vector>

#include "shadowvol/depth_oracle.h"
#include "volume/sheet_depths.h"

namespace shadowvol::volume {

/// The quads without a boundary side (splitBits' bits 0 and 1, findBoundaryEdges) whose square
/// holds a surface the capture records nearer than every corner's sample by more than the floor of
/// the discontinuity rule on an S x S sub-grid (kJumpFootprints texel footprints at that sample's
/// depth, divided by S = `subdivisions`: what a sub-grid sample there needs to make a boundary
/// sub-edge with that corner; a nearer limit would flag quads whose sub-grid finds nothing, a farther
/// one would miss what it resolves), or, with every corner far, any surface short of the far plane,
/// as `search` finds them (EmbreeDepthOracle::nearerSurfaces); and those whose square holds an open
/// mesh's rim nearer than the farthest corner's sample plus kJumpFootprints texel footprints there
/// (a gap in the surface the corners record: a hole, a sheet's edge; a rim farther than that lies
/// behind the recorded surface, which hides it). Each is marked with kHiddenQuadBit in splitBits (at
/// its lower-left texel), and returned in quad order; `*rims` (when given) counts those found by
/// their rims alone. The samples are read as the boundary-edge rule reads them
/// (SheetDepthRule::fromStored, the ring far), without the bias.
std::vector<std::uint32_t> findHiddenQuads(const SheetDepths& sheet, const NearerSurfaceOracle& search,
                                           int subdivisions, std::uint8_t* splitBits, std::size_t* rims = nullptr);

}  // namespace shadowvol::volume
