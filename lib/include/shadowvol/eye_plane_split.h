// Huge triangles across a perspective view's eye plane: bisected until they are short enough for a
// GPU to clip precisely.
//
// A rasteriser clips a triangle that crosses the eye's plane (w = 0, or the near plane) in single
// precision, so the clipped corners err by about 2^-24 of the triangle's size; measured on
// llvmpipe, a 2-triangle ground of side 2e6 with the eye 3 units above it (1e6 near planes across)
// put its depth off by a pixel along every shadow edge (99.79 % stencil vs count agreement), and
// the same ground in 8 x 8 cells (1e5 near planes across) agreed everywhere. This step bisects,
// before anything is rendered, every triangle that crosses the slab between a view's eye plane and
// its near plane and is longer than kEyePlaneEdgeRatio near planes (a 12-fold margin on that
// measurement), for the camera and a spot light. Longest-edge bisection, made conforming (an edge
// split for one triangle is split for its neighbours too), so closed meshes stay closed and no
// T-junction opens a crack; new vertices are edge midpoints (computed in double), so the surface
// is the same one. Triangles far from the eye planes are left alone, so the added count grows
// with the length of the crossing (in maxEdge units) rather than with the area; it is capped at
// kMaxEyePlaneTriangles per scene (a ground 2e7 across under an eye 3 units above needs about
// 150,000), and a scene that would need more is left partly split, with a warning.
#pragma once

#include <cstddef>
#include <span>

#include <glm/vec3.hpp>

#include "shadowvol/triangle_mesh.h"

namespace shadowvol {

struct Scene;

inline constexpr double kEyePlaneEdgeRatio = 16384.0;
inline constexpr std::size_t kMaxEyePlaneTriangles = 1'000'000;

/// A perspective view's eye plane: its eye and unit axis, its near plane's depth, and the longest
/// edge a triangle crossing the slab [0, near] of depth may keep.
struct EyePlane {
  glm::dvec3 eye{0.0}, axis{0.0, 0.0, -1.0};
  double nearPlane = 1.0;
  double maxEdge = 4096.0;
};

struct EyePlaneSplit {
  std::size_t added = 0;  ///< triangles added
  bool complete = true;   ///< false: stopped by the triangle budget with triangles left to split
};

/// Bisects the triangles of `mesh` as the header comment says, keeping their orientation, until
/// none is left or the mesh would exceed `maxTriangles` (each pass is applied whole or not at all,
/// so the mesh stays conforming).
EyePlaneSplit splitAcrossEyePlanes(TriangleMesh& mesh, std::span<const EyePlane> planes, std::size_t maxTriangles);

/// The scene's eye planes (the camera's, a spot light's, a point light's six faces') with maxEdge = kEyePlaneEdgeRatio x
/// near; applied to every object, adding at most kMaxEyePlaneTriangles and staying within
/// `maxTriangles` for the scene. Call after the near planes are fitted.
EyePlaneSplit splitSceneAcrossEyePlanes(Scene& scene, std::size_t maxTriangles);

}  // namespace shadowvol
