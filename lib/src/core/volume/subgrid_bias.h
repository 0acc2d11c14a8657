// The sub-grid's bias (docs/volume.md "Sub-grid", step 8): with a sheet bias B > 0 (front capture), how
// much of it each node that the sub-grid samples keeps.
//
// B is a texel footprint: the depth a surface tilted 45 degrees from the light changes across a
// texel, what the sheet's straight interpolation between texel centres needs to stay behind a
// curved or creased lit surface. It also hides every shadow that starts within B of the surface
// casting it (contact shadows, a crease's). The sub-grid's nodes lie S times closer together and
// measure how far the sheet bends: one more ray at the centre of each sub-cell finds the captured
// surface there, and the sub-cell's corners keep only as much bias as that sample lies behind the
// sheet through them, plus a floor. The texel centres keep B (every other stage, and the GPU
// volume, see them), as do the virtual nodes and the crossings' walls.
//
// Not a bound: a crease that crosses a sub-cell off its centre lies further behind the sheet than
// the centre sample does (up to twice as far along a straight V), so along the crease line itself
// the sheet can pass in front of the lit surface (a dome on the ground under an overhead spot light,
// 32^2, S = 4: 10 of 360 points on the crease line, none 0.1 texel off it). Measured with the centre's
// distance doubled instead (README "Sub-grid bias"): no such point, but most of the contact shadow
// lost again, more wrong pixels on 6 of 9 scenes with open meshes.
#pragma once

#include <array>

namespace shadowvol::volume {

/// The share of B / S that a sampled node keeps however flat its sub-cells are: covers the curvature
/// between the centre sample and the corners (a crease that crosses a sub-cell off its centre),
/// float precision and the camera's depth buffer. Measured (README "Sub-grid bias"): 1/4 left more
/// contact shadow out, 0 gave acne on every scene, 1/10 about the same as 1/8.
inline constexpr double kSubgridBiasFloor = 0.125;

/// The bias a sub-cell needs at its corners, from B down to kSubgridBiasFloor * B / S: how far the
/// captured surface at its centre lies behind the sheet there (its corners' sheet depths, the lower
/// of the two diagonals' midpoints, as the projection interpolates: the depth for a directional
/// light, its inverse for a spot light), plus the floor. `corners` and `centre` are sheet depths
/// with the bias B in them (SheetDepthRule::ofSample); B itself where a corner or the centre is far
/// (`farPlane`) or the centre lies more than 2 B behind (a surface beyond a jump, not this one).
double subCellBias(const std::array<double, 4>& corners, double centre, double bias, int subdivisions, bool perspective,
                   double farPlane);

}  // namespace shadowvol::volume
