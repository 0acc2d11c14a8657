// The sub-grid's bias (docs/volume.md "Sub-grid", step 8): with a sheet bias B > 0 (front or entry
// capture), how much of it each node that the sub-grid samples keeps.
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
// How far behind: the centre sample alone underestimates a fold that crosses the sub-cell off its
// centre. Along a straight V fold between two planes the sheet through the corners lies furthest
// from the surface on the fold line: Ds h f (1 - f) for a fold at fraction f of the sub-cell's side
// h and a slope change Ds, against Ds h min(f, 1 - f) / 2 at the centre, so at most twice the
// centre's distance, and at most Ds h / 4. The lattice gives Ds h on each line along a side of the
// sub-cell: the difference of the steps just before and just after it (foldBound in
// subgrid_cells.cpp). A sub-cell takes the smaller bound, never less than the centre's own
// distance: where the neighbours are planes, as near a fold, the estimate holds; where the lattice
// ends, twice the centre's distance. Measured (README "Sub-grid bias"): with the centre's distance
// alone an open part lit nearly edge-on showed acne along a fold (17 more false pixels at 256^2);
// with twice it everywhere most of the contact shadow gained was lost again.
#pragma once

#include <array>
#include <functional>

namespace shadowvol::volume {

/// The share of B / S that a sampled node keeps however flat its sub-cells are: covers what the
/// bounds above do not (curved rather than folded surfaces between the samples, folds the lattice's
/// neighbours misjudge), float precision and the camera's depth buffer. Measured (README "Sub-grid
/// bias", with the centre's distance alone): 1/4 left more contact shadow out, 0 gave acne on every
/// scene, 1/10 about the same as 1/8.
inline constexpr double kSubgridBiasFloor = 0.125;

/// The bias a sub-cell needs at its corners, from B down to kSubgridBiasFloor * B / S: how far the
/// captured surface can lie behind the sheet through its corners (as the projection interpolates:
/// the depth for a directional light, its inverse for a spot light; the nearer of the two
/// diagonals' midpoints), plus the floor. That distance: 0 when the `centre` sample lies on or in
/// front of the sheet, else min(2 x its distance, max(its distance, `foldBound()`)), foldBound the
/// lattice's bound on a fold inside the sub-cell (+inf when unknown; see above). `corners` and
/// `centre` are sheet depths with the bias B in them (SheetDepthRule::ofSample); B itself where a
/// corner or the centre is far (`farPlane`) or the centre lies more than 2 B behind (a surface
/// beyond a jump, not this one). `foldBound` is called only where its value can change the result.
double subCellBias(const std::array<double, 4>& corners, double centre, const std::function<double()>& foldBound,
                   double bias, int subdivisions, bool perspective, double farPlane);

}  // namespace shadowvol::volume
