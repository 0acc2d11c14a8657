// Stage 1c of the volume builder (the sub-grid with a sheet bias, docs/volume.md "Sub-grid", step 8):
// which quads without a boundary side hold a crease where the sheet bends away from the light, so
// that the sub-grid samples them and lowers the bias there (subgrid_bias.h).
//
// Front capture holds the sheet a texel footprint B behind the lit surface, enough for the sheet's
// straight interpolation between texel centres never to pass in front of a surface it crosses
// (acne), and shadows that start within B of the surface are lost: contact shadows in a concave
// crease (a stem on the ground, a fold of cloth, parts of a model shading each other). The sub-grid
// samples such a crease S times more finely and measures how far its sheet bends there, so its
// nodes can keep far less bias; the crease itself makes no boundary edge, so it is found here.
#pragma once

#include <cstdint>
#include <vector>

#include "volume/sheet_depths.h"

namespace shadowvol::volume {

/// How far behind the chord of its neighbours a sample must lie, in units of B / S, for its quads to
/// go on the sub-grid: 1/2, so that a step of more than B / S between two flat surfaces (the sample
/// just beyond it lies half the step behind the chord), or a fold that moves the depth by as much,
/// is sampled: B / S is what the sub-grid's spacing needs on a surface tilted 45 degrees, and a
/// step above it shows a shadow there that B hides on the texel grid. Measured (README "Sub-grid
/// bias", docs/results/crease-step): at 1 (B / S) the contact strip where an open terrain's edge
/// rises from the ground stayed lost at 128^2 (28 pixels against the 2048^2 map's 22), at 1/2 it is
/// 18; 0.6 gave 24, 1/4 and 1/10 no more than 1/2 for more quads.
inline constexpr double kCreaseChordShare = 0.5;

/// The quads without a boundary side (splitBits' bits 0 and 1, which must hold the boundary edges)
/// and not flagged yet (kHiddenQuadBit) one of whose corners lies behind the chord of its two
/// neighbours by more than kCreaseChordShare x B / S, B the sheet's bias (rule().bias) and S =
/// `subdivisions`: along the x axis, the y axis or either diagonal, the chord taken as the
/// projection interpolates (the depth for a directional light, its inverse for a spot light). A
/// pair with a far or ring neighbour is skipped. A corner more than 2 B behind a chord is a
/// discontinuity left to the boundary edges where they have it (a step on either side of the corner
/// along that direction is a boundary edge, or, along a diagonal, a side of the quad it crosses is
/// one); where they do not (a step next to steep neighbours, which the discontinuity rule keeps
/// continuous: ground lit at a grazing angle) it is a crease too. Each is marked with
/// kHiddenQuadBit in splitBits (at its lower-left texel: the sub-grid takes it as it takes a hidden
/// quad) and returned in quad order. None when B = 0 (back and midpoint capture by default). The
/// samples are read as the boundary-edge rule reads them (SheetDepthRule::fromStored: each with the
/// bias, which the chord cancels, and without the blur's averaging).
std::vector<std::uint32_t> findCreaseQuads(const SheetDepths& sheet, int subdivisions, std::uint8_t* splitBits);

}  // namespace shadowvol::volume
