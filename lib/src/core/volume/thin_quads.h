// Stage 1t of the volume builder (the sub-grid with back capture, docs/volume.md "Sub-grid",
// step 10): which quads without a boundary side hold a part thinner than the sheet bends there, so
// that the sub-grid samples them.
//
// Back capture records the first face turned away from the light; the sheet runs straight between
// those samples. Where that back surface bends between texel centres by more than the part is
// thick along the light (a thin wing whose underside curves steeply, a shell), the straight run
// passes in front of the part's lit face: false shadow on it, at every map size where the quad has
// no boundary edge (the ninth probe's boeing: 27 of its 64 false pixels at 128² in one quad). The
// sub-grid samples the back surface S times more finely, its bend S^2 times smaller.
#pragma once

#include <cstdint>
#include <vector>

#include "shadowvol/depth_oracle.h"
#include "volume/sheet_depths.h"

namespace shadowvol::volume {

/// The least bend looked at, in texel footprints at the sample's depth: on a smooth curved occluder
/// every sample lies a little off its neighbours' chord, and each such corner costs a ray (the
/// default scene's sphere at 256²: 3,074 more rays with no floor, 1,997 at 1/16 footprint, 1,142
/// at 1/8, 659 at 1/4, 351 at 1/2, flagging no quad at any; the boeing's and the bunny's flagged
/// quads were the same at every floor, but at 1/2 the valley of tests/embree/test_thin_quads_volume.cpp,
/// a fold of 0.37 footprint over plates 0.09 footprint thick, was missed; docs/results/thin-quads).
inline constexpr double kThinChordFloor = 1.0 / 8.0;

/// The quads without a boundary side (splitBits' bits 0 and 1, which must hold the boundary edges)
/// and not flagged yet (kHiddenQuadBit) one of whose corners' samples lies off the chord of its two
/// neighbours (x, y or either diagonal; the chord as the projection interpolates) by more than
/// kThinChordFloor footprints and by more than the part is thick there: its back sample less the first surface the light meets on its ray (one ray
/// of `oracle` with front capture, cast only at corners off a chord). Each is marked with
/// kHiddenQuadBit (the sub-grid takes it as a hidden quad) and returned in quad order. For back
/// capture without a bias only (none otherwise: front capture's bias and its crease quads keep the
/// sheet behind the lit face; midpoint capture's sheet is the middle of the part). Samples read as
/// the boundary-edge rule reads them (SheetDepthRule::fromStored, without the blur's averaging).
/// `rays` (when given) receives how many rays it cast.
std::vector<std::uint32_t> findThinQuads(const SheetDepths& sheet, const DepthOracle& oracle, std::uint8_t* splitBits,
                                         std::size_t* rays = nullptr);

}  // namespace shadowvol::volume
