// Refinement's crossings from a walk over the scene's triangles (the GPU's silhouette walk,
// shaders/silhouette_walk.comp, whose header comment gives the walk's rules) instead of bisection
// rays: the queries it takes and how its raw answers become a Refinement (silhouette_refinement.h).
//
// A walk answers in light-view depth as the scene's triangles give it; here the sheet-depth rule
// (SheetDepthRule::ofSample, the blur offset with blur) makes those the wall's vertices, as for a
// bisection ray's sample. Per boundary edge:
//   crossed: s = the walk's parameter, clamped into [kWalkEdgeMargin, 1 - kWalkEdgeMargin] (a
//            crossing lies strictly inside its edge, so crossings of one quad never coincide); near
//            depth = the rule at the crossing (the near end's own sheet depth where the rule puts it
//            on the far plane, as bisection's fallback); far depth = the far plane (far edge), or
//            the rule on the far surface's depth there (surface edge; the far end's own sheet depth
//            where that walk failed or does not lie beyond the near vertex);
//   otherwise (the walk reached the far end on the same surface, a surface falsely split, or it
//            failed): a fallback, counted in Refinement::fallbacks: s = 0.5 with the near end's and
//            far end's own sheet depths, a wall in the middle of the edge across the jump.
// Centre depths: the rule on the depth the walk found there, the far plane where none reached it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/silhouette_refinement.h"

namespace shadowvol {

/// Smallest distance of a walk's crossing from its edge's ends, in texels.
inline constexpr double kWalkEdgeMargin = 1.0 / 256.0;

/// One query of the walk, as silhouette_walk.comp reads it (16 bytes, std430).
struct WalkQuery {
  static constexpr std::uint32_t kEdge = 0, kCentre = 1;
  std::uint32_t kind = kEdge;
  std::int32_t i = 0, j = 0;  ///< edge: texel P; centre: the quad (its corner A)
  std::uint32_t flags = 0;    ///< edge: bit 0 axis, bit 1 nearAtP, bit 2 surface
};

/// One answer, as silhouette_walk.comp writes it (16 bytes, std430).
struct WalkResult {
  static constexpr std::uint32_t kCrossed = 0, kReached = 1, kFailed = 2;
  float s = 0.5f;           ///< edge: the parameter from the near end where it stopped
  float nearDepth = 0.0f;   ///< light-view depth there (edge) or at the centre; DepthMap::kNoHit: none
  float farDepth = 0.0f;    ///< surface edge: the far surface's depth at the crossing; kNoHit: none
  std::uint32_t status = kFailed;
};
static_assert(sizeof(WalkQuery) == 16 && sizeof(WalkResult) == 16);

/// The queries for every edge of `edges` (in order), then every centre (texel coordinates of a
/// quad's centre, (qi + 0.5, qj + 0.5)).
std::vector<WalkQuery> walkQueries(const BoundaryEdges& edges, std::span<const glm::dvec2> centres);

/// The Refinement of the header comment from the answers to walkQueries(edges, centres), in the
/// same order. `blurredSheetDepths` as for refineBoundaryEdges (read with blur only).
Refinement refinementFromWalks(const DepthMap& map, const BoundaryEdges& edges, const SheetDepthRule& rule, bool blur,
                               std::span<const double> blurredSheetDepths, std::span<const WalkResult> answers,
                               std::size_t centres);

}  // namespace shadowvol
