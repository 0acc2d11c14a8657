// The explicit shadow volume of a point light, from its cube map (cube_map.h): one closed,
// outward, welded 2-manifold around the light (docs/volume.md, "Point lights").
//
// Sheet: one vertex per texel of the six faces, at the texel centre's ray and the sheet depth
// of the rule of one map (sheet_depth.h) without its border ring (the cube has no border: the
// faces' sheets are joined across the cube's edges and corners, shadowvol/cube_grid.h); with blur,
// each face blurs its own map (clamp-to-edge at its border: the blur does not reach across a
// cube edge). Triangulation, fixed or perfect, per cell as in one map (evaluated in light-view
// space, world axes with the light at the origin). Cells whose triangles have three far
// vertices are dropped, as in one map.
//
// Far cap: the far images of the kept triangles (each vertex pushed along its ray to the far
// surface, the cube of half side `far`: exactly its face plane for the cells inside a face; a
// chord across the cube's edge for the cells across it), facing away from the light. Far
// vertices are split where the closed mesh would touch itself, by one map's rule (a far vertex
// with a dropped triangle around it gets one vertex per run of kept triangles between gaps and
// cuts; one with none keeps its sheet vertex and gets a separate cap vertex). With flattenCap
// (the default) each face's part of the cap, which lies in that face's far plane, is replaced by
// the lossless CDT of far_cap.h over its boundary; the cells across the cube's edges keep their
// mirrored cap triangles.
//
// Silhouette refinement (refineSteps > 0, a depthOracle that answers for each face's map): the
// walls at the boundary edges stand on the light's rays through their crossings, found by
// bisection rays, inside each face and across the cube's edges and corners (the source file
// cube/cube_refinement.h says how). Its crossings' far vertices are the far vertices of the rule
// above; the cap takes the kept triangles that are not walls. Not for point lights: chord points,
// the sub-grid, a crossing source (the GPU walk) and the quad cap (InputErrors).
#pragma once

#include "shadowvol/cube_map.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol {

/// Builds the volume; stats as buildVolume's (quads counts the cube's cells, droppedQuads those
/// that lost every triangle, capTrianglesBefore the kept sheet triangles that are not walls (the
/// mirrored cap's triangles: all kept ones without refinement), capTrianglesAfter what
/// the cap has, splitVertices the extra copies of far vertices in the result). Throws InputError
/// for a NaN or negative depth (naming the face and texel), a non-finite bias or blur offset,
/// refinement without a depth oracle or with what it refuses (kCubeRefinementRule), or the quad
/// cap. With refinement, the refinement stats of buildVolume.
VolumeBuildResult buildCubeVolume(const CubeDepthMap& cube, const VolumeBuildOptions& options);

/// What a point light's refinement refuses (an OptionConflict's problem of source "volume options",
/// the CPU's and GPU's): a MarkedProblem text (error.h), its ${field} marks that source's fields.
inline constexpr const char* kCubeRefinementRule =
    "a point light's volume is refined by ${refine steps} bisection rays alone: not with ${refine chords}, "
    "${refine subdivisions} above 1 or a crossing source";

/// Why a point light's volume refuses the quad cap (the InputError's problem, the CPU's and GPU's).
inline constexpr const char* kCubeVolumeCapRule =
    "a point light's volume has the exact cap only (the quad cap closes one map's border ring, and the cube has "
    "none)";

/// The bias a cube build uses when options.bias is unset: defaultBias of one face.
double defaultCubeBias(const CubeDepthMap& cube);

}  // namespace shadowvol
